#include "homework/scene_text.h"

#include <cstdio>

namespace rt::homework {
namespace {

std::string coordinate(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

std::string point(const Vec3& p) {
  return "[" + coordinate(p.x()) + ", " + coordinate(p.y()) + ", " + coordinate(p.z()) + "]";
}

}  // namespace

std::string sceneJsonText(const std::string& title, const std::vector<NamedPolygon>& given) {
  // The program solves only scenes with a light: when no surface emits, the first one does (form factors do
  // not depend on it).
  std::vector<NamedPolygon> surfaces = given;
  bool lit = false;
  for (const NamedPolygon& s : surfaces) lit = lit || s.emission > 0;
  if (!lit && !surfaces.empty()) surfaces.front().emission = 1;
  std::string materials, list;
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    const NamedPolygon& s = surfaces[k];
    materials += std::string(k ? ",\n" : "") + "    {\"name\": \"" + s.name +
                 "-material\", \"reflectance\": " + coordinate(s.reflectance) +
                 (s.emission > 0 ? ", \"emission\": " + coordinate(s.emission) : std::string()) + "}";
    std::string vertices;
    for (std::size_t v = 0; v < s.polygon.size(); ++v) vertices += (v ? ", " : "") + point(s.polygon[v]);
    list += std::string(k ? ",\n" : "") + "    {\"name\": \"" + s.name + "\", \"material\": \"" + s.name +
            "-material\", \"polygons\": [[" + vertices + "]]}";
  }
  return "{\n  \"name\": \"" + title + "\",\n  \"unit\": \"m\",\n  \"materials\": [\n" + materials +
         "\n  ],\n  \"surfaces\": [\n" + list + "\n  ]\n}\n";
}

std::string sceneObjText(const std::vector<NamedPolygon>& surfaces) {
  std::string out =
      "# radiosity homework geometry: one group per surface, faces counter-clockwise from the front\n";
  int next = 1;
  for (const NamedPolygon& s : surfaces) {
    out += "g " + s.name + "\n";
    for (const Vec3& p : s.polygon)
      out += "v " + coordinate(p.x()) + " " + coordinate(p.y()) + " " + coordinate(p.z()) + "\n";
    out += "f";
    for (std::size_t v = 0; v < s.polygon.size(); ++v)
      out += " " + std::to_string(next + static_cast<int>(v));
    out += "\n";
    next += static_cast<int>(s.polygon.size());
  }
  return out;
}

}  // namespace rt::homework
