#include "lesson/lesson.h"

#include <array>
#include <utility>

namespace rt::lesson {
namespace {

constexpr std::array<std::pair<Stage, const char*>, 14> kStages{{
    {Stage::Text, "text"},
    {Stage::Scene, "scene"},
    {Stage::Local, "local"},
    {Stage::FormFactors, "formfactors"},
    {Stage::Hemicube, "hemicube"},
    {Stage::Nusselt, "nusselt"},
    {Stage::Rays, "rays"},
    {Stage::Exact, "exact"},
    {Stage::Matrix, "matrix"},
    {Stage::Solve, "solve"},
    {Stage::Compare, "compare"},
    {Stage::Bounces, "bounces"},
    {Stage::Benchmark, "benchmark"},
    {Stage::Refine, "refine"},
}};

constexpr std::array<std::pair<View, const char*>, 12> kViews{{
    {View::Scene, "scene"},
    {View::FormFactor, "formfactor"},
    {View::Hemicube, "hemicube"},
    {View::Nusselt, "nusselt"},
    {View::Rays, "rays"},
    {View::Matrix, "matrix"},
    {View::Convergence, "convergence"},
    {View::RuntimeError, "runtime-error"},
    {View::SweepError, "sweep-error"},
    {View::Visibility, "visibility"},
    {View::Error, "error"},
    {View::Local, "local"},
}};

}  // namespace

std::string toString(Stage stage) {
  for (const auto& [s, name] : kStages)
    if (s == stage) return name;
  return "?";
}

std::string toString(View view) {
  for (const auto& [v, name] : kViews)
    if (v == view) return name;
  return "?";
}

std::optional<Stage> stageFromString(const std::string& name) {
  for (const auto& [s, n] : kStages)
    if (name == n) return s;
  return std::nullopt;
}

std::optional<View> viewFromString(const std::string& name) {
  for (const auto& [v, n] : kViews)
    if (name == n) return v;
  return std::nullopt;
}

std::vector<std::string> stageNames() {
  std::vector<std::string> names;
  for (const auto& entry : kStages) names.emplace_back(entry.second);
  return names;
}

std::vector<std::string> viewNames() {
  std::vector<std::string> names;
  for (const auto& entry : kViews) names.emplace_back(entry.second);
  return names;
}

std::vector<std::string> Step::figureFiles() const {
  std::vector<std::string> files;
  if (figure.empty()) return files;
  if (views.size() == 1) return {figure + ".png"};
  for (View v : views) files.push_back(figure + "-" + toString(v) + ".png");
  return files;
}

}  // namespace rt::lesson
