// The one mapping from a lesson step's parameters to the pipeline's settings: mesh options, the form-factor
// method's options (its accuracy knob), the solver's options, the material overrides. The step runner, the
// app (lesson steps and the reader's own scenes) and compare mode all call it.
#pragma once

#include "core/pipeline/pipeline_settings.h"
#include "lesson/lesson.h"

namespace rt::lesson {

MeshOptions meshOptionsFor(const StepParameters& p);
// Writes `options` back as the step's mesh keys (subdivide or max-edge), e.g. after compare mode scaled them.
void setMeshOptions(StepParameters& p, const MeshOptions& options);
// The options of form-factor method `method`; a sweep value > 0 sets the method's own accuracy knob.
FormFactorOptions formFactorOptionsFor(const StepParameters& p, const std::string& method,
                                       double sweepValue = 0);
SolverOptions solverOptionsFor(const StepParameters& p);
// The form-factor method of a step: `method` when written, otherwise the stage's own (hemicube, nusselt,
// raycast), otherwise the default.
std::string methodOf(const Step& step);
// `method`: the form-factor method to use (a stage may have its own, see StageContext::method).
PipelineSettings settingsFor(const StepParameters& p, const std::string& method);

}  // namespace rt::lesson
