// libFuzzer target: the OBJ loader with its MTL library. The input is the OBJ text, optionally followed by a
// line "#--mtl--" and the text of every material library it names. A loaded scene must pass validateScene
// (finite vertices, planar convex patches, 0 <= rho < 1) and mesh without breaking the mesh's checks.
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
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find("#--mtl--\n");
  const std::string obj = input.substr(0, split);
  const std::string mtl = split == std::string::npos ? "" : input.substr(split + 9);
  rt::fuzz::expectValidOrInputError([&] {
    const rt::Scene scene =
        rt::parseSceneObj(obj, "fuzz.obj", [&](const std::string&) -> std::optional<std::string> {
          if (split == std::string::npos) return std::nullopt;
          return mtl;
        });
    try {
      rt::validateScene(scene);
    } catch (const rt::InputError& e) {
      rt::fuzz::broken(std::string("a loaded scene fails validation: ") + e.what());
    }
    rt::buildMesh(scene);  // one element per patch: convex n-gons stay whole
  });
  return 0;
}
