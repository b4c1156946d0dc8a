// The lessons as the app sees them: the catalogue of a lessons folder (a broken lesson file is reported, the
// others still open), and running a step, with the reader's parameter changes, into a PipelineResult the
// window shows. No Qt widgets: the step runs on a worker thread.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "app/compare_choice.h"
#include "app/pipeline.h"
#include "lesson/lesson.h"
#include "lesson/lesson_loader.h"
#include "lesson/step_runner.h"

namespace rt::app {

class LessonLibrary {
 public:
  // `runOptions.quick` caps resolutions and subdivisions (tests walking every step).
  explicit LessonLibrary(lesson::LessonFolders folders, lesson::RunOptions runOptions = {});
  ~LessonLibrary();

  // Re-reads every lesson file; files that fail to load are listed in errors().
  void reload();
  const lesson::LessonFolders& folders() const { return folders_; }
  const std::vector<lesson::Lesson>& lessons() const { return lessons_; }
  const std::vector<std::string>& errors() const { return errors_; }
  // Index in lessons() or -1.
  int indexOf(const std::string& id) const;
  // The lesson a first-time reader starts with: "welcome" when there is one, else the first of the book.
  int welcomeIndex() const;

  // Runs a step with `parameters` in place of the step's own (the reader's changes) and, when `compare`
  // changes something, the same step with that solver, method or mesh for the compare pane. Serialised: one
  // step at a time (the step runner's form-factor cache is not shared between threads). May throw InputError,
  // Cancelled.
  PipelineResult runStep(int lessonIndex, int stepIndex, const lesson::StepParameters& parameters,
                         const CompareChoice& compare, Progress& progress);
  // The step as written, as the step runner returns it (what its figures are drawn from).
  std::shared_ptr<const lesson::StepResult> computeStep(int lessonIndex, int stepIndex, Progress& progress);
  // How often form factors were computed (the rest came from the cache).
  int formFactorComputations() const;
  // How many times a step was run by the step runner (a step opened once is run once).
  int stepRuns() const;

 private:
  PipelineResult runOne(const lesson::Lesson& lesson, const lesson::Step& step, Progress& progress);

  lesson::LessonFolders folders_;
  std::vector<lesson::Lesson> lessons_;
  std::vector<std::string> errors_;
  std::unique_ptr<lesson::StepRunner> runner_;
  mutable std::mutex runMutex_;
};

}  // namespace rt::app
