#include "app/lesson_session.h"

#include <algorithm>
#include <optional>

#include "core/input_error.h"
#include "core/solvers/radiosity_system.h"
#include "lesson/step_result.h"

namespace rt::app {

LessonLibrary::LessonLibrary(lesson::LessonFolders folders, lesson::RunOptions runOptions)
    : folders_(std::move(folders)) {
  runner_ = std::make_unique<lesson::StepRunner>(folders_.scenes, std::move(runOptions));
  reload();
}

LessonLibrary::~LessonLibrary() = default;

void LessonLibrary::reload() {
  lessons_.clear();
  errors_.clear();
  std::vector<std::string> files;
  try {
    files = lesson::lessonFiles(folders_.lessons);
  } catch (const std::exception& e) {
    errors_.push_back(e.what());
  }
  for (const std::string& file : files) {
    try {
      lessons_.push_back(lesson::loadLesson(file, folders_.scenes));
    } catch (const std::exception& e) {
      errors_.push_back(e.what());
    }
  }
  std::stable_sort(lessons_.begin(), lessons_.end(), [](const lesson::Lesson& a, const lesson::Lesson& b) {
    return a.order != b.order ? a.order < b.order : a.id < b.id;
  });
}

int LessonLibrary::indexOf(const std::string& id) const {
  for (std::size_t i = 0; i < lessons_.size(); ++i)
    if (lessons_[i].id == id) return static_cast<int>(i);
  return -1;
}

int LessonLibrary::welcomeIndex() const {
  const int welcome = indexOf("welcome");
  if (welcome >= 0) return welcome;
  return lessons_.empty() ? -1 : 0;
}

int LessonLibrary::formFactorComputations() const {
  std::lock_guard lock(runMutex_);
  return runner_->formFactorComputations();
}

SolverOptions solverOptionsFromParameters(const lesson::StepParameters& p) {
  SolverOptions options;
  if (p.iterations) options.maxIterations = *p.iterations;
  if (p.tolerance) options.tolerance = *p.tolerance;
  if (p.relaxation) options.relaxation = *p.relaxation;
  if (p.seed) options.seed = *p.seed;
  options.ambient = p.ambient;
  return options;
}

PipelineSettings settingsFromParameters(const lesson::StepParameters& p) {
  PipelineSettings s;
  if (p.subdivide) {
    s.mesh.mode = MeshOptions::Mode::Count;
    s.mesh.count = *p.subdivide;
  } else if (p.maxEdge) {
    s.mesh.mode = MeshOptions::Mode::MaxEdge;
    s.mesh.maxEdge = *p.maxEdge;
  }
  s.method = p.method;
  if (p.resolution) s.formFactors.hemicubeResolution = *p.resolution;
  if (p.samples) s.formFactors.samples = *p.samples;
  if (p.seed) s.formFactors.seed = *p.seed;
  s.solver = p.solver;
  s.solverOptions = solverOptionsFromParameters(p);
  s.reflectance = p.reflectance;
  s.lightScale = p.lightScale;
  return s;
}

PipelineResult LessonLibrary::runOne(const lesson::Lesson& lesson, const lesson::Step& step,
                                     Progress& progress) {
  auto stepResult = std::make_shared<lesson::StepResult>(runner_->run(lesson, step, progress));
  PipelineResult out;
  out.scene = std::make_shared<Scene>(stepResult->scene);
  out.mesh = std::make_shared<Mesh>(stepResult->mesh);
  out.camera = stepResult->camera;
  out.F = stepResult->F;
  out.formFactorStats = stepResult->formFactorStats;
  if (out.F) out.formFactorMethod = stepResult->method.empty() ? step.parameters.method : stepResult->method;
  out.title = step.title;
  // An exact step solves the room with its first approximate method's F (its error map is among the step's
  // figures): the view says whose radiosity it shows, not the step's title over it.
  if (step.stage == lesson::Stage::Exact && !stepResult->method.empty() && out.F)
    out.title = "Radiosity with " + stepResult->method + " form factors";
  // What the 3D view shows: the solution, else the local-illumination estimate, else the materials (B then
  // holds the ambient estimate, for exports that need a radiosity).
  if (stepResult->B.rows() == static_cast<Eigen::Index>(stepResult->mesh.size())) {
    out.B = stepResult->B;
  } else if (stepResult->local.rows() == static_cast<Eigen::Index>(stepResult->mesh.size())) {
    out.B = stepResult->local;
  } else {
    out.B = ambientEstimate(stepResult->mesh);
    out.materials = true;
  }
  // Solving steps are replayed iteration by iteration: solve again with the history recorded (F is at hand,
  // so this costs a solve, never a form-factor computation). A bounces step replays its partial sums, bounce
  // by bounce.
  const bool solves = step.stage == lesson::Stage::Solve || step.stage == lesson::Stage::Compare ||
                      step.stage == lesson::Stage::Matrix;
  if (step.stage == lesson::Stage::Bounces && !stepResult->bounceTerms.empty()) {
    std::optional<RadiositySystem> system;
    if (out.F) system = RadiositySystem::fromMesh(stepResult->mesh, *out.F);
    RgbField sum = RgbField::Zero(static_cast<Eigen::Index>(stepResult->mesh.size()), 3);
    for (std::size_t k = 0; k < stepResult->bounceTerms.size(); ++k) {
      sum += stepResult->bounceTerms[k];
      IterationRecord record;
      record.iteration = static_cast<int>(k);
      record.B = sum;
      record.residual = system ? system->relativeResidual(sum) : 0.0;
      out.history.push_back(std::move(record));
    }
    out.solverName = "bounces";
    out.iterations = static_cast<int>(out.history.size());
    out.residual = out.history.back().residual;
    out.status = SolverStatus::Success;
  } else if (out.F && solves && stepResult->B.rows() > 0) {
    // A step that compares solvers replays the one it measures against its reference (the last listed), not
    // the default solver the step never names.
    std::string replay = step.parameters.solver;
    if (!step.parameters.solvers.empty() && !step.fields.count("solver"))
      replay = step.parameters.solvers.back();
    solveWithHistory(out, replay, solverOptionsFromParameters(step.parameters), progress);
  }
  try {
    std::string text = "## " + step.title + "\n\n" + lesson::resolvedText(lesson, step, *stepResult);
    if (step.index == 0 && !lesson.intro.empty())
      text = "# " + lesson.title + "\n\n" + lesson.intro + "\n\n" + text;
    out.text = text;
  } catch (const InputError& e) {
    out.text = step.text;
    out.note = e.what();
  }
  out.stepResult = stepResult;
  return out;
}

PipelineResult LessonLibrary::runStep(int lessonIndex, int stepIndex,
                                      const lesson::StepParameters& parameters, const CompareChoice& compare,
                                      Progress& progress) {
  std::lock_guard lock(runMutex_);
  const lesson::Lesson& lesson = lessons_.at(static_cast<std::size_t>(lessonIndex));
  lesson::Step step = lesson.steps.at(static_cast<std::size_t>(stepIndex));
  step.parameters = parameters;
  PipelineResult result = runOne(lesson, step, progress);
  if (!compare.changesSomething()) return result;
  if (compare.refinesMesh()) {
    // A mesh that follows the light is its own computation (core/refine), from the same scene.
    result.compared = std::make_shared<PipelineResult>(
        runRefinedPipeline(result.scene, compare.mesh, runner_->options().quick, progress));
    return result;
  }
  if (!compare.solver.empty()) {
    step.parameters.solver = compare.solver;
    step.fields["solver"] = lesson::Field{compare.solver, 0};  // the chosen solver, not the step's list
  }
  if (!compare.method.empty()) step.parameters.method = compare.method;
  scaleStepMesh(step.parameters, compare.mesh);
  result.compared = std::make_shared<PipelineResult>(runOne(lesson, step, progress));
  return result;
}

std::shared_ptr<const lesson::StepResult> LessonLibrary::computeStep(int lessonIndex, int stepIndex,
                                                                     Progress& progress) {
  std::lock_guard lock(runMutex_);
  const lesson::Lesson& lesson = lessons_.at(static_cast<std::size_t>(lessonIndex));
  const lesson::Step& step = lesson.steps.at(static_cast<std::size_t>(stepIndex));
  return std::make_shared<lesson::StepResult>(runner_->run(lesson, step, progress));
}

}  // namespace rt::app
