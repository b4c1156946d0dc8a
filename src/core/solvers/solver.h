// Solvers in Eigen's shape: compute(system), solve() -> B, info(), iterations(), error(), and an observer
// called after every iteration with a record the app can replay. Non-convergence is a status, never an
// exception.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/formfactor/line_sampling.h"
#include "core/progress.h"
#include "core/solvers/radiosity_system.h"

namespace rt {

enum class SolverStatus { Success, NoConvergence, NumericalIssue, InvalidInput, Cancelled };
std::string toString(SolverStatus status);

struct SolverOptions {
  double tolerance = 1e-6;  // on the relative residual (gathering) or relative unshot power (shooting)
  // A sweep over all elements (gather), one shot (shooting), one bounce or one stochastic round; 0 is
  // automatic: sweepCap and shotCap.
  int maxIterations = 0;
  double relaxation = 1.0;    // over-relaxation factor for Gauss-Seidel (SOR when > 1)
  bool ambient = false;       // progressive: add the ambient term to the displayed B
  std::uint64_t seed = 1;     // stochastic solvers
  long raysPerIteration = 0;  // stochastic: ray budget per iteration (0 = a default from n)
  // local-lines, local-lines-regular: how the lines' numbers are drawn (line_sampling.h), and whether they
  // shoot B - beta with a constant control variate beta (line_shooting.h).
  LineSampling sampling = LineSampling::Random;
  bool controlVariate = false;
  // hierarchical-clustering: a link is kept when the light it could miss is at most this fraction of the
  // scene's mean radiosity (0 = defaultClusterTolerance()).
  double clusterTolerance = 0;
  bool recordHistory = true;  // keep every IterationRecord (memory n x 3 doubles per iteration)
  // random-walk: score every collision (lower variance) or only where a walk is absorbed.
  enum class WalkEstimator { Collision, Absorption };
  WalkEstimator walkEstimator = WalkEstimator::Collision;
  // Shooting: the exact residual costs O(n^2) and a shot O(n), so it is recomputed every this many shots and
  // carried over in between (the first and last records are always exact). 0 = automatic: max(1, n / 512).
  int residualEvery = 0;
};

// The iteration caps when SolverOptions::maxIterations is 0. Gathering converges in a number of sweeps that
// does not grow with n, so 1000 sweeps; a shot moves one element's light, so shooting needs shots in
// proportion to n: 100 sweeps' worth (100 n shots, at least 1000). A fixed 1000 shots stopped the Cornell
// box at 418 elements after fewer than three sweeps' worth, 1e-3 away from the solution.
int sweepCap(const SolverOptions& options);
int shotCap(const SolverOptions& options, long long elements);

struct IterationRecord {
  int iteration = 0;
  RgbField B;              // current estimate (for progressive with ambient: the displayed B + rho * ambient)
  RgbField unshot;         // unshot radiosity (shooting methods; empty otherwise)
  double residual = 0;     // ||K B - E|| / ||E||
  double unshotPower = 0;  // sum over elements and channels of unshot_i * A_i
  double emittedPower = 0;  // sum E_i A_i (all channels)
  double absorbedPower =
      0;               // sum (1 - rho_i) H_i A_i (all channels), H = incident irradiance; shooting: so far
  int shooter = -1;    // shooting methods: the element shot in this iteration
  double seconds = 0;  // since solve() started
  double escapedPower =
      0;  // power that left through openings (sum B_i A_i (1 - sum_j F_ij)); shooting: so far
  double standardError = 0;  // stochastic methods: area-weighted RMS of the per-element standard error of
                             // B, relative to that of B (solver_detail::relativeAreaRms)
  long rays = 0;             // stochastic methods: rays (or walks) used so far
  // Hierarchical methods: links, nodes, and the bytes they hold (counted from the containers, at the peak).
  long links = 0;
  long nodes = 0;
  long long memoryBytes = 0;
};

using IterationObserver = std::function<void(const IterationRecord&)>;
// What the free algorithm functions call after every iteration (the Solver classes forward it to record()).
using IterationSink = std::function<void(IterationRecord)>;

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string name() const = 0;
  void setOptions(const SolverOptions& options) { options_ = options; }
  const SolverOptions& options() const { return options_; }
  void setObserver(IterationObserver observer) { observer_ = std::move(observer); }
  void setProgress(Progress* progress) { progress_ = progress; }

  virtual Solver& compute(const RadiositySystem& system) {
    system_ = &system;
    return *this;
  }
  virtual RgbField solve() = 0;

  SolverStatus info() const { return status_; }
  int iterations() const { return iterations_; }
  double error() const { return error_; }  // final relative residual (or its estimate)
  const std::vector<IterationRecord>& history() const { return history_; }
  // Stochastic solvers: per-element standard error of the returned B (n x 3); empty for deterministic
  // solvers.
  const RgbField& standardError() const { return standardError_; }

 protected:
  // Called by implementations after every iteration: stores history, calls the observer, checks cancellation.
  void record(IterationRecord record);

  SolverOptions options_;
  IterationObserver observer_;
  Progress* progress_ = nullptr;
  double progressShown_ = 0;  // the largest fraction reported: a progress bar never moves backwards
  const RadiositySystem* system_ = nullptr;
  SolverStatus status_ = SolverStatus::InvalidInput;
  int iterations_ = 0;
  double error_ = 0;
  std::vector<IterationRecord> history_;
  RgbField standardError_;
};

// What a solver needs besides rho, E and the areas: the stored matrix F, F or its rows on demand (the
// shooting solvers with a row provider), or the mesh itself to trace rays through (system.mesh; no form
// factor at all). The pipeline computes F only for the solvers that read it.
enum class SolverInput { Matrix, MatrixOrRows, Geometry };

// One row per solver: the registry's table. solverNames(), the lessons' choices, the CLI's --solver and the
// app's panel come from it; `settings` are the step keys (lesson/step_keys.h) the solver reads.
struct SolverInfo {
  std::string name;
  SolverInput input = SolverInput::Matrix;
  std::string summary;
  std::vector<std::string> settings;
};
const std::vector<SolverInfo>& solverTable();
// The row of `name`; throws std::invalid_argument naming the known solvers.
const SolverInfo& solverInfo(const std::string& name);
// False for a solver that never reads F, so that nothing n x n is computed for it.
bool solverNeedsMatrix(const std::string& name);

// Registry by name (solverTable()): direct, jacobi, gauss-seidel, southwell, progressive, bounces,
// stochastic-jacobi, random-walk, random-walk-absorption, local-lines, local-lines-regular, photon-density,
// hierarchical-clustering.
std::unique_ptr<Solver> makeSolver(const std::string& name);  // throws std::invalid_argument
std::vector<std::string> solverNames();
// The solver used when none is named: a direct solve for small n, an iterative one otherwise.
std::string chooseSolver(std::size_t n);

// What `radiosity solve` runs when neither a solver nor a form-factor method is named: the way to about 1 %
// error that is soonest at this size, with the reason and the accuracy to expect, for the reader to see.
struct AutomaticSolve {
  std::string solver;
  bool formFactors = true;  // false: the solver traces its own rays, no F is computed
  std::string why;
};
AutomaticSolve chooseAutomaticSolve(std::size_t n);

}  // namespace rt
