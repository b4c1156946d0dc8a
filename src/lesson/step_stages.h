// The computations behind each stage, shared by StepRunner. Internal to rt_lesson.
#pragma once

#include <string>
#include <vector>

#include "core/formfactor/formfactor_method.h"
#include "core/input_error.h"
#include "core/mesh.h"
#include "core/solvers/radiosity_system.h"
#include "lesson/lesson.h"
#include "lesson/step_result.h"
#include "lesson/step_runner.h"

namespace rt::lesson::detail {

struct StageContext {
  const Lesson& lesson;
  const Step& step;
  StepParameters parameters;  // after quick-mode caps
  StepRunner& runner;
  Progress& progress;
  StepResult& result;
  MeshOptions meshOptions;
  FormFactorOptions formFactorOptions;

  SourceLocation at(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  // A method name the registry rejected: MethodUnavailable for known names, a plain InputError otherwise.
  [[noreturn]] void failUnavailable(const std::string& key, const std::string& name,
                                    const std::string& what) const;
  // The form-factor method: `method` when written, otherwise the stage's own (hemicube, nusselt, raycast).
  std::string method() const;
  // F for a mesh with a method (cached), errors reported at the `method`/`methods` line.
  std::shared_ptr<const FormFactorMatrix> formFactors(const Mesh& mesh, const std::string& method,
                                                      const std::string& key, FormFactorStats& stats);
  // The options of `method` for this step (lesson/step_settings.h), capped in quick mode; a sweep value > 0
  // sets the method's own accuracy knob.
  FormFactorOptions optionsFor(const std::string& method, int sweepValue) const;
  // The solver whose run a reader replays iteration by iteration: the step's solver, or in a step comparing
  // solvers the last one listed (the one measured against the first).
  std::string replayedSolver() const;
};

// Runs one solver on a system; B receives the solution. The run of replayedSolver() on the step's main system
// (`replayable`) keeps its iterations in result.replay when the runner records history.
SolverRun runSolver(StageContext& c, const std::string& name, const RadiositySystem& system, RgbField& B,
                    const std::string& label, bool replayable = false);

// Named values: per-surface means of a field (B.<surface>, with .r .g .b), surface-to-surface form factors.
void addSurfaceValues(StepResult& r, const std::string& prefix, const RgbField& field,
                      const std::string& suffix = "");
void addFormFactorValues(StepResult& r, const FormFactorMatrix& F, const std::string& suffix = "");
// Shooting runs: per surface, how many of the run's shots its elements made (shots.<surface>) and the number
// of its first shot, counting from 1 (first-shot.<surface>; 0 when it has not shot).
void addShotValues(StepResult& r, const SolverRun& run);

// Everything a stage's pictures depend on, as a key for StepRunner::keptPictures: the scene, every
// parameter as a lesson would write it but the `ignored` keys, the camera.
std::string picturesKey(const StageContext& c, const std::vector<std::string>& ignored);

void computeLocal(StageContext& c);
void computeMatrix(StageContext& c);
void computeSolve(StageContext& c);
void computeCompare(StageContext& c);
void computeBounces(StageContext& c);
void computeExact(StageContext& c);
void computeBenchmark(StageContext& c);
void computeRefine(StageContext& c);
void computePathTrace(StageContext& c);   // stage_pathtrace.cpp
void computeScaling(StageContext& c);     // stage_scaling.cpp
void computeRadiometry(StageContext& c);  // stage_radiometry.cpp: builds its own scene, no scene file
void computeRayTrace(StageContext& c);    // stage_raytrace.cpp
// stage_reflection.cpp: the BRDF's lobe (its scene when the step names none); with a scene, Phong local
// illumination beside the radiosity solution.
void computeReflection(StageContext& c);
// The classic ambient radiosity of the local model: the light reflected once (`direct`, per element), its
// area-weighted mean amplified by 1 / (1 - mean rho); `chosen` > 0 replaces it (the ambient-light key).
Rgb classicAmbient(const Mesh& mesh, const RgbField& direct, double chosen);
// Adds `polygon` to a scene a stage builds for itself, as a patch of surface `surface` (normal and area from
// the polygon).
void addScenePatch(Scene& scene, const Polygon& polygon, int surface);
void computeSampling(StageContext& c);     // stage_sampling.cpp
void computeSolveLinear(StageContext& c);  // stage_elements.cpp: a solve step with `basis: linear`
void computeElements(StageContext& c);     // stage_elements.cpp
// Rays stage with a `reference`: the `from` element's local lines per surface against the reference's F
// (lines.<surface>, lines-se.<surface>, lines.<surface>.reference, lines-z.<surface>, lines-z.max, lines).
void addLocalLineValues(StageContext& c);  // stage_rays.cpp

}  // namespace rt::lesson::detail
