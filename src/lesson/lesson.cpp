#include "lesson/lesson.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <utility>

namespace rt::lesson {
namespace {

constexpr std::array<std::pair<View, const char*>, 43> kViews{{
    {View::Scene, "scene"},
    {View::BasisError, "basis-error"},
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
    {View::Traced, "traced"},
    {View::Difference, "difference"},
    {View::Noise, "noise"},
    {View::TwoPass, "two-pass"},
    {View::Walkthrough, "walkthrough"},
    {View::Memory, "memory"},
    {View::Cost, "cost"},
    {View::Links, "links"},
    {View::Clusters, "clusters"},
    {View::SolidAngle, "solid-angle"},
    {View::CosineLaw, "cosine-law"},
    {View::InverseSquare, "inverse-square"},
    {View::Hits, "hits"},
    {View::RayTree, "ray-tree"},
    {View::Shadows, "shadows"},
    {View::Epsilon, "epsilon"},
    {View::RayCost, "ray-cost"},
    {View::Whitted, "whitted"},
    {View::PathBounces, "path-bounces"},
    {View::Lobe, "lobe"},
    {View::PhongSweep, "phong-sweep"},
    {View::Albedo, "albedo"},
    {View::PhongLocal, "phong-local"},
    {View::SamplingError, "sampling-error"},
    {View::Discontinuity, "discontinuity"},
    {View::Glossy, "glossy"},
    {View::TVertices, "t-vertices"},
    {View::Focus, "focus"},
    {View::Motion, "motion"},
    {View::Walks, "walks"},
}};

}  // namespace

// The one table of stages: what each computes and the views it can show. The parser checks a step's views
// against it, the docs print it (`radiosity lesson keys`), the app and the book read it.
const std::vector<StageInfo>& stageTable() {
  using V = View;
  static const std::vector<StageInfo> table{
      {Stage::Text, "text", "nothing", {}},
      {Stage::Scene, "scene", "the mesh", {V::Scene}},
      {Stage::Local,
       "local",
       "direct light + ambient term, and the radiosity solution",
       {V::Scene, V::Local, V::FormFactor, V::Matrix}},
      {Stage::FormFactors, "formfactors", "F", {V::Scene, V::FormFactor, V::Matrix, V::Visibility}},
      {Stage::Hemicube,
       "hemicube",
       "F by the hemicube",
       {V::Scene, V::FormFactor, V::Matrix, V::Hemicube, V::Visibility}},
      {Stage::Nusselt,
       "nusselt",
       "F by the Nusselt analog",
       {V::Scene, V::FormFactor, V::Matrix, V::Nusselt}},
      {Stage::Rays,
       "rays",
       "F by ray casting or Monte Carlo; with `reference`, the `from` element's local lines per surface "
       "against the reference's F",
       {V::Scene, V::FormFactor, V::Matrix, V::Rays, V::Visibility, V::Hits}},
      {Stage::Exact,
       "exact",
       "F by `methods` and by `reference`, both solved",
       {V::Scene, V::FormFactor, V::Matrix, V::Visibility, V::Error}},
      {Stage::Matrix,
       "matrix",
       "F, K, spectral radius, dominance, condition, export, and B with `solver`",
       {V::Scene, V::FormFactor, V::Matrix}},
      {Stage::Solve,
       "solve",
       "F and B with `solver`",
       {V::Scene, V::FormFactor, V::Matrix, V::Convergence, V::Walkthrough}},
      {Stage::Compare,
       "compare",
       "several `solvers`, `methods` or `subdivisions`; the stochastic solvers' noise against their rays; "
       "the first walks of the walk solvers, as they followed them",
       {V::Scene, V::FormFactor, V::Matrix, V::Convergence, V::Error, V::Noise, V::Walks}},
      {Stage::Bounces,
       "bounces",
       "B after 0..`bounces` bounces, and the exact B",
       {V::Scene, V::FormFactor, V::Matrix, V::Convergence}},
      {Stage::Benchmark,
       "benchmark",
       "run time and error of `methods` over `sweep`",
       {V::Scene, V::FormFactor, V::Matrix, V::RuntimeError, V::SweepError}},
      {Stage::Refine,
       "refine",
       "an adaptive, discontinuity or hierarchical mesh and its B; with `discontinuity`, its critical lines",
       {V::Scene, V::Discontinuity, V::TVertices}},
      {Stage::Exercise,
       "exercise",
       "a homework exercise of `topic` drawn with `seed`: questions, Check, hint, worked solution",
       {}},
      {Stage::PathTrace,
       "pathtrace",
       "B with `solver`; path-traced (`paths`), radiosity and two-pass images of `image-size`; noise against "
       "paths; times",
       {V::Scene, V::Traced, V::Difference, V::Noise, V::TwoPass, V::Walkthrough}},
      {Stage::Scaling,
       "scaling",
       "for each of `subdivisions`: bytes and time of F with `method`, time of a direct solve and of a "
       "Jacobi sweep with it, links and bytes of hierarchical-clustering; local lines' standard error for "
       "each `sweep` (rays per element); the bytes F would take on the step's own mesh, and with `solver` "
       "written, that mesh solved without F (its links and bytes); each of `scenes` solved by "
       "hierarchical-clustering, its links against n; the cluster tree at `cluster-depth`",
       {V::Scene, V::Memory, V::Cost, V::Links, V::Noise, V::Clusters}},
      {Stage::Radiometry,
       "radiometry",
       "a square patch of `patch-size` at `patch-distance` and `patch-tilt` from a point: its solid angle "
       "(exact and A cos(theta) / r^2), the irradiance a point source gives it against tilt, and the "
       "irradiance of a point source and of a square of the same power against distance (no scene: the "
       "stage builds its own)",
       {V::Scene, V::SolidAngle, V::CosineLaw, V::InverseSquare}},
      {Stage::RayTrace,
       "raytrace",
       "B with `solver`; Whitted images of `image-size` (`ray-depth`, `shadow-rays`, `ray-epsilon`, "
       "`light-size`, `mirrors`, `gloss`, `pixel-samples`, `aperture`, `focus-distance`, `moving`, `motion`) "
       "with their rays "
       "counted by kind and timed, "
       "against "
       "the cost formula; hard against soft shadows; epsilon 0, the step's and too large, with the acne and "
       "leaks counted; ideal against glossy mirrors; a pinhole against a lens; still against moving; the ray "
       "tree of pixel "
       "(`pixel-x`, `pixel-y`); "
       "path-traced images (`paths`) with 0, 1, 2 and any number of bounces",
       {V::Scene, V::RayTree, V::Shadows, V::Epsilon, V::RayCost, V::Whitted, V::PathBounces, V::Glossy,
        V::Focus, V::Motion}},
      {Stage::Reflection,
       "reflection",
       "the BRDF `brdf-model` with `phong-exponent`, `specular-fraction` and `anisotropy` for light arriving "
       "at `incidence-angle`: its lobe f_r cos(theta) in 3D, its directional albedo (energy conservation) "
       "and "
       "reciprocity, Phong's lobe for q = 1 ... 128; with a `scene`, the scene lit by Phong local "
       "illumination plus `ambient-light` beside its radiosity solution (without one, the stage builds the "
       "lobe as its scene)",
       {V::Scene, V::Lobe, V::PhongSweep, V::Albedo, V::PhongLocal}},
      {Stage::Sampling,
       "sampling",
       "B by a direct solve of F with `method` (the reference); `solver` (local-lines or "
       "local-lines-regular) with plain Monte Carlo lines, the constant control variate and Sobol lines, "
       "at each of `sweep` rays per iteration and four seeds from `seed`: RMS error against the reference, "
       "rays, time, and the log-log slope of error against rays",
       {V::Scene, V::SamplingError}},
      {Stage::Elements,
       "elements",
       "the reference B with the linear `basis` on the step's mesh (`subdivide`); for each of "
       "`subdivisions`, B with the constant and the linear basis (`solver`) and its relative L1 error "
       "against the reference over the scene and over each `highlight`ed surface; the fitted orders of the "
       "error in the element size",
       {V::Scene, V::BasisError}},
  };
  return table;
}

const StageInfo& stageInfo(Stage stage) {
  for (const StageInfo& info : stageTable())
    if (info.stage == stage) return info;
  return stageTable().front();
}

bool stageOffersView(Stage stage, View view) {
  const auto& views = stageInfo(stage).views;
  return std::find(views.begin(), views.end(), view) != views.end();
}

std::string stageTableMarkdown() {
  std::string out = "| stage | computes | views |\n|---|---|---|\n";
  for (const StageInfo& info : stageTable()) {
    std::string views;
    for (View v : info.views) views += (views.empty() ? "`" : ", `") + toString(v) + "`";
    out += "| `" + std::string(info.name) + "` | " + info.computes + " | " +
           (views.empty() ? "none" : views) + " |\n";
  }
  return out;
}

std::string toString(Stage stage) {
  return stageInfo(stage).name;
}

std::string toString(View view) {
  for (const auto& [v, name] : kViews)
    if (v == view) return name;
  return "?";
}

std::optional<Stage> stageFromString(const std::string& name) {
  for (const StageInfo& info : stageTable())
    if (name == info.name) return info.stage;
  return std::nullopt;
}

std::optional<View> viewFromString(const std::string& name) {
  for (const auto& [v, n] : kViews)
    if (name == n) return v;
  return std::nullopt;
}

std::vector<std::string> stageNames() {
  std::vector<std::string> names;
  for (const StageInfo& info : stageTable()) names.emplace_back(info.name);
  return names;
}

std::vector<std::string> viewNames() {
  std::vector<std::string> names;
  for (const auto& entry : kViews) names.emplace_back(entry.second);
  return names;
}

std::string walkthroughFrameFile(const std::string& figureFile, int frame) {
  const auto dot = figureFile.rfind('.');
  char number[16];
  std::snprintf(number, sizeof number, "-%04d", frame + 1);
  return figureFile.substr(0, dot) + number + (dot == std::string::npos ? "" : figureFile.substr(dot));
}

std::vector<std::string> Step::figureFiles() const {
  std::vector<std::string> files;
  if (figure.empty()) return files;
  if (views.size() == 1) return {figure + ".png"};
  for (View v : views) files.push_back(figure + "-" + toString(v) + ".png");
  return files;
}

}  // namespace rt::lesson
