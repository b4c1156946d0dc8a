#include "app/lesson_session.h"

#include <algorithm>
#include <optional>

#include "core/input_error.h"
#include "core/solvers/radiosity_system.h"
#include "lesson/citations.h"
#include "lesson/step_result.h"
#include "lesson/text_apparatus.h"

namespace rt::app {

LessonLibrary::LessonLibrary(lesson::LessonFolders folders, lesson::RunOptions runOptions)
    : folders_(std::move(folders)) {
  runOptions.recordHistory = true;  // the window replays a step's solver iteration by iteration
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

int LessonLibrary::stepRuns() const {
  std::lock_guard lock(runMutex_);
  return runner_->stepRuns();
}

int LessonLibrary::formFactorComputations() const {
  std::lock_guard lock(runMutex_);
  return runner_->formFactorComputations();
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
  // Solving steps are replayed iteration by iteration from the run the step runner recorded (the step is
  // computed once); a bounces step replays its partial sums, bounce by bounce.
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
  } else if (!stepResult->replay.solverName.empty()) {
    takeSolve(out, std::move(stepResult->replay));
  }
  try {
    // Equations and listings are numbered over the whole lesson, so that a step shows the numbers the book
    // prints; the works the page cites are listed under it, where its citations link to, and so are the
    // definitions of the terms it uses, where the first use of each links to.
    const lesson::TextApparatus apparatus = lesson::lessonApparatus(lesson);
    const std::string resolved = lesson::resolvedText(lesson, step, *stepResult);
    std::vector<std::string> cited = lesson::citedKeys(resolved, step.textLine, lesson.file);
    std::vector<const lesson::GlossaryEntry*> terms;
    std::string text;
    if (step.index == 0 && !lesson.intro.empty()) {
      text = "# " + lesson.title + "\n\n" +
             lesson::linkTermsToDefinitions(
                 lesson::prepareText(lesson.intro, lesson.introLine, lesson.file, apparatus),
                 apparatus.glossary, terms) +
             "\n\n";
      const auto introKeys = lesson::citedKeys(lesson.intro, lesson.introLine, lesson.file);
      cited.insert(cited.end(), introKeys.begin(), introKeys.end());
    }
    text +=
        "## " + step.title + "\n\n" +
        lesson::linkTermsToDefinitions(lesson::prepareText(resolved, step.textLine, lesson.file, apparatus),
                                       apparatus.glossary, terms);
    out.text = text + "\n\n" + lesson::furtherReading(cited, apparatus.bibliography, 3) + "\n\n" +
               lesson::termDefinitionsHtml(terms, 3);
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
  try {
    result.compared = std::make_shared<PipelineResult>(runOne(lesson, step, progress));
  } catch (const InputError& e) {
    // A comparison this step cannot make (a sampling step takes only the stochastic solvers): the step is
    // shown all the same, and the right pane says why it shows the same result, instead of an error dialog
    // in place of the step.
    auto same = std::make_shared<PipelineResult>(result);
    same->title = "Not compared: " + e.message();
    same->solverName.clear();
    same->formFactorMethod.clear();
    same->history.clear();
    result.compared = std::move(same);
  }
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
