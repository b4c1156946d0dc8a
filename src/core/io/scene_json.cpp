// The project's JSON scene format (docs/scene-format.md). Every message names the file, the line and the JSON
// path of the offending value.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>

#include "core/camera_path.h"
#include "core/io/json_line_map.h"
#include "core/io/scene_assembly.h"
#include "core/io/scene_loader.h"

namespace rt {
namespace {

using nlohmann::json;

// Keys that may appear anywhere to document a scene; they are ignored.
bool isCommentKey(const std::string& key) {
  return key == "description" || key == "notes" || key == "source" || (!key.empty() && key[0] == '_');
}

std::string typeName(const json& value) {
  if (value.is_number()) return "a number";
  if (value.is_string()) return "a string";
  if (value.is_array()) return "an array";
  if (value.is_object()) return "an object";
  if (value.is_boolean()) return "a boolean";
  return "null";
}

class SceneJsonReader {
 public:
  SceneJsonReader(const std::string& text, const std::string& fileName)
      : file_(fileName), root_(parse(text, fileName)), lines_(text) {}

  Scene read() {
    Scene scene;
    scene.sourceFile = file_;
    requireType(root_, "", json::value_t::object, "an object with \"materials\" and \"surfaces\"");
    if (!lines_.firstDuplicateKey().empty()) {
      const std::string& pointer = lines_.firstDuplicateKey();
      fail(pointer,
           "key \"" + pointer.substr(pointer.rfind('/') + 1) + "\" appears twice in the same object");
    }
    checkKeys(root_, "", {"version", "name", "unit", "camera", "cameras", "materials", "surfaces"});
    if (root_.contains("version")) {
      const json& v = root_["version"];
      if (!v.is_number_integer() || v.get<int>() != 1)
        fail("/version", "unsupported version " + v.dump() + " (this program reads version 1)");
    }
    scene.name = root_.contains("name") ? string(root_["name"], "/name") : stem(file_);
    if (root_.contains("unit")) {
      scene.unit = string(root_["unit"], "/unit");
      if (scene.unit.empty()) fail("/unit", "unit is empty (use e.g. \"m\" or \"mm\")");
    }
    if (root_.contains("camera")) scene.camera = camera(root_["camera"], "/camera");
    if (root_.contains("cameras")) readCameras(scene);
    readMaterials(scene);
    readSurfaces(scene);
    validateScene(scene);
    io_detail::addLightWarnings(scene);
    return scene;
  }

 private:
  static json parse(const std::string& text, const std::string& fileName) {
    try {
      return json::parse(text);
    } catch (const json::parse_error& e) {
      // e.byte is the 1-based offset of the character where parsing stopped.
      int line = 1, column = 1;
      for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
          ++line;
          column = 1;
        } else {
          ++column;
        }
      }
      std::string what = e.what();
      const std::size_t detail = what.find(": ", what.find("parse error"));
      what = detail == std::string::npos ? what : what.substr(detail + 2);
      throw InputError({fileName, line, ""},
                       "JSON syntax error at column " + std::to_string(column) + ": " + what);
    } catch (const json::exception& e) {
      // E.g. "number overflow parsing '1e999'": no position is given, so find the quoted text.
      std::string what = e.what();
      const std::size_t bracket = what.find("] ");
      if (bracket != std::string::npos) what = what.substr(bracket + 2);
      int line = 0;
      const std::size_t open = what.find('\''), close = what.rfind('\'');
      if (open != std::string::npos && close > open) {
        const std::size_t at = text.find(what.substr(open + 1, close - open - 1));
        if (at != std::string::npos)
          line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
      }
      throw InputError({fileName, line, ""}, "JSON: " + what);
    }
  }

  static std::string stem(const std::string& path) {
    const std::size_t slash = path.find_last_of("/\\");
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::size_t dot = name.rfind('.');
    return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
  }

