// libFuzzer target: the MTL reader alone. Every material it returns has a reflectance in [0,1) and a finite
// emission >= 0, checked where its library says so.
#include <cstddef>
#include <cstdint>

#include "core/io/mtl_reader.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rt::fuzz::expectValidOrInputError([&] {
    for (const auto& m : rt::io_detail::parseMtl(text, "fuzz.mtl").materials) {
      const rt::Material& material = m.material;
      if (!material.reflectance.allFinite() || (material.reflectance < 0).any() ||
          (material.reflectance >= 1).any())
        rt::fuzz::broken("reflectance outside [0,1) accepted for '" + material.name + "'");
      if (!material.emission.allFinite() || (material.emission < 0).any())
        rt::fuzz::broken("bad emission accepted for '" + material.name + "'");
    }
  });
  return 0;
}
