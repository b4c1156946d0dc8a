// The generators of topic_table.cpp, one per topic, grouped by chapter in topics_*.cpp. Internal to
// rt_homework: everything else reaches them through the table.
#pragma once

#include <optional>

#include "homework/topic_table.h"

namespace rt::homework {

std::optional<Exercise> generateRectangles(Draw& draw);
std::optional<Exercise> generateNusselt(Draw& draw);
std::optional<Exercise> generateClosure(Draw& draw);
std::optional<Exercise> generateHemicube(Draw& draw);
std::optional<Exercise> generateRaycast(Draw& draw);
std::optional<Exercise> generateAssembleK(Draw& draw);
std::optional<Exercise> generateJacobiGaussSeidel(Draw& draw);
std::optional<Exercise> generateSouthwell(Draw& draw);
std::optional<Exercise> generateBounces(Draw& draw);
std::optional<Exercise> generateSpectralRadius(Draw& draw);
std::optional<Exercise> generateToneMapping(Draw& draw);
std::optional<Exercise> generateSubdivision(Draw& draw);
std::optional<Exercise> generateIrradiance(Draw& draw);
std::optional<Exercise> generatePhong(Draw& draw);
std::optional<Exercise> generateStochasticJacobi(Draw& draw);
std::optional<Exercise> generateRayTree(Draw& draw);
std::optional<Exercise> generateReflectionEquation(Draw& draw);
std::optional<Exercise> generateHierarchicalOracle(Draw& draw);
std::optional<Exercise> generateRandomWalk(Draw& draw);
std::optional<Exercise> generateTwoPass(Draw& draw);
std::optional<Exercise> generateLinearElement(Draw& draw);
std::optional<Exercise> generateDiscontinuity(Draw& draw);
std::optional<Exercise> generateDenseCost(Draw& draw);

}  // namespace rt::homework
