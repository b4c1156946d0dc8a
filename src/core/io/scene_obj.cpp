// Wavefront OBJ/MTL scenes as modelling tools and model archives write them: one face = one patch,
// groups/objects -> surfaces, Kd = reflectance, Ke = emission (W/m^2). The reader is our own, so that every
// message says file:line and a malformed number is an error instead of a silent 0. Inline comments,
// continuation lines, texture coordinates, normals and smoothing groups are accepted; faces before any
// usemtl get a default material, with a warning.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "core/camera_path.h"
#include "core/io/mtl_reader.h"
#include "core/io/scene_assembly.h"
#include "core/io/scene_loader.h"

namespace rt {
namespace {

using namespace io_detail;

// Given to faces that come before any usemtl (exporters write such files for objects without a material).
const char* const kDefaultMaterial = "default";
constexpr double kDefaultReflectance = 0.5;

std::string directoryOf(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

struct ObjFace {
  int line = 0;
  std::vector<long> indices;  // as written: positive from the first vertex, negative back from the latest
  long verticesSoFar = 0;     // for resolving negative indices
  std::string group;
  std::string material;  // empty when no usemtl came before the face
};

struct ObjScan {
  std::vector<Vec3> vertices;  // double precision, in file order
  std::vector<ObjFace> faces;
  std::map<std::string, int> usemtlLine;  // first usemtl line of each material name
  std::vector<std::pair<std::string, int>> mtllibs;
  std::vector<std::string> warnings;
  std::string name;
  std::string unit = "m";
  std::optional<Camera> camera;
  std::vector<NamedCamera> cameras;
};

// Statements that say nothing a radiosity scene can use; skipped without a word.
const std::set<std::string>& skippedStatements() {
  static const std::set<std::string> keys{"vt", "vn", "vp", "s", "lod", "shadow_obj", "trace_obj", "mg"};
  return keys;
}

// "# unit: mm", "# name: ...", "# camera: ...": what OBJ cannot say otherwise, kept in whole-line comments.
void readMetaComment(const std::string& line, const SourceLocation& where, ObjScan& scan) {
  const std::string body = line.substr(line.find('#') + 1);
  const std::size_t colon = body.find(':');
  if (colon == std::string::npos) return;
  const std::string word = trimmed(body.substr(0, colon));
  const std::string value = trimmed(body.substr(colon + 1));
  if (word == "unit" && !value.empty()) scan.unit = value;
  if (word == "name") scan.name = value;
  if (word == "camera") scan.camera = parseCameraText(value, where);
  // "# camera NAME: ...": a named view, for --camera NAME and the lessons' camera keys.
  if (word.rfind("camera ", 0) == 0) {
    const std::string name = trimmed(word.substr(7));
    if (!isCameraName(name))
      throw InputError(where, "camera name '" + name + "' uses letters, digits, '-', '_' and '.' only");
    for (const NamedCamera& c : scan.cameras)
      if (c.name == name) throw InputError(where, "camera '" + name + "' is named twice");
    scan.cameras.push_back({name, parseCameraText(value, where)});
  }
}

Vec3 parseVertex(const std::vector<std::string>& words, const SourceLocation& where) {
  // "v x y z", optionally followed by w or by a vertex colour (r g b): only x y z matter here.
  if (words.size() < 4) throw InputError(where, "malformed vertex: expected 'v x y z'");
  Vec3 position;
  for (int k = 1; k <= 3; ++k) {
    const std::optional<double> x = parseNumber(words[k]);
    if (!x) throw InputError(where, "malformed vertex: '" + words[k] + "' is not a number");
    if (!std::isfinite(*x))
      throw InputError(where,
                       "vertex coordinate '" + words[k] + "' is not a finite number (NaN or infinity)");
    position[k - 1] = *x;
  }
  return position;
}

ObjFace parseFace(const std::vector<std::string>& words, const SourceLocation& where, long verticesSoFar) {
  if (words.size() < 4)
    throw InputError(where,
                     "face has " + std::to_string(words.size() - 1) + " vertices; at least 3 are needed");
  if (words.size() - 1 > kMaxPolygonVertices)
    throw InputError(where, "face has " + std::to_string(words.size() - 1) + " vertices; at most " +
                                std::to_string(kMaxPolygonVertices) + " are accepted");
  ObjFace face;
  face.line = where.line;
  face.verticesSoFar = verticesSoFar;
  for (std::size_t k = 1; k < words.size(); ++k) {
    // "v", "v/vt", "v//vn", "v/vt/vn": only the vertex index is used.
    const std::string index = words[k].substr(0, words[k].find('/'));
    char* end = nullptr;
    errno = 0;
    const long n = std::strtol(index.c_str(), &end, 10);
    if (index.empty() || end != index.c_str() + index.size() || errno == ERANGE)
      throw InputError(where, "malformed face: '" + words[k] + "' is not a vertex index");
    const long resolved = n > 0 ? n : verticesSoFar + n + 1;
    if (n == 0 || resolved < 1 || (n < 0 && resolved > verticesSoFar))
      throw InputError(where, "face vertex index " + index + " is out of range (OBJ indices start at 1; " +
                                  std::to_string(verticesSoFar) + " vertices so far)");
    face.indices.push_back(n);
  }
  return face;
}

ObjScan scanObj(const std::string& text, const std::string& path) {
  ObjScan scan;
  std::string group = "default", material;
  std::set<std::string> unknownReported;
  for (const auto& [number, raw] : logicalLines(text)) {
    const SourceLocation where{path, number, ""};
    const std::string line = withoutComment(raw);
    if (line.empty()) {
      if (raw.find('#') != std::string::npos) readMetaComment(raw, where, scan);
      continue;
    }
    const std::vector<std::string> words = splitWords(line);
    const std::string& key = words[0];
    if (key == "v") {
      scan.vertices.push_back(parseVertex(words, where));
    } else if (key == "f") {
      ObjFace face = parseFace(words, where, static_cast<long>(scan.vertices.size()));
      face.group = group;
      face.material = material;
      scan.faces.push_back(std::move(face));
    } else if (key == "g" || key == "o") {
      const std::string name = afterFirstWord(line);
      group = name.empty() ? "default" : name;
    } else if (key == "usemtl") {
      material = afterFirstWord(line);
      if (material.empty()) throw InputError(where, "usemtl needs a material name");
      scan.usemtlLine.emplace(material, where.line);
    } else if (key == "mtllib") {
      for (std::size_t k = 1; k < words.size(); ++k) scan.mtllibs.push_back({words[k], where.line});
    } else if (!skippedStatements().count(key) && unknownReported.insert(key).second) {
      // Lines, points and free-form curves/surfaces have no area to exchange light.
      scan.warnings.push_back(where.describe() + ": warning: '" + key +
                              "' statements are not supported and are ignored");
    }
  }
  return scan;
}

// The materials of every mtllib, in order, each checked where its library defines it.
std::vector<MtlMaterial> readLibraries(const ObjScan& scan, const std::string& path, const MtlSource& mtlText,
                                       std::vector<std::string>& warnings, std::string& names) {
  std::vector<MtlMaterial> materials;
  for (const auto& [file, line] : scan.mtllibs) {
    const std::string mtlPath = directoryOf(path) + file;
    names += (names.empty() ? "" : ", ") + mtlPath;
    const std::optional<std::string> text = mtlText(mtlPath);
    if (!text) throw InputError({path, line, ""}, "cannot open the material library " + mtlPath);
    MtlLibrary library = parseMtl(*text, mtlPath);
    warnings.insert(warnings.end(), library.warnings.begin(), library.warnings.end());
    for (MtlMaterial& m : library.materials) materials.push_back(std::move(m));
  }
  return materials;
}

}  // namespace

// "# camera: position x y z target x y z up x y z fov_y_degrees f": OBJ has no camera, a comment keeps it
// with the file.
Camera parseCameraText(const std::string& text, const SourceLocation& where) {
  const std::vector<std::string> words = splitWords(text);
  Camera camera;
  auto numbers = [&](std::size_t at, int count) {
    std::vector<double> out;
    for (int k = 0; k < count; ++k) {
      const std::optional<double> x = at + k < words.size() ? parseNumber(words[at + k]) : std::nullopt;
      if (!x || !std::isfinite(*x))
        throw InputError(where,
                         "camera: '" + words[at - 1] + "' needs " + std::to_string(count) +
                             " finite numbers (expected '# camera: position x y z target x y z up x y z "
                             "fov_y_degrees f')");
      out.push_back(*x);
    }
    return out;
  };
  for (std::size_t i = 0; i < words.size();) {
    const std::string& key = words[i++];
    const int count = key == "fov_y_degrees" ? 1 : 3;
    if (key != "position" && key != "target" && key != "up" && key != "fov_y_degrees")
      throw InputError(where, "camera: unknown word '" + key + "'");
    const std::vector<double> v = numbers(i, count);
    i += count;
    if (key == "fov_y_degrees") {
      camera.fovYDegrees = v[0];
    } else {
      (key == "position" ? camera.position
       : key == "target" ? camera.target
                         : camera.up) = Vec3(v[0], v[1], v[2]);
    }
  }
  if (!(camera.fovYDegrees > 0 && camera.fovYDegrees < 180))
    throw InputError(where, "camera: field of view outside (0, 180) degrees");
  if ((camera.target - camera.position).norm() == 0 ||
      camera.up.cross(camera.target - camera.position).norm() == 0)
    throw InputError(where, "camera: target equals position, or up is parallel to the viewing direction");
  return camera;
}

Scene parseSceneObj(const std::string& text, const std::string& path, const MtlSource& mtlText) {
  ObjScan scan = scanObj(text, path);
  Scene scene;
  scene.sourceFile = path;
  scene.unit = scan.unit;
  scene.camera = scan.camera;
  scene.cameras = scan.cameras;
  if (!scan.name.empty()) {
    scene.name = scan.name;
  } else {
    const std::size_t slash = path.find_last_of("/\\");
    scene.name = slash == std::string::npos ? path : path.substr(slash + 1);
  }
  if (scan.faces.empty()) throw InputError({path}, "the file has no faces ('f' lines)");
  std::string mtlNames;
  const std::vector<MtlMaterial> library = readLibraries(scan, path, mtlText, scan.warnings, mtlNames);
  scene.warnings = scan.warnings;

  // Materials with a Kd join the scene in library order; using one without is an error at its newmtl.
  std::map<std::string, int> materialIndex;
  std::map<std::string, const MtlMaterial*> withoutKd;
  for (const MtlMaterial& m : library) {
    if (!m.hasKd) {
      withoutKd[m.material.name] = &m;
      continue;
    }
    withoutKd.erase(m.material.name);
    materialIndex[m.material.name] = static_cast<int>(scene.materials.size());
    scene.materials.push_back(m.material);
  }
  const long vertexCount = static_cast<long>(scan.vertices.size());
  int facesWithoutMaterial = 0;
  for (ObjFace& face : scan.faces) {
    if (!face.material.empty()) continue;
    if (facesWithoutMaterial++ == 0 && !materialIndex.count(kDefaultMaterial)) {
      materialIndex[kDefaultMaterial] = static_cast<int>(scene.materials.size());
      scene.materials.push_back({kDefaultMaterial, Rgb::Constant(kDefaultReflectance), Rgb::Zero()});
    }
    if (facesWithoutMaterial == 1)
      scene.warnings.push_back(SourceLocation{path, face.line, ""}.describe() +
                               ": warning: face before any 'usemtl': it gets the material '" +
                               kDefaultMaterial + "' (reflectance " + formatNumber(kDefaultReflectance) +
                               " grey, no emission)");
    face.material = kDefaultMaterial;
  }
  if (facesWithoutMaterial > 1)
    scene.warnings.back() += ", as do the " + std::to_string(facesWithoutMaterial - 1) + " other such faces";

  std::map<std::pair<std::string, std::string>, int> surfaceIndex;
  std::map<std::string, int> materialsPerGroup;
  for (const ObjFace& face : scan.faces)
    if (surfaceIndex.emplace(std::make_pair(face.group, face.material), 0).second)
      ++materialsPerGroup[face.group];
  surfaceIndex.clear();
  for (const ObjFace& face : scan.faces) {
    const SourceLocation where{path, face.line, ""};
    const auto material = materialIndex.find(face.material);
    if (material == materialIndex.end()) {
      if (const auto missing = withoutKd.find(face.material); missing != withoutKd.end())
        throw InputError(missing->second->newmtl,
                         "material '" + face.material + "' has no Kd (diffuse reflectance)");
      std::string known;
      for (const Material& m : scene.materials) known += (known.empty() ? "" : ", ") + m.name;
      throw InputError({path, scan.usemtlLine.at(face.material), ""},
                       "unknown material '" + face.material + "' (" +
                           (mtlNames.empty() ? "no mtllib line" : "known in " + mtlNames + ": " + known) +
                           ")");
    }
    const auto key = std::make_pair(face.group, face.material);
    auto surface = surfaceIndex.find(key);
    if (surface == surfaceIndex.end()) {
      // A group with several materials becomes one surface per material.
      const std::string name =
          materialsPerGroup[face.group] > 1 ? face.group + "/" + face.material : face.group;
      surface = surfaceIndex.emplace(key, static_cast<int>(scene.surfaces.size())).first;
      scene.surfaces.push_back({name, material->second});
    }
    Polygon polygon;
    for (const long n : face.indices) {
      // Positive indices may name vertices written later in the file: checked now that all are known.
      const long resolved = n > 0 ? n : face.verticesSoFar + n + 1;
      if (resolved > vertexCount)
        throw InputError(where, "face vertex index " + std::to_string(n) + " is out of range (the file has " +
                                    std::to_string(vertexCount) + " vertices)");
      polygon.push_back(scan.vertices[static_cast<std::size_t>(resolved - 1)]);
    }
    addPolygon(scene, polygon, surface->second, where);
  }
  validateScene(scene);
  addLightWarnings(scene);
  return scene;
}

Scene loadSceneObj(const std::string& path) {
  const std::string text = readTextFile(path);
  return parseSceneObj(text, path, [](const std::string& mtlPath) -> std::optional<std::string> {
    try {
      return readTextFile(mtlPath);
    } catch (const InputError&) {
      return std::nullopt;
    }
  });
}

}  // namespace rt
