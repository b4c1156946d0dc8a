// libFuzzer target: the JSON scene loader. A loaded scene must pass validateScene again and mesh without
// breaking the mesh's checks.
#include <cstddef>
#include <cstdint>

#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  rt::fuzz::limitMemory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rt::fuzz::expectValidOrInputError([&] {
    const rt::Scene scene = rt::parseSceneJson(text, "fuzz.json");
    try {
      rt::validateScene(scene);
    } catch (const rt::InputError& e) {
      rt::fuzz::broken(std::string("a loaded scene fails validation: ") + e.what());
    }
    rt::buildMesh(scene);
  });
  return 0;
}
