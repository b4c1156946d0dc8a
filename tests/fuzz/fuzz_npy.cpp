// libFuzzer target: the NumPy .npy reader. A matrix or an InputError; never a read past the input or an
// allocation beyond what the input's bytes can fill.
#include <cstddef>
#include <cstdint>

#include "core/io/matrix_import.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  rt::fuzz::limitMemory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  rt::fuzz::expectValidOrInputError([&] {
    const Eigen::MatrixXd m = rt::parseNpyMatrix(bytes, "fuzz.npy");
    if (static_cast<double>(m.size()) * 8 > static_cast<double>(size))
      rt::fuzz::broken("more doubles than bytes");
  });
  return 0;
}