  SourceLocation at(const std::string& pointer) const {
    return {file_, lines_.lineOf(pointer), pointer.empty() ? "/" : pointer};
  }
  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    throw InputError(at(pointer), message);
  }

  void requireType(const json& value, const std::string& pointer, json::value_t type,
                   const std::string& what) const {
    if (value.type() != type) fail(pointer, "expected " + what + ", found " + typeName(value));
  }

  void checkKeys(const json& object, const std::string& pointer,
                 std::initializer_list<const char*> allowed) const {
    for (const auto& [key, value] : object.items()) {
      if (isCommentKey(key)) continue;
      bool known = false;
      std::string list;
      for (const char* name : allowed) {
        known = known || key == name;
        list += (list.empty() ? "" : ", ") + std::string(name);
      }
      if (!known)
        fail(pointer + "/" + io_detail::escapeJsonPointerToken(key),
             "unknown key \"" + key + "\" (expected one of: " + list + ")");
    }
  }

  const json& member(const json& object, const std::string& pointer, const char* key) const {
    if (!object.contains(key)) fail(pointer, std::string("missing required key \"") + key + "\"");
    return object[key];
  }

  std::string string(const json& value, const std::string& pointer) const {
    requireType(value, pointer, json::value_t::string, "a string");
    return value.get<std::string>();
  }

  double number(const json& value, const std::string& pointer) const {
    if (!value.is_number()) fail(pointer, "expected a number, found " + typeName(value));
    const double x = value.get<double>();
    // JSON has no NaN, but a literal like 1e999 overflows to infinity.
    if (!std::isfinite(x)) fail(pointer, "number " + value.dump() + " is not finite");
    return x;
  }

  Vec3 vec3(const json& value, const std::string& pointer) const {
    if (!value.is_array() || value.size() != 3)
      fail(pointer, "expected [x, y, z] (an array of 3 numbers), found " +
                        (value.is_array() ? "an array of " + std::to_string(value.size()) : typeName(value)));
    return Vec3(number(value[0], pointer + "/0"), number(value[1], pointer + "/1"),
                number(value[2], pointer + "/2"));
  }

  // A colour: [r, g, b], or one number meaning grey.
  Rgb rgb(const json& value, const std::string& pointer) const {
    if (value.is_number()) return Rgb::Constant(number(value, pointer));
    if (!value.is_array() || value.size() != 3)
      fail(pointer, "expected [r, g, b] (an array of 3 numbers) or a single number, found " +
                        (value.is_array() ? "an array of " + std::to_string(value.size()) : typeName(value)));
    return Rgb(number(value[0], pointer + "/0"), number(value[1], pointer + "/1"),
               number(value[2], pointer + "/2"));
  }

  // "cameras": {"NAME": {camera}, ...}: views a command or a lesson step asks for by name.
  void readCameras(Scene& scene) const {
    const json& cameras = root_["cameras"];
    requireType(cameras, "/cameras", json::value_t::object, "an object of named cameras");
    for (const auto& [name, value] : cameras.items()) {
      if (!isCameraName(name))
        fail("/cameras/" + name,
             "camera name '" + name + "' uses letters, digits, '-', '_' and '.' only (no spaces)");
      scene.cameras.push_back({name, camera(value, "/cameras/" + name)});
    }
  }

  Camera camera(const json& value, const std::string& pointer) const {
    requireType(value, pointer, json::value_t::object, "an object");
    checkKeys(value, pointer, {"position", "target", "up", "fov_y_degrees"});
    Camera c;
    c.position = vec3(member(value, pointer, "position"), pointer + "/position");
    c.target = vec3(member(value, pointer, "target"), pointer + "/target");
    if (value.contains("up")) c.up = vec3(value["up"], pointer + "/up");
    if (value.contains("fov_y_degrees"))
      c.fovYDegrees = number(value["fov_y_degrees"], pointer + "/fov_y_degrees");
    const Vec3 view = c.target - c.position;
    if (view.norm() == 0) fail(pointer + "/target", "camera target equals its position");
    if (c.up.cross(view).norm() <= 1e-9 * c.up.norm() * view.norm())
      fail(pointer + "/up", "camera up vector is zero or parallel to the viewing direction");
    if (!(c.fovYDegrees > 0 && c.fovYDegrees < 180))
      fail(pointer + "/fov_y_degrees",
           "field of view " + io_detail::formatNumber(c.fovYDegrees) + " degrees is outside (0, 180)");
    return c;
  }

  void readMaterials(Scene& scene) {
    const json& list = member(root_, "", "materials");
    requireType(list, "/materials", json::value_t::array, "an array of materials");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string pointer = "/materials/" + std::to_string(i);
      const json& item = list[i];
      requireType(item, pointer, json::value_t::object, "a material object {name, reflectance, emission}");
      checkKeys(item, pointer, {"name", "reflectance", "emission"});
      Material m;
      m.name = string(member(item, pointer, "name"), pointer + "/name");
      if (materialIndex_.count(m.name)) fail(pointer + "/name", "duplicate material name '" + m.name + "'");
      m.reflectance = rgb(member(item, pointer, "reflectance"), pointer + "/reflectance");
      if (item.contains("emission")) m.emission = rgb(item["emission"], pointer + "/emission");
      // Point at the offending field when there is one, so that the path leads to the number to fix.
      const bool badReflectance =
          !m.reflectance.allFinite() || (m.reflectance < 0).any() || (m.reflectance >= 1).any();
      io_detail::checkMaterial(m, at(badReflectance              ? pointer + "/reflectance"
                                     : item.contains("emission") ? pointer + "/emission"
                                                                 : pointer));
      materialIndex_[m.name] = static_cast<int>(scene.materials.size());
      scene.materials.push_back(m);
    }
  }

  void readSurfaces(Scene& scene) {
    const json& list = member(root_, "", "surfaces");
    requireType(list, "/surfaces", json::value_t::array, "an array of surfaces");
    std::map<std::string, int> names;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string pointer = "/surfaces/" + std::to_string(i);
      const json& item = list[i];
      requireType(item, pointer, json::value_t::object, "a surface object {name, material, polygons}");
      checkKeys(item, pointer, {"name", "material", "polygons"});
      Surface s;
      s.name =
          item.contains("name") ? string(item["name"], pointer + "/name") : "surface " + std::to_string(i);
      if (names.count(s.name)) fail(pointer + "/name", "duplicate surface name '" + s.name + "'");
      names[s.name] = static_cast<int>(i);
      const std::string materialName = string(member(item, pointer, "material"), pointer + "/material");
      const auto found = materialIndex_.find(materialName);
      if (found == materialIndex_.end()) {
        std::string known;
        for (const Material& m : scene.materials) known += (known.empty() ? "" : ", ") + m.name;
        fail(pointer + "/material", "unknown material '" + materialName + "' (known: " + known + ")");
      }
      s.material = found->second;
      const int surfaceIndex = static_cast<int>(scene.surfaces.size());
      scene.surfaces.push_back(s);

      const json& polygons = member(item, pointer, "polygons");
      requireType(polygons, pointer + "/polygons", json::value_t::array,
                  "an array of polygons (each an array of [x, y, z] vertices)");
      if (polygons.empty()) fail(pointer + "/polygons", "surface '" + s.name + "' has no polygons");
      for (std::size_t j = 0; j < polygons.size(); ++j) {
        const std::string polygonPointer = pointer + "/polygons/" + std::to_string(j);
        const json& vertices = polygons[j];
        requireType(vertices, polygonPointer, json::value_t::array,
                    "a polygon (an array of [x, y, z] vertices)");
        Polygon polygon;
        for (std::size_t k = 0; k < vertices.size(); ++k)
          polygon.push_back(vec3(vertices[k], polygonPointer + "/" + std::to_string(k)));
        io_detail::addPolygon(scene, polygon, surfaceIndex, at(polygonPointer));
      }
    }
  }

  std::string file_;
  json root_;
  io_detail::JsonLineMap lines_;
  std::map<std::string, int> materialIndex_;
};

}  // namespace

Scene parseSceneJson(const std::string& text, const std::string& fileName) {
  try {
    return SceneJsonReader(text, fileName).read();
  } catch (const json::exception& e) {
    // Every expected problem is reported above with its path; this only keeps a surprise from escaping as a
    // crash.
    throw InputError({fileName}, std::string("cannot read the JSON scene: ") + e.what());
  }
}

Scene loadSceneJson(const std::string& path) {
  return parseSceneJson(io_detail::readTextFile(path), path);
}

}  // namespace rt
