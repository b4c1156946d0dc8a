// Random walks from the lights (Dutré, Bekaert and Bala 2006, sec. 6.4 and 6.5), with the collision or the
// absorption estimator, whatever moves the walk from one element to the next:
// - discrete walks (random-walk, random-walk-absorption, stochastic_solvers.h) jump by the rows of a stored
//   F: from element i the next element is j with probability F_ij, as if the walk left from a uniform point
//   of i, whatever point it arrived at;
// - continuous walks (photon-density, here) are photon trajectories traced through the scene: a walk leaves
//   a light from a uniform point in a cosine-distributed direction, and after every reflection leaves the
//   point it arrived at in a new cosine-distributed direction. Their collision estimator is the photon
//   density method: the power of the hit points landing on each element, histogrammed per element, is the
//   irradiance times the area, so B_j = E_j + rho_j (power of j's hits) / A_j. They solve the radiosity
//   integral equation itself, not the constant-element linear system: an element's estimate is the average
//   over the element of the true irradiance, and no form factor is computed.
//
// A walk starts at an emitter drawn in proportion to its power, carrying all the emitted power; on arrival
// at element j it survives with probability q = max_c rho_jc (its weight multiplied by rho_jc / q) and is
// absorbed otherwise. One iteration is a batch of options.raysPerIteration walks (0 = 100 n, at least 1000);
// it stops when the relative standard error (area-weighted RMS of the per-element standard error over that
// of B) is <= options.tolerance. Deterministic for options.seed.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/solvers/solver.h"
#include "core/solvers/solver_support.h"
#include "core/vec.h"

namespace rt {

// One walk as a walk solver followed it: the source it left, every element it landed on with the weight it
// carried there (before the reflection), and how it ended. `points` holds the start and each landing: the
// traced points of a continuous walk; for a discrete walk, which has no point on an element, the element's
// centroid (where the mesh is known; the origin otherwise).
struct RecordedWalk {
  enum class End { Absorbed, Escaped, Cut };
  int source = -1;
  std::vector<int> landings;
  std::vector<Vec3> points;                 // landings.size() + 1
  std::vector<Eigen::RowVector3d> weights;  // per landing
  End end = End::Absorbed;
  double escapedPower = 0, absorbedPower = 0;  // all channels, as the solver counts them
};

// The first `count` walks the walk solver `solver` (random-walk, random-walk-absorption: discrete, over
// system.F; photon-density: continuous, over system.mesh) follows with `options`: the same random numbers,
// so the same walks, as its first batch whatever its batch size. InvalidInput for another solver or a
// system the solver refuses.
SolverStatus recordWalks(const std::string& solver, const RadiositySystem& system,
                         const SolverOptions& options, long count, std::vector<RecordedWalk>& walks);

// Continuous random walks with the collision estimator: the photon-density solver. system.mesh is required
// (InvalidInput without it); system.F is never read.
SolverStatus photonDensity(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                           const IterationSink& sink = {}, RgbField* standardError = nullptr);

namespace solver_detail {

// Where a walk stands: an element, and for continuous walks the point on it.
struct WalkPosition {
  int element = -1;  // -1: escaped (or hit the back of a polygon)
  Vec3 point = Vec3::Zero();
};

// What moves a walk: its start on a source element, and its jump from where it stands.
class WalkJumps {
 public:
  virtual ~WalkJumps() = default;
  virtual WalkPosition start(int source, Random& random) = 0;
  virtual WalkPosition jump(const WalkPosition& from, Random& random) = 0;
};

// Told of every walk as it ends (recordWalks).
using WalkObserver = std::function<void(RecordedWalk&&)>;

// The walks and their estimators (options.walkEstimator), in batches of `batch` walks.
SolverStatus walkSolve(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                       const IterationSink& sink, RgbField* standardError, WalkJumps& jumps, long batch,
                       const WalkObserver& observer = {});

// Discrete walks' jumps: the next element drawn from the row of F of the one the walk stands on
// (stochastic_solvers.cpp).
std::unique_ptr<WalkJumps> rowJumps(const FormFactorMatrix& F);

// The walks of one batch when options.raysPerIteration is 0: 100 per element, at least 1000.
long defaultWalks(const RadiositySystem& system, const SolverOptions& options);

}  // namespace solver_detail
}  // namespace rt
