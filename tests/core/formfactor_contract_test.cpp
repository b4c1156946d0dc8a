// The contract (formfactor_contract.h) over every method the core registers.
#include "formfactor_contract.h"

namespace rt::test {
namespace {

INSTANTIATE_TEST_SUITE_P(Registered, FormFactorContract, ::testing::ValuesIn(formFactorMethodNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return testNameOf(info.param);
                         });

}  // namespace
}  // namespace rt::test
