// The form-factor contract (tests/core/formfactor_contract.h) over the method this layer registers: the
// exact reference, held to the promises every core method is held to.
#include "core/formfactor_contract.h"
#include "exact/exact_reference.h"

namespace rt::test {
namespace {

// The CLI adds "exact" to the registry when it is built in (src/plugins); so does this binary.
[[maybe_unused]] const bool kExactRegistered = [] {
  exact::registerExactMethod();
  return true;
}();

INSTANTIATE_TEST_SUITE_P(Exact, FormFactorContract, ::testing::Values(std::string("exact")),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return testNameOf(info.param);
                         });

}  // namespace
}  // namespace rt::test
