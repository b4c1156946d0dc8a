#include "lesson/step_runner.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "core/formfactor/formfactor_matrix.h"
#include "core/io/scene_loader.h"
#include "lesson/placeholders.h"
#include "lesson/step_stages.h"

namespace rt::lesson {
namespace {

bool isNumber(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Material overrides: a surface with its own reflectance gets its own copy of the material, so that surfaces
// sharing the material keep theirs.
void applyOverrides(Scene& scene, const StepParameters& p, const detail::StageContext& c) {
  for (const auto& [surfaceName, rho] : p.reflectance) {
    auto it = std::find_if(scene.surfaces.begin(), scene.surfaces.end(),
                           [&](const Surface& s) { return s.name == surfaceName; });
    if (it == scene.surfaces.end())
      c.fail("reflectance." + surfaceName, "the scene has no surface '" + surfaceName + "'");
    Material m = scene.materials[it->material];
    m.name += "/" + surfaceName;
    m.reflectance = rho;
    scene.materials.push_back(m);
    it->material = static_cast<int>(scene.materials.size()) - 1;
  }
  if (p.lightScale != 1.0)
    for (auto& m : scene.materials) m.emission *= p.lightScale;
}

std::vector<int> elementsOf(const StepResult& r, const std::string& target, const detail::StageContext& c,
                            const std::string& key) {
  if (isNumber(target)) {
    const auto e = std::stoul(target);
    if (e >= r.mesh.size())
      c.fail(key,
             "element " + target + " does not exist (the mesh has " + std::to_string(r.mesh.size()) + ")");
    return {static_cast<int>(e)};
  }
  std::vector<int> out;
  for (std::size_t e = 0; e < r.mesh.size(); ++e) {
    const Patch& patch = r.scene.patches[r.mesh.elements[e].patch];
    if (r.scene.surfaces[patch.surface].name == target) out.push_back(static_cast<int>(e));
  }
  if (out.empty()) c.fail(key, "the scene has no surface '" + target + "'");
  return out;
}

void quickCaps(StepParameters& p) {
  if (p.subdivide) p.subdivide = std::min(*p.subdivide, 3);
  if (p.resolution) p.resolution = std::min(*p.resolution, 32);
  p.samples = std::min(p.samples.value_or(8), 8);
  // Lists keep their length and labels (the text names their entries); only the largest values shrink.
  for (int& s : p.sweep) s = std::min(s, 64);
  if (p.maxEdge) p.maxEdge = *p.maxEdge * 2.0;
}

}  // namespace

StepRunner::StepRunner(std::string scenesDir, RunOptions options)
    : scenesDir_(std::move(scenesDir)), options_(std::move(options)) {}

const Scene& StepRunner::scene(const std::string& relativePath) {
  auto it = scenes_.find(relativePath);
  if (it == scenes_.end())
    it = scenes_.emplace(relativePath, loadScene((std::filesystem::path(scenesDir_) / relativePath).string()))
             .first;
  return it->second;
}

std::shared_ptr<const FormFactorMatrix> StepRunner::formFactors(const Mesh& mesh, const std::string& meshKey,
                                                                const std::string& method,
                                                                const FormFactorOptions& options,
                                                                FormFactorStats& stats, Progress& progress) {
  std::ostringstream key;
  key << mesh.geometryHash() << "|" << meshKey << "|" << method << "|" << options.hemicubeResolution << "|"
      << options.samples << "|" << options.seed << "|" << options.tolerance;
  if (auto it = cache_.find(key.str()); it != cache_.end()) {
    stats = it->second.stats;
    return it->second.F;
  }
  auto algorithm = makeFormFactorMethod(method);
  auto F = std::make_shared<FormFactorMatrix>(algorithm->compute(mesh, options, progress, stats));
  ++computations_;
  cache_[key.str()] = {F, stats};
  return F;
}

StepResult StepRunner::run(const Lesson& lesson, const Step& step, Progress& progress) {
  StepResult result;
  detail::StageContext c{lesson, step, step.parameters, *this, progress, result, {}, "", {}};
  if (options_.quick) quickCaps(c.parameters);
  if (step.stage == Stage::Text) return result;

  try {
    result.scene = scene(step.scene);
  } catch (const InputError& e) {
    c.fail("scene", std::string("the scene does not load: ") + e.what());
  }
  applyOverrides(result.scene, c.parameters, c);
  const StepParameters& p = c.parameters;
  if (p.subdivide) {
    c.meshOptions.mode = MeshOptions::Mode::Count;
    c.meshOptions.count = *p.subdivide;
    c.meshKey = "count" + std::to_string(*p.subdivide);
  } else if (p.maxEdge) {
    c.meshOptions.mode = MeshOptions::Mode::MaxEdge;
    c.meshOptions.maxEdge = *p.maxEdge;
    c.meshKey = "edge" + std::to_string(*p.maxEdge);
  } else {
    c.meshKey = "none";
  }
  result.mesh = buildMesh(result.scene, c.meshOptions);
  c.formFactorOptions = c.optionsFor(c.method(), 0);

  // The camera: the scene's (or one that sees everything), with the step's overrides.
  result.camera = result.scene.cameraOrDefault();
  if (step.camera.position) result.camera.position = *step.camera.position;
  if (step.camera.target) result.camera.target = *step.camera.target;
  if (step.camera.up) result.camera.up = *step.camera.up;
  if (step.camera.fovYDegrees) result.camera.fovYDegrees = *step.camera.fovYDegrees;

  for (const auto& h : step.highlights)
    for (int e : elementsOf(result, h, c, "highlight")) result.highlighted.push_back(e);
  if (!step.from.empty()) result.sourceElement = elementsOf(result, step.from, c, "from").front();

  result.values["elements"] = static_cast<double>(result.mesh.size());
  result.values["patches"] = static_cast<double>(result.scene.patches.size());
  result.values["surfaces"] = static_cast<double>(result.scene.surfaces.size());
  result.values["source"] = result.sourceElement;
  for (const auto& surface : result.scene.surfaces) {
    Eigen::VectorXd areas = result.mesh.areas();
    double area = 0;
    for (std::size_t e = 0; e < result.mesh.size(); ++e)
      if (result.scene.surfaces[result.scene.patches[result.mesh.elements[e].patch].surface].name ==
          surface.name)
        area += areas[static_cast<Eigen::Index>(e)];
    result.values["area." + surface.name] = area;
  }
  detail::addSurfaceValues(result, "rho", result.mesh.reflectance);
  detail::addSurfaceValues(result, "E", result.mesh.emission);

  switch (step.stage) {
    case Stage::Text:
    case Stage::Scene:
      break;
    case Stage::FormFactors:
    case Stage::Hemicube:
    case Stage::Nusselt:
    case Stage::Rays: {
      result.method = c.method();
      result.F = c.formFactors(result.mesh, c.meshKey, result.method, "method", result.formFactorStats);
      detail::addFormFactorValues(result, *result.F);
      break;
    }
    case Stage::Local:
      detail::computeLocal(c);
      break;
    case Stage::Matrix:
      detail::computeMatrix(c);
      break;
    case Stage::Solve:
      detail::computeSolve(c);
      break;
    case Stage::Compare:
      detail::computeCompare(c);
      break;
    case Stage::Bounces:
      detail::computeBounces(c);
      break;
    case Stage::Exact:
      detail::computeExact(c);
      break;
    case Stage::Benchmark:
      detail::computeBenchmark(c);
      break;
    case Stage::Refine:
      detail::computeRefine(c);
      break;
  }
  if (result.B.rows() == static_cast<Eigen::Index>(result.mesh.size()))
    detail::addSurfaceValues(result, "B", result.B);
  return result;
}

std::string resolvedText(const Lesson& lesson, const Step& step, const StepResult& result) {
  return resolvePlaceholders(
      step.text, step.textLine, lesson.file, [&](const std::string& name) { return result.value(name); },
      result.valueNames());
}

}  // namespace rt::lesson
