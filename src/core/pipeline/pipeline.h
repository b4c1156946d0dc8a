// The one pipeline from settings to a solution: apply the overrides, mesh, form factors (one cache, one key:
// geometry, method and its options, so that RGB and material-only changes never recompute F), solve with the
// iteration history when asked. The lessons' step runner, the app and the CLI each hold a Pipeline and call
// it; stages that need more (bounces, benchmarks, refinement) call its pieces.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/formfactor/formfactor_cache.h"
#include "core/pipeline/pipeline_settings.h"
#include "core/progress.h"
#include "core/scene.h"
#include "core/solvers/radiosity_system.h"

namespace rt {

// One point of a convergence curve (kept for every run; the full B of each iteration only on request).
struct IterationPoint {
  int iteration = 0;
  double residual = 0;
  double seconds = 0;
  int shooter = -1;          // shooting solvers: the element that shot in this iteration
  long rays = 0;             // stochastic solvers: the rays so far
  double standardError = 0;  // stochastic solvers: the relative standard error of B
  double unshot = 0;         // shooting solvers: the unshot power as a fraction of the emitted power
};

struct SolveOutcome {
  std::string solverName;
  RgbField B;
  std::vector<IterationRecord> history;  // every iteration's B; empty unless recordHistory
  std::vector<IterationPoint> trace;     // the convergence curve
  SolverStatus status = SolverStatus::InvalidInput;
  int iterations = 0;
  double error = 0;     // the solver's own final error (its stopping measure)
  double residual = 0;  // relative residual ||K B - E|| / ||E|| of the returned B (without F: error)
  double seconds = 0;
  // Stochastic solvers: the per-element standard error of B (n x 3; empty otherwise), its area-weighted
  // RMS relative to that of B, and the rays used.
  RgbField standardErrors;
  double standardError = 0;
  long rays = 0;
  // Hierarchical solvers: links, nodes and the bytes they hold (IterationRecord).
  long links = 0;
  long nodes = 0;
  long long memoryBytes = 0;
  // A linear basis: the solution per node and at every element corner (LinearBasis::cornerValues), the
  // function itself, which views draw as it is; B above holds its element averages. Empty for constant.
  RgbField nodal, corners;
};

struct LinearKernel;  // linear_solve.h

struct PipelineOutput {
  std::shared_ptr<const Scene> scene;  // with the overrides applied
  std::shared_ptr<const Mesh> mesh;
  // null when the method is not in this build, or when the solver reads no F (solverNeedsMatrix)
  std::shared_ptr<const FormFactorMatrix> F;
  std::string formFactorMethod;  // the method that computed F (empty without F)
  FormFactorStats formFactorStats;
  bool formFactorsReused = false;
  std::shared_ptr<const LinearKernel> linear;  // the linear basis's nodes and kernel; null for constant
  SolveOutcome solve;
  std::string note;  // why the result is an approximation, when it is one
};

class Pipeline {
 public:
  explicit Pipeline(std::size_t cachedMatrices = 4);

  // May throw Cancelled and InputError. A form-factor method missing from this build leaves F null, and B
  // the ambient estimate, with a note. A solver that traces rays itself (local-lines) gets no F at all.
  PipelineOutput run(const Scene& scene, const PipelineSettings& settings, Progress& progress = noProgress());

  // F of `method` for this mesh, from the cache when the same geometry, method and options were computed
  // before. Throws std::invalid_argument for a method this build does not have.
  std::shared_ptr<const CachedFormFactors> formFactors(const Mesh& mesh, const std::string& method,
                                                       const FormFactorOptions& options, Progress& progress,
                                                       bool* reused = nullptr);

  // True when formFactors() would answer from the cache; storeFormFactors keeps a matrix assembled from rows
  // computed elsewhere (the web edition's workers) where formFactors() finds it.
  bool holdsFormFactors(const Mesh& mesh, const std::string& method, const FormFactorOptions& options) const;
  void storeFormFactors(const Mesh& mesh, const std::string& method, const FormFactorOptions& options,
                        std::shared_ptr<const CachedFormFactors> value);

  // The linear basis's kernel for this mesh, kept for the last geometry and options (a material change
  // reuses it). Throws InputError for a mesh the basis cannot use, Cancelled.
  std::shared_ptr<const LinearKernel> linearKernel(const Mesh& mesh, const FormFactorOptions& options,
                                                   Progress& progress, bool* reused = nullptr);

  // How many times F was actually computed (the rest came from the cache).
  int formFactorComputations() const { return static_cast<int>(cache_.misses()); }

 private:
  FormFactorCache cache_;
  std::shared_ptr<const LinearKernel> linear_;
  std::uint64_t linearKey_ = 0;
  double linearTolerance_ = -1;
};

// The scene with the settings' overrides, and its mesh, as run() makes them.
struct MeshedScene {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const Mesh> mesh;
};
MeshedScene meshScene(const Scene& input, const PipelineSettings& settings);

// Solves the system by `solverName` (empty: chooseSolver(n)); `observer`, when given, sees every iteration
// (the CLI's --verbose). Throws std::invalid_argument for an unknown solver, Cancelled when progress asks.
SolveOutcome solveRadiosity(const RadiositySystem& system, const std::string& solverName,
                            SolverOptions options, bool recordHistory, Progress& progress,
                            const std::function<void(const IterationRecord&)>& observer = {});

// Direct light plus the classic ambient term: B_i = E_i + rho_i * ambient, ambient = (sum E A / sum A) / (1 -
// rho_avg). Shown when no form-factor method or solver is available, so that the view is never empty.
RgbField ambientEstimate(const Mesh& mesh);

}  // namespace rt
