// What running one step produced: the scene and mesh, the form factors, the solutions, convergence histories
// and the named numbers a step's text can quote as {{placeholders}} (docs/lesson-format.md lists the names).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/formfactor/formfactor_method.h"
#include "core/mesh.h"
#include "core/pipeline/pipeline.h"
#include "core/refine/refine.h"
#include "core/scene.h"
#include "core/solvers/random_walks.h"
#include "core/solvers/sampling_study.h"
#include "homework/exercise.h"
#include "lesson/elements_data.h"
#include "lesson/radiometry_data.h"
#include "lesson/raytrace_data.h"
#include "lesson/reflection_data.h"
#include "lesson/scaling_data.h"
#include "lesson/traced_pictures.h"

namespace rt::lesson {

// One convergence curve: a solver on a system, or a bounce series.
struct SolverRun {
  std::string label;  // solver name (or "sub4", a method name... in compare steps)
  std::string status;
  int iterations = 0;
  double residual = 0;
  double seconds = 0;
  std::vector<double> iteration, residuals, elapsed;  // one entry per recorded iteration
  std::vector<int> shooters;                          // shooting solvers: the element of each shot
  // Stochastic solvers, one entry per iteration: the rays so far and the relative standard error of B.
  std::vector<double> rays, standardErrors;
};

// The first walks of a walk solver of a compare step, as the solver followed them (recordWalks).
struct DrawnWalks {
  std::string solver;
  std::vector<RecordedWalk> walks;
};

// One point of a run-time-against-error sweep.
struct BenchmarkPoint {
  std::string method;
  int parameter = 0;  // resolution or samples
  double seconds = 0;
  double error = 0;  // ||F - F_ref||_F / ||F_ref||_F
};

// A variant of a compare step (another subdivision or form-factor method) kept for its figure.
struct Variant {
  std::string label;
  Mesh mesh;
  RgbField B;
};

struct StepResult {
  Scene scene;  // after the step's material overrides
  Mesh mesh;
  Camera camera;
  std::vector<Camera> cameraPath;             // the step's camera-path, one camera per frame (empty: none)
  std::shared_ptr<const FormFactorMatrix> F;  // empty when the stage needs none
  FormFactorStats formFactorStats;
  std::string method;                                  // the form-factor method used
  std::shared_ptr<const FormFactorMatrix> referenceF;  // exact and benchmark stages
  RgbField B;                                          // the solution (empty for stages that do not solve)
  RgbField reference;                 // a reference solution (exact stage: with the reference F)
  RgbField local;                     // local stage: direct light plus ambient
  std::vector<RgbField> bounceTerms;  // bounces stage: term k = (rho F)^k E
  std::vector<SolverRun> runs;
  std::vector<BenchmarkPoint> benchmark;
  std::vector<Variant> variants;
  // Compare stage with the walks view: one discrete walk solver's first walks and the photons' first ones.
  std::vector<DrawnWalks> walks;
  int sourceElement = 0;         // the element hemicube / Nusselt / rays / formfactor views look from
  std::vector<int> highlighted;  // element indices
  std::string exportedMatrix;    // path of the exported matrix, when the step asked for one
  // Matrix stage: the matrix the matrix view shows (StepParameters::matrix: F, rho F or K = I - rho F, with
  // the green channel's rho), so that the figure and the numbers quoted beside it come from the same data.
  std::shared_ptr<const Eigen::MatrixXd> shownMatrix;
  // The solver run a reader replays iteration by iteration (RunOptions::recordHistory): its B per iteration.
  SolveOutcome replay;

  // Pathtrace stage: the images, the noise sweep and the times.
  std::shared_ptr<const TracedPictures> pictures;

  // A linear basis (`basis: linear`, the elements stage's reference): B at every element corner
  // (LinearBasis::cornerValues), drawn as it is; B above holds the element averages.
  RgbField corners;
  // Elements stage: both bases' error against the reference on each mesh, and the fitted orders.
  std::shared_ptr<const ElementsData> elements;

  // Scaling stage: the dense method's cost and the clustering and local-lines solvers' against n and rays.
  std::shared_ptr<const ScalingData> scaling;

  // Sampling stage: error against rays for plain Monte Carlo, the control variate and Sobol lines.
  std::shared_ptr<const std::vector<SamplingSeries>> sampling;

  // Radiometry stage: the patch, its solid angle and the irradiance curves.
  std::shared_ptr<const RadiometryData> radiometry;

  // Raytrace stage: the Whitted images, one pixel's ray tree and the rays counted against the formula.
  std::shared_ptr<const RayTraceData> raytrace;
  // Reflection stage: the BRDF, its lobe and albedo; with a scene, the local and radiosity pictures.
  std::shared_ptr<const ReflectionData> reflection;
  // Refine stage: the refined solution, with its T-vertices and (discontinuity) critical lines.
  std::shared_ptr<const RefinedSolution> refined;

  // Exercise stage: the question, its answers and worked solution (values: given.<name>, answer.<id>).
  std::optional<homework::Exercise> exercise;

  std::map<std::string, double> values;  // named numbers, see value()

  // A named number: the values map, then the indexed forms F[i][j], B[i], B[i].r, rowsum[i].
  std::optional<double> value(const std::string& name) const;
  // The names available (indexed forms shown once, with i and j).
  std::vector<std::string> valueNames() const;
};

// Area-weighted mean of the three channels over the elements of a surface (nullopt for an unknown surface).
std::optional<Rgb> surfaceMean(const Mesh& mesh, const Scene& scene, const RgbField& field,
                               const std::string& surface);

}  // namespace rt::lesson
