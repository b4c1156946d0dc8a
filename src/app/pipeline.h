// What the app's window shows of a computation: the core pipeline's output (scene, mesh, F, solution and its
// iterations, see core/pipeline/pipeline.h) plus what a lesson step adds (title, text, the step's result) and
// compare mode's second result. A view model only: the computing is done by rt::Pipeline, for lesson steps
// through the step runner.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/pipeline/pipeline.h"

namespace rt::app {

struct StepFigures;

struct PipelineResult {
  std::shared_ptr<const Scene> scene;  // with the overrides applied
  std::shared_ptr<const Mesh> mesh;
  std::shared_ptr<const FormFactorMatrix> F;  // null when no form-factor method was available
  std::string formFactorMethod;               // the method that computed F (empty without F)
  FormFactorStats formFactorStats;
  bool formFactorsReused = false;
  std::string solverName;
  RgbField B;
  std::vector<IterationRecord> history;
  SolverStatus status = SolverStatus::InvalidInput;
  int iterations = 0;
  double residual = 0;
  std::string note;        // why the result is an approximation, when it is one
  bool materials = false;  // no radiosity to show (a benchmark step): the 3D view shows the materials
  Camera camera;
  // Lesson steps: the title, the step's text with its placeholders filled in, and what the step runner
  // returned.
  std::string title;
  std::string text;
  std::shared_ptr<const void>
      stepResult;  // a lesson::StepResult (kept opaque so that core users need no lesson)
  // Compare mode: the same scene with the compared settings (another solver or form-factor method).
  std::shared_ptr<const PipelineResult> compared;
  // A lesson step's figures other than the 3D view, drawn on the worker thread with the step (StepFigures,
  // app/step_figures.h); null when they were not drawn there.
  std::shared_ptr<const StepFigures> figures;

  bool valid() const { return mesh != nullptr; }
};

// The window's view of a solve (solver name, B, its iterations, status, residual).
void takeSolve(PipelineResult& result, SolveOutcome solve);

// A user's scene through the core pipeline (`pipeline` keeps the form factors between runs: a change of
// reflectance or light re-solves without recomputing F). May throw Cancelled and InputError.
PipelineResult runScenePipeline(Pipeline& pipeline, const Scene& scene, const PipelineSettings& settings,
                                Progress& progress);

}  // namespace rt::app
