// libFuzzer target: the Matrix Market reader. A matrix of finite values or an InputError naming the line;
// a declared size the memory budget cannot hold is refused before allocating.
#include <cstddef>
#include <cstdint>

#include "core/io/matrix_import.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  rt::fuzz::limitMemory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rt::fuzz::expectValidOrInputError([&] {
    const Eigen::MatrixXd m = rt::parseMatrixMarket(text, "fuzz.mtx");
    if (!m.allFinite()) rt::fuzz::broken("a non-finite entry was accepted");
  });
  return 0;
}
