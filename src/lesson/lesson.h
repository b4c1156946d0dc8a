// A lesson as data: an ordered list of steps, each naming a scene, a computation (the stage), its parameters,
// the views to show and the Markdown text to read beside them. Lessons are Markdown files in lessons/ (see
// docs/lesson-format.md); every field remembers the line it came from so that errors and placeholders can
// name it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/formfactor/formfactor_method.h"
#include "core/scene.h"
#include "homework/conceptual.h"

namespace rt::lesson {

// What a step computes. Each stage computes only what it needs (a `scene` step never computes form factors).
enum class Stage {
  Text,         // no computation, no figure
  Scene,        // load and mesh the scene; show its geometry and materials
  Local,        // direct light plus a constant ambient term, beside the radiosity solution
  FormFactors,  // F with one method; diagnostics (closure, reciprocity)
  Hemicube,     // F by the hemicube; the hemicube of one element
  Nusselt,      // F by the Nusselt analog; its projection disk
  Rays,         // F by ray casting or Monte Carlo; the rays of one element
  Exact,        // F by a method against a reference method; error per element
  Matrix,       // K = I - diag(rho) F: dominance, spectral radius, export
  Solve,        // B with one solver
  Compare,      // several solvers, methods or subdivisions side by side
  Bounces,      // B after 0, 1, 2 ... bounces (Neumann series)
  Benchmark,    // run time against error for methods over a parameter sweep
  Refine,       // meshes that follow the light: adaptive, discontinuity or hierarchical (core/refine)
  Exercise,     // a homework exercise (src/homework) the reader answers: questions, Check, hint, solution
  PathTrace,    // the radiosity image against a path-traced one of the same equation, and the two-pass image
  Scaling,      // the dense matrix's memory and time against n, clustering's links, local lines' noise
  Radiometry,   // a patch seen from a point: solid angle, the cosine law, point against area source
  RayTrace,    // Whitted ray tracing: one pixel's ray tree, shadows, the epsilon, the cost, against radiosity
  Reflection,  // a BRDF's lobe, albedo and Phong's exponent; with a scene, Phong local light beside radiosity
  Sampling,    // plain Monte Carlo, control variate and quasi-Monte Carlo lines: error against rays
  Elements,    // constant against linear elements: error against the mesh, fitted convergence orders
};

// The figures a step can ask for; the names match the viz layer's views.
enum class View {
  Scene,
  FormFactor,
  Hemicube,
  Nusselt,
  Rays,
  Matrix,
  Convergence,
  RuntimeError,
  SweepError,  // error against the sweep's knob (samples, resolution), log-log
  Visibility,
  Error,
  Local,
  Traced,         // path-traced and radiosity images side by side
  Difference,     // |image - path-traced| of the radiosity and two-pass images
  Noise,          // the path tracer's noise against its paths per pixel, log-log
  TwoPass,        // the two-pass image beside the path-traced one
  Walkthrough,    // the solution along the step's camera path, as numbered frames
  Memory,         // bytes of the dense F against n, log-log, with this machine's memory
  Cost,           // form-factor time against n, log-log
  Links,          // clustering's links against the n^2 element pairs
  Clusters,       // the cluster tree's boxes at one depth over the scene
  SolidAngle,     // the patch projected onto the sphere about the point: its solid angle
  CosineLaw,      // irradiance on the patch against its tilt
  InverseSquare,  // irradiance against distance from a point source and from a square of the same power
  Hits,           // rays stage: the local lines' hit fractions per surface with their standard errors, and F
  RayTree,        // raytrace stage: one pixel's ray tree in the scene
  Shadows,        // one shadow ray per light (hard) against many over its area (soft)
  Epsilon,        // the self-intersection epsilon: 0, the step's, too large
  RayCost,        // rays per pixel against depth: the cost formula and the counted rays
  Whitted,        // the Whitted picture beside the radiosity solution
  PathBounces,    // path-traced pictures with 0, 1, 2 and any number of diffuse bounces
  Lobe,           // f_r(w_i, w_o) cos(theta_o) over the hemisphere as a 3D surface, with the incoming ray
  PhongSweep,     // cos^q(alpha) against alpha for q = 1, 2, 4, ..., 128
  Albedo,         // the directional albedo against the angle of incidence
  PhongLocal,     // the scene lit by Phong local illumination plus ambient, beside its radiosity solution
  SamplingError,  // sampling stage: error against rays per variance reduction, log-log, with fitted slopes
  Discontinuity,  // refine stage: the mesh with its critical lines, umbra/penumbra boundaries apart
  Glossy,         // raytrace stage: the mirrors ideal beside the same mirrors glossy (gloss, pixel-samples)
  Focus,          // raytrace stage: the pinhole picture beside the lens's (aperture, focus-distance)
  Motion,         // raytrace stage: the scene standing still beside it with `moving` in motion (motion)
  BasisError,     // elements stage: error against elements per basis, log-log, with the fitted orders
  TVertices,      // refine stage: the mesh with its T-vertices and the long edges they split
  Walks,          // compare stage: the first walks of the step's walk solvers drawn in the scene
};

// A row of the table of stages: its name, what it computes and the views it can show.
struct StageInfo {
  Stage stage;
  const char* name;
  const char* computes;
  std::vector<View> views;
};
const std::vector<StageInfo>& stageTable();
const StageInfo& stageInfo(Stage stage);
bool stageOffersView(Stage stage, View view);
// The table as Markdown (docs/lesson-format.md holds it; a test keeps the two equal).
std::string stageTableMarkdown();

std::string toString(Stage stage);
std::string toString(View view);
std::optional<Stage> stageFromString(const std::string& name);
std::optional<View> viewFromString(const std::string& name);
std::vector<std::string> stageNames();
std::vector<std::string> viewNames();

// A value from a step block, with the line it was written on.
struct Field {
  std::string value;
  int line = 0;
};

struct CameraOverride {
  std::string name;  // a camera the scene names; position... adjust it
  std::optional<Vec3> position, target, up;
  std::optional<double> fovYDegrees;
  std::vector<std::string> path;  // camera-path: the scene's cameras a walkthrough flies through
  int pathFrames = 48;
  bool any() const { return !name.empty() || position || target || up || fovYDegrees; }
};

// The parameters of a step. Unset optionals mean "the method's or solver's default".
struct StepParameters {
  std::string method = defaultFormFactorMethod();
  std::vector<std::string> methods;           // compare / benchmark / exact: several methods
  std::string reference;                      // exact / benchmark: the method errors are measured against
  std::optional<int> resolution;              // hemicube resolution
  std::optional<int> samples;                 // raycast / montecarlo samples
  std::optional<double> formFactorTolerance;  // quadrature / exact: the form factors' tolerance
  std::optional<double> formFactorBudget;     // exact: the most point evaluations of the whole matrix
  std::optional<std::uint64_t> seed;
  std::string sampling = "random";   // montecarlo, local-lines solvers: random or Sobol lines
  bool controlVariate = false;       // local-lines solvers: a constant control variate
  std::optional<int> subdivide;      // N x N per patch
  std::optional<double> maxEdge;     // or: split until no edge is longer than this
  bool splitAtContacts = false;      // with subdivide or maxEdge: cut patches where other surfaces stand
  std::optional<double> overlapGap;  // with the cuts: also under parallel patches this near (of the diagonal)
  std::vector<int> subdivisions;     // compare: several subdivision levels
  std::vector<int> sweep;            // benchmark: resolutions (hemicube) or samples (rays) to try
  std::string solver = "gauss-seidel";
  std::string basis = "constant";    // constant or linear (core/basis/linear_basis.h)
  std::vector<std::string> solvers;  // compare: several solvers
  std::optional<int> iterations;     // maximum iterations
  std::optional<double> tolerance;
  std::optional<double> relaxation;
  std::optional<int> raysPerIteration;     // stochastic solvers: rays of the first iteration
  std::optional<double> clusterTolerance;  // hierarchical-clustering: the refinement's threshold
  bool ambient = false;                    // progressive refinement with the ambient term
  int bounces = 6;                         // bounces stage
  double ambientLight = 0.0;  // local stage: the constant ambient radiosity (0 = the classic estimate)
  std::map<std::string, Rgb> reflectance;  // surface name -> reflectance override
  double lightScale = 1.0;                 // multiplies every emission
  // Display
  double exposure = 0.0;
  std::string toneMap = "linear";  // linear | reinhard
  bool gamma = true;
  bool smooth = false;
  bool edges = false;
  std::string refine = "adaptive";        // refine stage: uniform | adaptive | discontinuity | hierarchical
  std::optional<double> refineTolerance;  // adaptive: gradient tolerance; hierarchical: link tolerance
  std::string exportMatrix;  // matrix stage: file name (csv, mtx, npy, tex) written beside the figures
  std::string matrix = "F";  // matrix stage: the matrix shown, F, rhoF or K = I - rho F
  std::string from;          // the element or surface a hemicube/Nusselt/rays view is seen from
  std::string topic;         // exercise stage: the homework topic (src/homework/topic_table.h)
  // pathtrace stage: the images are small so that a step renders in seconds (the tracer is TBB-parallel)
  int paths = 256;       // path-traced samples per pixel
  int imageSize = 128;   // pixels along each side of the images
  int gatherRays = 64;   // final-gather rays per pixel of the two-pass image
  int clusterDepth = 3;  // scaling stage: the depth of the cluster tree whose boxes are drawn
  std::string scenes;    // scaling stage: scene files whose links against n are counted, comma-separated
  // radiometry stage: the patch seen from the point (metres, degrees)
  double patchDistance = 1.0;  // from the point to the patch's centre
  double patchTilt = 0.0;      // between the patch's normal and the line to the point
  double patchSize = 0.5;      // the side of the square patch (and of the square source)
  // raytrace stage: the Whitted tracer's settings (core/raytrace/whitted.h) and the pixel whose tree is drawn
  int rayDepth = 3;              // mirror reflections followed at most
  int shadowRays = 16;           // per light per hit (1: hard shadows)
  double rayEpsilon = 0.1;       // self-intersection offset, in the scene's units
  double lightSize = 1.0;        // the lights scaled about their centres, power kept
  double gloss = 0.0;            // mirrors' Phong exponent q for glossy reflection (0: ideal mirrors)
  int pixelSamples = 1;          // primary rays per pixel, jittered (antialiasing, and the lobe's average)
  double aperture = 0.0;         // the camera lens's radius, scene units (0: a pinhole, no depth of field)
  double focusDistance = 0.0;    // the lens's plane of focus along the view (0: the camera's target)
  int pixelX = 64, pixelY = 64;  // the pixel whose ray tree is drawn
  std::string mirrors;           // surfaces that reflect as mirrors, comma-separated
  std::string moving;            // surfaces that move while the shutter is open, comma-separated
  double motion = 0.0;           // how far they move then, along the scene's x axis (scene units)
  // reflection stage: the BRDF shown (core/brdf.h) and the direction light arrives from
  std::string brdfModel = "phong";
  double phongExponent = 16.0;    // q
  double specularFraction = 0.3;  // k_s / (k_d + k_s)
  double anisotropy = 1.0;        // Ward: alpha_x / alpha_y
  double incidenceAngle = 45.0;   // degrees from the normal
};

struct Step {
  int index = 0;  // 0-based position in the lesson
  int line = 0;   // line of the step's heading
  std::string title;
  std::string text;   // Markdown, may contain {{placeholders}}
  int textLine = 0;   // line where the text starts (for placeholder errors)
  std::string scene;  // relative to the scenes folder; empty for Text steps
  Stage stage = Stage::Text;
  StepParameters parameters;
  std::vector<View> views;
  CameraOverride camera;
  std::vector<std::string> highlights;  // surface names or element ids ("12")
  std::string figure;                   // base name of the step's figure files
  std::string caption;                  // the first figure's caption, may contain {{placeholders}}
  int captionLine = 0;
  std::optional<View> captionView;  // the view first listed, whose figure the caption is (a copy of the step
                                    // that shows fewer views keeps it)
  std::vector<std::string> controls;    // parameter keys the app may let the reader change
  std::map<std::string, Field> fields;  // every key as written, with its line (for late errors)
  // An exercise step's conceptual question: the choices of its ```question block (the step's text asks the
  // question), and the block's line.
  std::vector<homework::Choice> choices;
  int questionLine = 0;

  // File names (without folder) of the figures, one per view: "<figure>.png" for a single view,
  // "<figure>-<view>.png" otherwise.
  std::vector<std::string> figureFiles() const;
};

// The walkthrough view writes its figure file (the first frame) and every frame beside it, numbered from 1:
// "tour.png" -> "tour-0001.png", "tour-0002.png"...
std::string walkthroughFrameFile(const std::string& figureFile, int frame);

struct Lesson {
  std::string id;  // the file name without extension
  std::string file;
  std::string title;
  std::string chapter;
  int order = 0;
  std::string summary;
  std::string intro;  // Markdown between the header and the first step
  int introLine = 0;
  std::vector<Step> steps;
};

}  // namespace rt::lesson
