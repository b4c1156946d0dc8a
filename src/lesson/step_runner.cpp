#include "lesson/step_runner.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "core/camera_path.h"
#include "core/contact_lines.h"
#include "core/formfactor/formfactor_matrix.h"
#include "core/io/scene_loader.h"
#include "core/pipeline/scene_overrides.h"
#include "homework/topic_table.h"
#include "lesson/placeholders.h"
#include "lesson/step_settings.h"
#include "lesson/step_stages.h"

namespace rt::lesson {
namespace {

bool isNumber(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::vector<int> elementsOf(const StepResult& r, const std::string& target, const detail::StageContext& c,
                            const std::string& key) {
  if (isNumber(target)) {
    const auto e = (target.size() > 9 ? ~0ul : std::stoul(target));
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
  // Divided rather than capped, so that a reader's change still changes a quick run's pictures.
  p.paths = std::max(4, p.paths / 4);
  const int fullSize = std::max(1, p.imageSize);
  p.imageSize = std::max(16, p.imageSize / 4);
  // The traced pixel keeps its place in the smaller image.
  p.pixelX = p.pixelX * p.imageSize / fullSize;
  p.pixelY = p.pixelY * p.imageSize / fullSize;
  p.gatherRays = std::max(4, p.gatherRays / 4);
  p.shadowRays = std::max(1, p.shadowRays / 4);
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

std::shared_ptr<const FormFactorMatrix> StepRunner::formFactors(const Mesh& mesh, const std::string& method,
                                                                const FormFactorOptions& options,
                                                                FormFactorStats& stats, Progress& progress) {
  auto cached = pipeline_.formFactors(mesh, method, options, progress);
  stats = cached->stats;
  return {cached, &cached->F};
}

void StepRunner::keep(const std::string& key, std::any pictures) {
  kept_.emplace_back(key, std::move(pictures));
  if (kept_.size() > 3) kept_.pop_front();
}

StepResult StepRunner::run(const Lesson& lesson, const Step& step, Progress& progress) {
  ++stepRuns_;
  StepResult result;
  detail::StageContext c{lesson, step, step.parameters, *this, progress, result, {}, {}};
  if (options_.quick) quickCaps(c.parameters);
  if (step.stage == Stage::Text) return result;
  if (step.stage == Stage::Exercise) {
    // No scene: a conceptual question is the lesson's own; a numeric exercise brings its own numbers, drawn
    // from the step's seed (student 0: the book's).
    if (!step.choices.empty()) {
      result.exercise = homework::conceptualExercise(step.title, step.choices);
      result.values["answer.choice"] = result.exercise->questions.front().answer;
      return result;
    }
    const homework::Topic* topic = homework::findTopic(step.parameters.topic);
    if (!topic) c.fail("topic", "unknown homework topic '" + step.parameters.topic + "'");
    result.exercise = homework::generateExercise(*topic, step.parameters.seed.value_or(1), 0);
    for (const auto& [name, value] : result.exercise->given) result.values["given." + name] = value;
    for (const auto& q : result.exercise->questions) result.values["answer." + q.id] = q.answer;
    return result;
  }
  if (step.stage == Stage::Radiometry) {
    detail::computeRadiometry(c);
    return result;
  }
  if (step.stage == Stage::Reflection && step.scene.empty()) {
    detail::computeReflection(c);  // the lobe is its scene
    return result;
  }

  try {
    result.scene = scene(step.scene);
  } catch (const InputError& e) {
    c.fail("scene", std::string("the scene does not load: ") + e.what());
  }
  const StepParameters& p = c.parameters;
  for (const auto& entry : p.reflectance) {
    const std::string& surface = entry.first;  // a plain name: clang 14 cannot capture a structured binding
    if (std::none_of(result.scene.surfaces.begin(), result.scene.surfaces.end(),
                     [&](const Surface& s) { return s.name == surface; }))
      c.fail("reflectance." + surface, "the scene has no surface '" + surface + "'");
  }
  result.scene = applyOverrides(result.scene, p.reflectance, p.lightScale);
  c.meshOptions = meshOptionsFor(p);
  result.mesh = buildMesh(result.scene, c.meshOptions);
  c.formFactorOptions = c.optionsFor(c.method(), 0);

  // The camera: the scene's (or one that sees everything), with the step's overrides.
  result.camera = result.scene.cameraOrDefault();
  if (!step.camera.name.empty()) result.camera = namedCamera(result.scene, step.camera.name, c.at("camera"));
  std::vector<Camera> keys;
  for (const auto& name : step.camera.path)
    keys.push_back(namedCamera(result.scene, name, c.at("camera-path")));
  result.cameraPath = interpolateCameraPath(keys, step.camera.pathFrames);
  if (step.camera.position) result.camera.position = *step.camera.position;
  if (step.camera.target) result.camera.target = *step.camera.target;
  if (step.camera.up) result.camera.up = *step.camera.up;
  if (step.camera.fovYDegrees) result.camera.fovYDegrees = *step.camera.fovYDegrees;

  for (const auto& h : step.highlights)
    for (int e : elementsOf(result, h, c, "highlight")) result.highlighted.push_back(e);
  if (!c.parameters.from.empty())
    result.sourceElement = elementsOf(result, c.parameters.from, c, "from").front();

  result.values["elements"] = static_cast<double>(result.mesh.size());
  result.values["patches"] = static_cast<double>(result.scene.patches.size());
  result.values["surfaces"] = static_cast<double>(result.scene.surfaces.size());
  result.values["source"] = result.sourceElement;
  result.values["contact-segments"] = 0;  // a reader who turns the cut off still sees the number: none
  if (c.meshOptions.splitAtContacts) {
    // The contact lines the mesh was cut along (the tolerance buildMesh cuts with).
    const Eigen::AlignedBox3d box = result.scene.bounds();
    const double size = box.isEmpty() ? 1.0 : box.diagonal().norm();
    double contacts = 0;
    for (std::size_t p = 0; p < result.scene.patches.size(); ++p)
      contacts += static_cast<double>(contactSegments(result.scene, static_cast<int>(p), 1e-7 * size).size());
    result.values["contact-segments"] = contacts;
  }
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
    case Stage::Exercise:
    case Stage::Radiometry:
    case Stage::Scene:
      break;
    case Stage::FormFactors:
    case Stage::Hemicube:
    case Stage::Nusselt:
    case Stage::Rays: {
      result.method = c.method();
      result.F = c.formFactors(result.mesh, result.method, "method", result.formFactorStats);
      detail::addFormFactorValues(result, *result.F);
      if (step.stage == Stage::Rays) detail::addLocalLineValues(c);
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
    case Stage::PathTrace:
      detail::computePathTrace(c);
      break;
    case Stage::Reflection:
      detail::computeReflection(c);
      break;
    case Stage::Scaling:
      detail::computeScaling(c);
      break;
    case Stage::RayTrace:
      detail::computeRayTrace(c);
      break;
    case Stage::Sampling:
      detail::computeSampling(c);
      break;
    case Stage::Elements:
      detail::computeElements(c);
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

std::string resolvedCaption(const Lesson& lesson, const Step& step, const StepResult& result) {
  if (step.caption.empty()) return {};
  return resolvePlaceholders(
      step.caption, step.captionLine, lesson.file,
      [&](const std::string& name) { return result.value(name); }, result.valueNames());
}

}  // namespace rt::lesson
