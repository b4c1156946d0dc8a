// One interface for every form-factor method (analytic, hemicube, raycast, montecarlo, nusselt, exact).
// Methods register by name; `radiosity formfactors --method NAME` and the lessons pick them by that name.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/formfactor/formfactor_matrix.h"
#include "core/formfactor/line_sampling.h"
#include "core/mesh.h"
#include "core/progress.h"

namespace rt {

struct FormFactorOptions {
  int hemicubeResolution = 128;  // pixels along the top face's edge
  int samples = 16;              // raycast: sample pairs per element pair; montecarlo: rays per element
  std::uint64_t seed = 1;        // stochastic methods are deterministic for a seed
  LineSampling sampling = LineSampling::Random;  // montecarlo: pseudo-random or Sobol local lines
  // exact: requested relative tolerance; quadrature: absolute error per entry; 0: the method's own default
  // (its knob's defaultValue), so that a solve that names the method without a tolerance costs what the
  // method says it costs.
  double tolerance = 0;
  int threads = 0;  // 0 = all cores
  // exact: the most point evaluations the whole matrix may take; past it the run stops with a message that
  // names this budget (WorkBudgetExceeded). 0: no limit.
  long workBudget = 0;
};

// What a run did and skipped; printed as one line by the CLI.
struct FormFactorStats {
  std::size_t elements = 0;
  std::size_t pairsComputed = 0;       // pairs that were integrated
  std::size_t pairsSkippedFacing = 0;  // one entirely behind the other's plane: F = 0 without work
  std::size_t pairsByReciprocity = 0;  // derived as F_ji = A_i F_ij / A_j
  std::size_t pairsUnoccluded = 0;     // shaft proved empty: no visibility work
  std::size_t raysCast = 0;
  // Work of the methods that integrate kernels: Lambert point-to-polygon evaluations and exact contour
  // integrals (a measure of cost that does not depend on the machine or its load).
  std::size_t kernelEvaluations = 0, contourIntegrals = 0;
  double seconds = 0.0;
  double standardError = 0.0;  // stochastic methods: RMS standard error of the entries (0 otherwise)
  std::size_t pairsOccludersIgnored = 0;  // pairs whose shaft may be blocked, computed as if it were not
  std::string notes;                      // e.g. "visibility by ray casting (16 rays/pair)"
  // What a user must know about the result: rows of F summing to more than 1, occluders ignored. Filled by
  // FormFactorMethod::compute for every method, printed by every command and shown by the app.
  std::vector<std::string> warnings;
  std::string summary() const;  // one line
};

// The one option that buys a method accuracy for time, declared by the method itself, so that bench sweeps,
// lessons, the app and the CLI set the field the method actually reads (the Nusselt analog reads `samples`,
// the hemicube `hemicubeResolution`).
struct AccuracyKnob {
  enum class Field { None, Resolution, Samples, Tolerance };
  Field field = Field::None;
  std::string name;  // the step key and CLI option: "resolution", "samples", "ff-tolerance"; empty for none
  std::string meaning;  // what the number counts, for tooltips and docs
  double min = 0, max = 0, defaultValue = 0;

  // `options` with the knob set to `value` (unchanged for a method without a knob).
  FormFactorOptions applied(FormFactorOptions options, double value) const;
  // The knob's value for a point of a sweep (a lesson's `sweep`, `bench formfactors`): a resolution or a
  // count as it is; a tolerance 10^-v, v the digits asked for, so that sweeps stay whole numbers that grow
  // with the effort for every method.
  double fromSweep(int v) const;
  // The knob's current value in `options` (0 for a method without a knob).
  double valueIn(const FormFactorOptions& options) const;
};

class FormFactorMethod {
 public:
  virtual ~FormFactorMethod() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  virtual AccuracyKnob knob() const { return {}; }
  // The error the method states for one computed entry at `options` (its knob resolved): a row sums to at
  // most 1 plus these over its entries before compute() warns. 0 for methods that state none per entry.
  virtual double entryErrorBound(double entry, const FormFactorOptions& options) const;
  // The options the matrix depends on, the others at their defaults: the form-factor cache's key, so that a
  // new seed or line sampling (meant for a stochastic method) does not compute a deterministic method's F
  // again. All of them, unless the method reads its knob alone (readsOnlyItsKnob).
  FormFactorOptions significantOptions(const FormFactorOptions& options) const;
  // The full n x n matrix for the mesh's elements, checked: stats.warnings says what is wrong with it. May
  // throw Cancelled.
  FormFactorMatrix compute(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                           FormFactorStats& stats) const;
  // True when row i of the matrix depends on nothing but the mesh, i and the options (the hemicube): rows
  // computed apart, by makeRowProvider (row_providers.h) in processes that share no memory (the web edition's
  // workers), then make the matrix compute() makes, bit for bit.
  virtual bool rowsAreIndependent() const { return false; }
  // The matrix from such rows (n x n, every row filled), with the checks, counters and warnings compute()
  // gives its own; stats.seconds is left to the caller. Throws std::invalid_argument for a method whose rows
  // are not independent.
  FormFactorMatrix fromRows(FormFactorMatrix F, const Mesh& mesh, const FormFactorOptions& options,
                            FormFactorStats& stats) const;

 protected:
  // True for a method whose matrix no option changes but its knob (`threads` changes no result).
  virtual bool readsOnlyItsKnob() const { return false; }
  virtual FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options,
                                         Progress& progress, FormFactorStats& stats) const = 0;
  // What a method checks and counts on its whole matrix, after computeMatrix or fromRows, with the sums of
  // F's rows from the one pass that all the checks share.
  virtual void checkRows(const Mesh& mesh, const FormFactorOptions& options, const FormFactorMatrix& F,
                         const RowSums& rows, FormFactorStats& stats) const;
};

using FormFactorMethodFactory = std::function<std::unique_ptr<FormFactorMethod>()>;

// Registry. Built-in methods register themselves in formfactor_registry.cpp; the exact library adds "exact"
// with registerFormFactorMethod when it is linked (rt::exact::registerExactMethod()).
void registerFormFactorMethod(const std::string& name, FormFactorMethodFactory factory);
std::unique_ptr<FormFactorMethod> makeFormFactorMethod(
    const std::string& name);  // throws std::invalid_argument
// The methods this build can run (the registry).
std::vector<std::string> formFactorMethodNames();
// Methods a layer above the core registers when the build has it ("exact" needs CGAL): lesson files and the
// CLI accept their names in every build, and making one that is absent says what the build lacks.
const std::vector<std::string>& optionalFormFactorMethods();
// Every name a lesson or a command may give: the registered methods and the optional ones, sorted.
std::vector<std::string> declaredFormFactorMethods();
// The method every computation uses when none is named: the CLI, the app, a lesson step without `method`,
// PipelineSettings. Quadrature: the most accurate for its time on every scene measured (docs/formfactors.md).
const std::string& defaultFormFactorMethod();
// The knob of a registered method (AccuracyKnob{} for an unknown name).
AccuracyKnob accuracyKnobOf(const std::string& method);

}  // namespace rt
