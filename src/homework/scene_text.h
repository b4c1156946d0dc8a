// The geometry of an exercise as the project's scene files (docs/scene-format.md), so that a student can load
// it in the app or the CLI and check a hand computation against the program.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/vec.h"

namespace rt::homework {

struct NamedPolygon {
  std::string name;
  Polygon polygon;  // counter-clockwise seen from the front
  double reflectance = 0.5;
  double emission = 0;
};

std::string sceneJsonText(const std::string& title, const std::vector<NamedPolygon>& surfaces);
// OBJ without materials (one group per surface); the JSON file carries the materials.
std::string sceneObjText(const std::vector<NamedPolygon>& surfaces);

}  // namespace rt::homework
