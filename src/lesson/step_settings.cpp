#include "lesson/step_settings.h"

#include <cmath>

namespace rt::lesson {

MeshOptions meshOptionsFor(const StepParameters& p) {
  MeshOptions o;
  if (p.subdivide) {
    o.mode = MeshOptions::Mode::Count;
    o.count = *p.subdivide;
  } else if (p.maxEdge) {
    o.mode = MeshOptions::Mode::MaxEdge;
    o.maxEdge = *p.maxEdge;
  }
  o.splitAtContacts = p.splitAtContacts && o.mode != MeshOptions::Mode::None;
  if (p.overlapGap) o.overlapGap = *p.overlapGap;
  return o;
}

void setMeshOptions(StepParameters& p, const MeshOptions& options) {
  p.splitAtContacts = options.splitAtContacts;
  if (options.overlapGap != MeshOptions{}.overlapGap) p.overlapGap = options.overlapGap;
  switch (options.mode) {
    case MeshOptions::Mode::Count:
      p.subdivide = options.count;
      p.maxEdge.reset();
      break;
    case MeshOptions::Mode::MaxEdge:
      p.maxEdge = options.maxEdge;
      p.subdivide.reset();
      break;
    case MeshOptions::Mode::None:
      p.subdivide.reset();
      p.maxEdge.reset();
      break;
  }
}

FormFactorOptions formFactorOptionsFor(const StepParameters& p, const std::string& method,
                                       double sweepValue) {
  FormFactorOptions o;
  if (p.resolution) o.hemicubeResolution = *p.resolution;
  if (p.samples) o.samples = *p.samples;
  if (p.formFactorTolerance) o.tolerance = *p.formFactorTolerance;
  if (p.formFactorBudget) o.workBudget = std::lround(*p.formFactorBudget);
  if (p.seed) o.seed = *p.seed;
  o.sampling = parseLineSampling(p.sampling).value_or(LineSampling::Random);
  if (sweepValue > 0) {
    const AccuracyKnob knob = accuracyKnobOf(method);
    o = knob.applied(o, knob.fromSweep(static_cast<int>(sweepValue)));
  }
  return o;
}

SolverOptions solverOptionsFor(const StepParameters& p) {
  SolverOptions o;
  if (p.tolerance) o.tolerance = *p.tolerance;
  if (p.iterations) o.maxIterations = *p.iterations;
  if (p.relaxation) o.relaxation = *p.relaxation;
  if (p.raysPerIteration) o.raysPerIteration = *p.raysPerIteration;
  if (p.clusterTolerance) o.clusterTolerance = *p.clusterTolerance;
  if (p.seed) o.seed = *p.seed;
  o.ambient = p.ambient;
  o.sampling = parseLineSampling(p.sampling).value_or(LineSampling::Random);
  o.controlVariate = p.controlVariate;
  return o;
}

std::string methodOf(const Step& step) {
  if (step.fields.count("method")) return step.parameters.method;
  switch (step.stage) {
    case Stage::Hemicube:
      return "hemicube";
    case Stage::Nusselt:
      return "nusselt";
    case Stage::Rays:
      return "raycast";
    default:
      return step.parameters.method;
  }
}

PipelineSettings settingsFor(const StepParameters& p, const std::string& method) {
  PipelineSettings s;
  s.mesh = meshOptionsFor(p);
  s.method = method;
  s.formFactors = formFactorOptionsFor(p, method);
  s.solver = p.solver;
  s.basis = parseBasis(p.basis).value_or(Basis::Constant);
  s.solverOptions = solverOptionsFor(p);
  s.reflectance = p.reflectance;
  s.lightScale = p.lightScale;
  return s;
}

}  // namespace rt::lesson
