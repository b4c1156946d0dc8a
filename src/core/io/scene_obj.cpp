// Wavefront OBJ/MTL scenes: one face = one patch, groups/objects -> surfaces, Kd = reflectance, Ke = emission
// (W/m^2). tinyobjloader reads the geometry and the materials. A line scan of our own runs first:
// tinyobjloader reports few problems with line numbers (it reads a malformed number as 0 and an out-of-range
// index without saying where), and every message of ours must say file:line.
#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include "core/io/scene_assembly.h"
#include "core/io/scene_loader.h"

namespace rt {
namespace {

using io_detail::formatNumber;

std::vector<std::string> splitWords(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// The rest of a line after its keyword: "g left wall" -> "left wall".
std::string afterFirstWord(const std::string& line) {
  const std::string text = trimmed(line);
  const std::size_t gap = text.find_first_of(" \t");
  return gap == std::string::npos ? "" : trimmed(text.substr(gap));
}

// A number that is all of `word`; nullopt for "1.5x", "", "abc".
std::optional<double> parseNumber(const std::string& word) {
  if (word.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size()) return std::nullopt;
  return value;
}

std::string directoryOf(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

// Lines of a text, without their line terminators ("\r\n" or "\n").
std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

// What our own scan of the .obj finds for each face, in file order (the order tinyobjloader keeps too).
struct ObjFace {
  int line = 0;
  std::size_t vertexCount = 0;
  std::string group;
  std::string material;  // empty when no usemtl came before the face
};

struct ObjScan {
  // Vertex positions in double precision, in file order (= tinyobjloader's order). The Debian tinyobjloader
  // stores floats, which would move a coordinate like 548.8 by 1e-5.
  std::vector<Vec3> vertices;
  std::vector<ObjFace> faces;
  std::map<std::string, int> usemtlLine;  // first usemtl line of each material name
  std::vector<std::pair<std::string, int>> mtllibs;
  std::string name;
  std::string unit = "m";
  std::optional<Camera> camera;
};

// "# camera: position x y z target x y z up x y z fov_y_degrees f": OBJ has no camera, a comment keeps it
// with the file.
Camera parseCameraComment(const std::string& text, const SourceLocation& where) {
  const std::vector<std::string> words = splitWords(text);
  Camera camera;
  auto numbers = [&](std::size_t at, int count) {
    std::vector<double> out;
    for (int k = 0; k < count; ++k) {
      const std::optional<double> x = at + k < words.size() ? parseNumber(words[at + k]) : std::nullopt;
      if (!x || !std::isfinite(*x))
        throw InputError(where,
                         "camera comment: '" + words[at - 1] + "' needs " + std::to_string(count) +
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
      throw InputError(where, "camera comment: unknown word '" + key + "'");
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
    throw InputError(where, "camera comment: field of view outside (0, 180) degrees");
  if ((camera.target - camera.position).norm() == 0 ||
      camera.up.cross(camera.target - camera.position).norm() == 0)
    throw InputError(where,
                     "camera comment: target equals position, or up is parallel to the viewing direction");
  return camera;
}

ObjScan scanObj(const std::string& text, const std::string& path) {
  ObjScan scan;
  std::string group = "default", material;
  long vertexCount = 0;
  const std::vector<std::string> lines = linesOf(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const SourceLocation where{path, static_cast<int>(i + 1), ""};
    const std::vector<std::string> words = splitWords(lines[i]);
    if (words.empty()) continue;
    const std::string& key = words[0];
    if (key[0] == '#') {
      // "# unit: mm", "# name: ...", "# camera: ...": what OBJ cannot say otherwise.
      const std::string body = lines[i].substr(lines[i].find('#') + 1);
      const std::size_t colon = body.find(':');
      if (colon == std::string::npos) continue;
      const std::string word = trimmed(body.substr(0, colon));
      const std::string value = trimmed(body.substr(colon + 1));
      if (word == "unit" && !value.empty()) scan.unit = value;
      if (word == "name") scan.name = value;
      if (word == "camera") scan.camera = parseCameraComment(value, where);
    } else if (key == "v") {
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
      scan.vertices.push_back(position);
      ++vertexCount;
    } else if (key == "f") {
      if (words.size() < 4)
        throw InputError(where,
                         "face has " + std::to_string(words.size() - 1) + " vertices; at least 3 are needed");
      for (std::size_t k = 1; k < words.size(); ++k) {
        const std::string index = words[k].substr(0, words[k].find('/'));
        char* end = nullptr;
        const long n = std::strtol(index.c_str(), &end, 10);
        if (index.empty() || end != index.c_str() + index.size())
          throw InputError(where, "malformed face: '" + words[k] + "' is not a vertex index");
        // Positive indices count from the file's first vertex, negative ones back from the latest.
        const long resolved = n > 0 ? n : vertexCount + n + 1;
        if (n == 0 || resolved < 1 || (n < 0 && resolved > vertexCount))
          throw InputError(where, "face vertex index " + index +
                                      " is out of range (OBJ indices start at 1; " +
                                      std::to_string(vertexCount) + " vertices so far)");
      }
      scan.faces.push_back({where.line, words.size() - 1, group, material});
    } else if (key == "g" || key == "o") {
      const std::string name = afterFirstWord(lines[i]);
      group = name.empty() ? "default" : name;
    } else if (key == "usemtl") {
      material = afterFirstWord(lines[i]);
      scan.usemtlLine.emplace(material, where.line);
    } else if (key == "mtllib") {
      for (std::size_t k = 1; k < words.size(); ++k) scan.mtllibs.push_back({words[k], where.line});
    }
  }
  // Positive indices may refer to vertices written later in the file; check them once all are known.
  for (const ObjFace& face : scan.faces) {
    const std::vector<std::string> words = splitWords(lines[face.line - 1]);
    for (std::size_t k = 1; k < words.size(); ++k) {
      const long n = std::strtol(words[k].c_str(), nullptr, 10);
      if (n > vertexCount)
        throw InputError({path, face.line, ""}, "face vertex index " + std::to_string(n) +
                                                    " is out of range (the file has " +
                                                    std::to_string(vertexCount) + " vertices)");
    }
  }
  return scan;
}

// Where each material's statements are in its .mtl, and Kd/Ke checked the way the MTL format defines them.
struct MtlEntry {
  SourceLocation newmtl;
  std::optional<Rgb> kd, ke;
  SourceLocation kdAt, keAt;
};

std::map<std::string, MtlEntry> scanMtl(const std::string& path) {
  std::map<std::string, MtlEntry> entries;
  std::string text;
  try {
    text = io_detail::readTextFile(path);
  } catch (const InputError&) {
    return entries;  // reported later, when a face needs one of its materials
  }
  MtlEntry* current = nullptr;
  const std::vector<std::string> lines = linesOf(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const SourceLocation where{path, static_cast<int>(i + 1), ""};
    const std::vector<std::string> words = splitWords(lines[i]);
    if (words.empty() || words[0][0] == '#') continue;
    if (words[0] == "newmtl") {
      current = &entries[afterFirstWord(lines[i])];
      current->newmtl = where;
    } else if ((words[0] == "Kd" || words[0] == "Ke") && current) {
      // "Kd r" means grey, "Kd r g b" a colour; spectral and xyz forms are not supported.
      if (words.size() != 2 && words.size() != 4)
        throw InputError(where, words[0] + " needs 1 or 3 numbers ('" + words[0] + " r g b'), found " +
                                    std::to_string(words.size() - 1) + " values");
      Rgb value;
      for (std::size_t k = 1; k < words.size(); ++k) {
        const std::optional<double> x = parseNumber(words[k]);
        if (!x) throw InputError(where, words[0] + ": '" + words[k] + "' is not a number");
        value[static_cast<int>(k - 1)] = *x;
      }
      if (words.size() == 2) value = Rgb::Constant(value[0]);
      (words[0] == "Kd" ? current->kd : current->ke) = value;
      (words[0] == "Kd" ? current->kdAt : current->keAt) = where;
    }
  }
  return entries;
}

}  // namespace

Scene loadSceneObj(const std::string& path) {
  const std::string text = io_detail::readTextFile(path);
  const ObjScan scan = scanObj(text, path);
  Scene scene;
  scene.sourceFile = path;
  scene.unit = scan.unit;
  scene.camera = scan.camera;
  if (!scan.name.empty()) {
    scene.name = scan.name;
  } else {
    const std::size_t slash = path.find_last_of("/\\");
    scene.name = slash == std::string::npos ? path : path.substr(slash + 1);
  }
  if (scan.faces.empty()) throw InputError({path}, "the file has no faces ('f' lines)");

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // one face = one patch; our own checks split non-planar faces
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config))
    throw InputError({path}, "cannot read the OBJ file: " + reader.Error());

  // Materials: tinyobjloader's, located and format-checked by our scan of the .mtl files.
  std::map<std::string, MtlEntry> located;
  std::string mtlNames;
  for (const auto& [file, line] : scan.mtllibs) {
    const std::string mtlPath = directoryOf(path) + file;
    mtlNames += (mtlNames.empty() ? "" : ", ") + mtlPath;
    if (!std::ifstream(mtlPath))
      throw InputError({path, line, ""}, "cannot open the material library " + mtlPath);
    located.merge(scanMtl(mtlPath));
  }
  std::map<std::string, int> materialIndex;
  for (const tinyobj::material_t& m : reader.GetMaterials()) {
    const auto at = located.find(m.name);
    const MtlEntry entry = at == located.end() ? MtlEntry{} : at->second;
    Material material;
    material.name = m.name;
    if (!entry.kd)
      throw InputError(entry.newmtl, "material '" + m.name + "' has no Kd (diffuse reflectance)");
    // tinyobjloader's Kd/Ke in float precision, replaced by the scan's doubles; the scan also reads "Kd 0.5"
    // as the MTL format means it (grey), where tinyobjloader gives (0.5, 0, 0).
    material.reflectance = Rgb(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
    material.emission = Rgb(m.emission[0], m.emission[1], m.emission[2]);
    material.reflectance = *entry.kd;
    if (entry.ke) material.emission = *entry.ke;
    const bool badReflectance = !material.reflectance.allFinite() || (material.reflectance < 0).any() ||
                                (material.reflectance >= 1).any();
    io_detail::checkMaterial(material, badReflectance ? entry.kdAt : entry.ke ? entry.keAt : entry.newmtl);
    materialIndex[m.name] = static_cast<int>(scene.materials.size());
    scene.materials.push_back(material);
  }

  // Faces, matched one to one with our scan (same order, same vertex counts).
  const std::size_t vertexCount = scan.vertices.size();
  if (reader.GetAttrib().vertices.size() != 3 * vertexCount)
    throw InputError({path}, "the vertices read do not match the file's 'v' lines");
  std::size_t faceNumber = 0;
  std::map<std::pair<std::string, std::string>, int> surfaceIndex;
  std::map<std::string, int> materialsPerGroup;
  for (const ObjFace& face : scan.faces)
    if (surfaceIndex.emplace(std::make_pair(face.group, face.material), 0).second)
      ++materialsPerGroup[face.group];
  surfaceIndex.clear();
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t offset = 0;
    for (const auto count : shape.mesh.num_face_vertices) {
      if (faceNumber >= scan.faces.size() || scan.faces[faceNumber].vertexCount != count)
        throw InputError({path},
                         "the faces read do not match the file's 'f' lines (line continuations with '\\' "
                         "are not supported)");
      const ObjFace& face = scan.faces[faceNumber++];
      const SourceLocation where{path, face.line, ""};
      if (face.material.empty())
        throw InputError(where, "face has no material: put 'usemtl <name>' before it (materials come from " +
                                    (mtlNames.empty() ? std::string("an mtllib file") : mtlNames) + ")");
      const auto material = materialIndex.find(face.material);
      if (material == materialIndex.end()) {
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
      for (std::size_t k = 0; k < count; ++k) {
        const int v =
            offset + k < shape.mesh.indices.size() ? shape.mesh.indices[offset + k].vertex_index : -1;
        if (v < 0 || static_cast<std::size_t>(v) >= vertexCount)
          throw InputError(where, "face vertex index out of range");
        polygon.push_back(scan.vertices[v]);
      }
      offset += count;
      io_detail::addPolygon(scene, polygon, surface->second, where);
    }
  }
  if (faceNumber != scan.faces.size())
    throw InputError({path},
                     "the faces read do not match the file's 'f' lines (line continuations with '\\' are "
                     "not supported)");
  validateScene(scene);
  return scene;
}

}  // namespace rt
