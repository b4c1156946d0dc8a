#include "lesson/step_keys.h"

#include <algorithm>
#include <limits>
#include <sstream>

#include "core/basis/linear_basis.h"
#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/line_sampling.h"
#include "core/io/scene_assembly.h"
#include "core/mesh.h"
#include "homework/topic_table.h"
#include "lesson/lesson_parser.h"
#include "lesson/step_keys_chapters.h"
#include "lesson/value_parsing.h"

namespace rt::lesson {
namespace {

using P = StepParameters;

const std::vector<std::string>& toneMaps() {
  static const std::vector<std::string> values{"linear", "reinhard"};
  return values;
}
const std::vector<std::string>& refineModes() {
  static const std::vector<std::string> values{"uniform", "adaptive", "discontinuity", "hierarchical"};
  return values;
}
const std::vector<std::string>& homeworkTopics() {
  static const std::vector<std::string> values = homework::topicIds();
  return values;
}
const std::vector<std::string>& matrixKinds() {
  static const std::vector<std::string> values{"F", "rhoF", "K"};
  return values;
}

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// One row per key. Order: what the step is, what it computes with, how it solves, how it is shown.
std::vector<StepKey> makeTable() {
  const std::vector<Stage> computeF{Stage::FormFactors, Stage::Hemicube, Stage::Nusselt,    Stage::Rays,
                                    Stage::Exact,       Stage::Matrix,   Stage::Solve,      Stage::Compare,
                                    Stage::Bounces,     Stage::Local,    Stage::Benchmark,  Stage::PathTrace,
                                    Stage::Scaling,     Stage::RayTrace, Stage::Reflection, Stage::Sampling,
                                    Stage::Elements};
  const std::vector<Stage> solving{Stage::Solve,      Stage::Compare,   Stage::Matrix,  Stage::Local,
                                   Stage::Exact,      Stage::PathTrace, Stage::Scaling, Stage::RayTrace,
                                   Stage::Reflection, Stage::Sampling,  Stage::Elements};
  const std::vector<Stage> seen{Stage::FormFactors, Stage::Hemicube, Stage::Nusselt, Stage::Rays,
                                Stage::Exact};
  std::vector<StepKey> t;
  auto add = [&t](StepKey k) -> StepKey& { return t.emplace_back(std::move(k)); };
  add({"scene", KeyType::Text, 0, 0, nullptr, "", "Scene", "The scene file, relative to scenes/."});
  add({"stage", KeyType::Text, 0, 0, nullptr, "", "Stage",
       "What the step computes (see the table of stages below)."});
  add({.name = "method",
       .type = KeyType::Choice,
       .choices = &knownMethods,
       .defaultText = defaultFormFactorMethod(),
       .label = "Form factors",
       .tooltip =
           "The form-factor method. Stages named after a method (hemicube, nusselt, rays) use theirs "
           "unless the step names another. analytic-visibility is biased where a shadow edge crosses a "
           "pair; analytic and nusselt ignore occluders.",
       .control = true,
       .stages = computeF,
       .slot = &P::method});
  add({.name = "methods",
       .type = KeyType::Choices,
       .choices = &knownMethods,
       .label = "Methods",
       .tooltip = "Several form-factor methods to compare, measure or benchmark.",
       .stages = {Stage::Compare, Stage::Exact, Stage::Benchmark},
       .slot = &P::methods});
  add({.name = "reference",
       .type = KeyType::Choice,
       .choices = &knownMethods,
       .label = "Reference",
       .tooltip = "The method errors are measured against (rays: the form factors the local lines' hit "
                  "fractions are compared with).",
       .stages = {Stage::Exact, Stage::Benchmark, Stage::Rays},
       .slot = &P::reference});
  add({.name = "resolution",
       .type = KeyType::Int,
       .min = 2,
       .max = 4096,
       .defaultText = "128",
       .label = "Hemicube resolution",
       .tooltip = "Hemicube: pixels along the edge of the top face.",
       .control = true,
       .step = 8,
       .stages = computeF,
       .slot = &P::resolution});
  add({.name = "samples",
       .type = KeyType::Int,
       .min = 1,
       .max = 1000000,
       .defaultText = "16",
       .label = "Samples",
       .tooltip = "The sampling methods' accuracy knob: ray casting, sample pairs per element pair; Monte "
                  "Carlo, rays per element; hybrid, rays per 1 % of an occluded pair's form factor; analytic "
                  "with visibility, rays per pair; Nusselt analog, segments per arc.",
       .control = true,
       .stages = computeF,
       .slot = &P::samples});
  // Not "tolerance": that is the solver's, and a solve names both.
  add({.name = "ff-tolerance",
       .type = KeyType::Double,
       .min = 0,
       .max = 0.5,
       .defaultText = "0",
       .label = "Form-factor tolerance",
       .tooltip = "The tolerance methods' accuracy knob: quadrature, the absolute error allowed in each form "
                  "factor; exact, the relative tolerance of each. Smaller costs more (1e-3 is far cheaper "
                  "than 1e-6). 0 is the method's own: quadrature 1e-5, exact 1e-9.",
       .control = true,
       .logScale = true,
       .zeroText = "the method's own",
       .stages = computeF,
       .slot = &P::formFactorTolerance});
  add({.name = "ff-budget",
       .type = KeyType::Double,
       .min = 0,
       .max = 1e15,
       .defaultText = "0",
       .label = "Form-factor work budget",
       .tooltip =
           "The exact method's work budget: the most point evaluations the whole matrix may take; past "
           "it the computation stops with a message naming the budget, instead of running on for "
           "hours. 0: no limit.",
       .control = true,
       .logScale = true,
       .zeroText = "no limit",
       .stages = computeF,
       .slot = &P::formFactorBudget});
  add({.name = "seed",
       .type = KeyType::Int,
       .min = 0,
       .max = 2000000000,
       .defaultText = "1",
       .label = "Seed",
       .tooltip = "Random seed of the stochastic methods and solvers, and of an exercise's numbers: the same "
                  "seed gives the same numbers.",
       .control = true,
       .slot = &P::seed});
  add({.name = "subdivide",
       .type = KeyType::Int,
       .min = 1,
       .max = 64,
       .defaultText = "1",
       .label = "Subdivision (N x N)",
       .tooltip = "Split every patch into N x N elements.",
       .control = true,
       .slot = &P::subdivide});
  add({.name = "max-edge",
       .type = KeyType::Double,
       .min = 1e-9,
       .max = 1e9,
       .label = "Max edge",
       .tooltip = "Split patches until no element edge is longer than this (scene units); or give subdivide.",
       .control = true,
       .logScale = true,
       .slot = &P::maxEdge});
  add({.name = "split-at-contacts",
       .type = KeyType::Bool,
       .defaultText = "false",
       .label = "Split at contacts",
       .tooltip =
           "With subdivide or max-edge: first cut every patch along the lines where other surfaces stand "
           "on it, so that no element straddles a block's footprint (an element partly under a block "
           "sends part of its light into the block, where it is lost).",
       .control = true,
       .slot = &P::splitAtContacts});
  add({.name = "overlap-gap",
       .type = KeyType::Double,
       .min = 0,
       .max = 1,
       .defaultText = io_detail::formatNumber(MeshOptions{}.overlapGap),
       .label = "Overlap gap",
       .tooltip =
           "With the cuts at contacts (and in the mesh chosen for a scene without mesh options): also "
           "cut every patch along the outline of a parallel patch lying in front of it within this gap, "
           "as a fraction of the scene's diagonal (a light hung just below a ceiling, a picture on a "
           "wall), so that no element is partly covered; 0: no such cut.",
       .decimals = 3,
       .step = 0.005,
       .slot = &P::overlapGap});
  add({.name = "subdivisions",
       .type = KeyType::Ints,
       .min = 1,
       .max = 64,
       .label = "Subdivisions",
       .tooltip = "Several subdivision levels to compare (scaling: the meshes whose cost is measured).",
       .stages = {Stage::Compare, Stage::Scaling, Stage::Elements},
       .slot = &P::subdivisions});
  add({.name = "scenes",
       .type = KeyType::Text,
       .label = "Scenes",
       .tooltip =
           "Scaling stage: scene files (relative to scenes/, comma-separated), each meshed as the step's own "
           "scene (without mesh keys, one element per polygon), solved by hierarchical-clustering and its "
           "links counted; the links chart "
           "draws the links against n, one series per scene name (the files of one scene at several sizes "
           "share it).",
       .stages = {Stage::Scaling},
       .slot = &P::scenes});
  add({.name = "sweep",
       .type = KeyType::Ints,
       .min = 1,
       .max = 1000000,
       .label = "Sweep",
       .tooltip =
           "The values of each method's accuracy knob a benchmark tries (a resolution or a count; for "
           "a tolerance, the digits d of 10^-d); scaling: the rays per element local lines is run with; "
           "sampling: the rays per iteration of each run.",
       .stages = {Stage::Benchmark, Stage::Scaling, Stage::Sampling},
       .slot = &P::sweep});
  add({.name = "solver",
       .type = KeyType::Choice,
       .choices = &knownSolvers,
       .defaultText = "gauss-seidel",
       .label = "Solver",
       .tooltip = "How B = E + rho F B is solved.",
       .control = true,
       .stages = solving,
       .slot = &P::solver});
  add({.name = "basis",
       .type = KeyType::Choice,
       .choices = &basisNames,
       .defaultText = "constant",
       .label = "Basis",
       .tooltip =
           "What B is between the nodes: constant, one value per element (B_i = E_i + rho_i sum_j F_ij "
           "B_j); linear, one value per vertex of a patch, interpolated across each element and drawn "
           "as it is (collocation at the vertices, kernel integrals by quadrature; solvers direct, jacobi, "
           "gauss-seidel, southwell, progressive, bounces).",
       .control = true,
       .stages = {Stage::Solve},
       .slot = &P::basis});
  add({.name = "solvers",
       .type = KeyType::Choices,
       .choices = &knownSolvers,
       .label = "Solvers",
       .tooltip = "Several solvers to compare.",
       .stages = {Stage::Compare},
       .slot = &P::solvers});
  add({.name = "iterations",
       .type = KeyType::Int,
       .min = 0,
       .max = 1000000,
       .defaultText = "0",
       .label = "Max iterations",
       .tooltip =
           "Iterations (sweeps, shots or rounds) after which a solver stops unconverged. 0 is automatic: "
           "1000 sweeps or rounds; shooting, 100 shots per element.",
       .control = true,
       .step = 1,
       .zeroText = "automatic",
       .stages = solving,
       .slot = &P::iterations});
  add({.name = "tolerance",
       .type = KeyType::Double,
       .min = 1e-15,
       .max = 0.5,
       .defaultText = "1e-6",
       .label = "Tolerance",
       .tooltip = "A solver stops when the relative residual falls below this.",
       .control = true,
       .logScale = true,
       .stages = solving,
       .slot = &P::tolerance});
  add({.name = "relaxation",
       .type = KeyType::Double,
       .min = 0.05,
       .max = 1.99,
       .defaultText = "1",
       .label = "Relaxation",
       .tooltip = "Over-relaxation factor of the Gauss-Seidel sweeps (1: none; above 1: SOR; below 1: "
                  "under-relaxation). Jacobi ignores it.",
       .control = true,
       .decimals = 2,
       .step = 0.05,
       .stages = solving,
       .slot = &P::relaxation});
  add({.name = "rays-per-iteration",
       .type = KeyType::Int,
       .min = 0,
       .max = 2000000000,
       .defaultText = "0",
       .label = "Rays per iteration",
       .tooltip = "Stochastic solvers: the rays (or walks) of the first iteration; later ones get fewer, in "
                  "proportion to the power left to shoot. Noise falls like 1/sqrt(rays). 0 is automatic: 100 "
                  "per element (stochastic-jacobi, random-walk) or 1000 (local-lines).",
       .control = true,
       .step = 100000,
       .zeroText = "automatic",
       .stages = solving,
       .slot = &P::raysPerIteration});
  add({.name = "sampling",
       .type = KeyType::Choice,
       .choices = &lineSamplingNames,
       .defaultText = "random",
       .label = "Line sampling",
       .tooltip = "How local lines draw their origins and directions (the montecarlo method; the local-lines "
                  "solvers, which also draw each line's source): random, pseudo-random numbers; sobol, the "
                  "points of a scrambled Sobol sequence, spread more evenly, so the error falls faster than "
                  "1/sqrt(rays).",
       .control = true,
       .stages = computeF,
       .slot = &P::sampling});
  add({.name = "control-variate",
       .type = KeyType::Bool,
       .defaultText = "false",
       .label = "Control variate",
       .tooltip =
           "local-lines solvers: shoot B - beta instead of B, beta the area-weighted median radiosity, "
           "and add back the known part beta times each element's row sum (estimated once by "
           "lines); less power shot, less noise.",
       .control = true,
       .stages = solving,
       .slot = &P::controlVariate});
  add({.name = "cluster-tolerance",
       .type = KeyType::Double,
       .min = 0,
       .max = 10,
       .defaultText = "0",
       .label = "Cluster tolerance",
       .tooltip =
           "hierarchical-clustering: a link between two clusters (or elements) is kept when the light it "
           "could miss is at most this fraction of the scene's mean radiosity; smaller gives more links "
           "and less error. 0 is automatic: 0.05.",
       .control = true,
       .decimals = 3,
       .step = 0.01,
       .zeroText = "automatic",
       .stages = solving,
       .slot = &P::clusterTolerance});
  add({.name = "ambient",
       .type = KeyType::Bool,
       .defaultText = "false",
       .label = "Ambient term",
       .tooltip = "Progressive refinement: show the unshot light as a constant ambient term.",
       .control = true,
       .stages = solving,
       .slot = &P::ambient});
  add({.name = "bounces",
       .type = KeyType::Int,
       .min = 0,
       .max = 1000,
       .defaultText = "6",
       .label = "Bounces",
       .tooltip = "Bounces stage: how many bounces of light (terms of the Neumann series) to add up.",
       .control = true,
       .stages = {Stage::Bounces},
       .slot = &P::bounces});
  add({.name = "ambient-light",
       .type = KeyType::Double,
       .min = 0,
       .max = 1e9,
       .defaultText = "0",
       .label = "Ambient light",
       .tooltip = "Local and reflection stages: the constant ambient radiosity in W/m^2 (0: the classic "
                  "estimate).",
       .control = true,
       .decimals = 2,
       .step = 0.5,
       .stages = {Stage::Local, Stage::Reflection},
       .slot = &P::ambientLight});
  add({.name = "paths",
       .type = KeyType::Int,
       .min = 4,
       .max = 1000000,
       .defaultText = "256",
       .label = "Paths per pixel",
       .tooltip =
           "Pathtrace and raytrace stages: paths traced per pixel of the path-traced images. Their "
           "noise falls like 1/sqrt(paths); the noise chart measures it at 1/64, 1/16 and 1/4 of them.",
       .control = true,
       .step = 64,
       .stages = {Stage::PathTrace, Stage::RayTrace},
       .slot = &P::paths});
  add({.name = "image-size",
       .type = KeyType::Int,
       .min = 16,
       .max = 2048,
       .defaultText = "128",
       .label = "Image size (pixels)",
       .tooltip = "Pathtrace and raytrace stages: pixels along each side of the traced and radiosity images.",
       .control = true,
       .step = 16,
       .stages = {Stage::PathTrace, Stage::RayTrace},
       .slot = &P::imageSize});
  add({.name = "gather-rays",
       .type = KeyType::Int,
       .min = 4,
       .max = 65536,
       .defaultText = "64",
       .label = "Gather rays",
       .tooltip = "Pathtrace stage: final-gather rays per pixel of the two-pass image (direct light is "
                  "computed at the point itself, the gather reads one bounce from the radiosity solution).",
       .control = true,
       .step = 16,
       .stages = {Stage::PathTrace},
       .slot = &P::gatherRays});
  add({.name = "cluster-depth",
       .type = KeyType::Int,
       .min = 0,
       .max = 30,
       .defaultText = "3",
       .label = "Cluster depth",
       .tooltip = "Scaling stage: the depth of the cluster tree whose boxes are drawn (0: the root, one box "
                  "round the scene; each level doubles the boxes).",
       .control = true,
       .stages = {Stage::Scaling},
       .slot = &P::clusterDepth});
  addChapterKeys(t);  // step_keys_chapters.cpp: the keys of the light, reflection and ray-tracing stages
  add({.name = "light-scale",
       .type = KeyType::Double,
       .min = 0,
       .max = 1e9,
       .defaultText = "1",
       .label = "Light intensity",
       .tooltip = "Multiplies every emission.",
       .control = true,
       .decimals = 2,
       .step = 0.25,
       .slot = &P::lightScale});
  add({.name = "reflectance",
       .type = KeyType::Rgb,
       .min = 0,
       .max = 0.999999,
       .label = "Reflectance (r g b)",
       .tooltip = "reflectance.<surface>: the surface's reflectance, one number (grey) or three (r g b), "
                  "each in [0, 1). `controls: reflectance` offers every surface.",
       .control = true,
       .decimals = 3,
       .step = 0.05});
  add({.name = "refine",
       .type = KeyType::Choice,
       .choices = &refineModes,
       .defaultText = "adaptive",
       .label = "Refinement",
       .tooltip = "Refine stage: how the mesh follows the light.",
       .control = true,
       .stages = {Stage::Refine},
       .slot = &P::refine});
  add({.name = "refine-tolerance",
       .type = KeyType::Double,
       .min = 1e-6,
       .max = 10,
       .label = "Refine tolerance",
       .tooltip =
           "Adaptive: the radiosity gradient that splits an element; hierarchical: the link tolerance.",
       .control = true,
       .logScale = true,
       .stages = {Stage::Refine},
       .slot = &P::refineTolerance});
  add({.name = "matrix",
       .type = KeyType::Choice,
       .choices = &matrixKinds,
       .defaultText = "F",
       .label = "Matrix shown",
       .tooltip = "Matrix stage: the matrix the matrix view shows, F, rho F or K = I - rho F.",
       .control = true,
       .stages = {Stage::Matrix},
       .slot = &P::matrix});
  add({.name = "export",
       .type = KeyType::Text,
       .label = "Export",
       .tooltip = "Matrix stage: a file name ending in .csv, .mtx, .npy or .tex, written beside the figures.",
       .stages = {Stage::Matrix},
       .slot = &P::exportMatrix});
  add({.name = "from",
       .type = KeyType::Text,
       .label = "Seen from",
       .tooltip = "The element (a number) or surface whose hemicube, disk, rays or form-factor row is shown.",
       .control = true,
       .stages = seen,
       .slot = &P::from});
  add({.name = "topic",
       .type = KeyType::Choice,
       .choices = &homeworkTopics,
       .label = "Exercise",
       .tooltip = "The homework topic an exercise step draws its question from (docs/homework.md).",
       .stages = {Stage::Exercise},
       .slot = &P::topic});
  add({.name = "exposure",
       .type = KeyType::Double,
       .min = 0,
       .max = 1e9,
       .defaultText = "0",
       .label = "Exposure",
       .tooltip = "Multiplies B before the tone map (0: automatic).",
       .control = true,
       .decimals = 3,
       .step = 0.01,
       .slot = &P::exposure});
  add({.name = "tone-map",
       .type = KeyType::Choice,
       .choices = &toneMaps,
       .defaultText = "linear",
       .label = "Tone map",
       .tooltip = "linear (clamped) or reinhard x / (1 + x).",
       .control = true,
       .slot = &P::toneMap});
  add({.name = "gamma",
       .type = KeyType::Bool,
       .defaultText = "true",
       .label = "sRGB gamma",
       .tooltip = "Encode the displayed values with the sRGB transfer curve.",
       .control = true,
       .slot = &P::gamma});
  add({.name = "smooth",
       .type = KeyType::Bool,
       .defaultText = "false",
       .label = "Smooth shading",
       .tooltip = "Interpolate radiosity at the vertices (Gouraud) instead of flat elements.",
       .control = true,
       .slot = &P::smooth});
  add({.name = "edges",
       .type = KeyType::Bool,
       .defaultText = "false",
       .label = "Mesh edges",
       .tooltip = "Draw the elements' edges.",
       .control = true,
       .slot = &P::edges});
  add({"views", KeyType::Text, 0, 0, nullptr, "", "Views", "The figures the step shows, comma-separated."});
  add({"camera.position", KeyType::Vec3, 0, 0, nullptr, "", "Camera position", "x y z of the eye."});
  add({"camera.target", KeyType::Vec3, 0, 0, nullptr, "", "Camera target", "x y z looked at."});
  add({"camera.up", KeyType::Vec3, 0, 0, nullptr, "", "Camera up", "x y z of the up direction."});
  add({"camera.fov", KeyType::Double, 1, 170, nullptr, "", "Field of view",
       "Vertical field of view, degrees."});
  add({"camera", KeyType::Text, 0, 0, nullptr, "", "Camera",
       "A camera the scene names (JSON cameras, OBJ '# camera NAME:' comments); the camera.* keys adjust "
       "it."});
  add({"camera-path", KeyType::Text, 0, 0, nullptr, "", "Camera path",
       "Two or more cameras the scene names: the app flies through them after one solve (the solution does "
       "not depend on the view), and the walkthrough view writes the flight as numbered frames."});
  add({"path-frames", KeyType::Int, 2, 10000, nullptr, "48", "Frames",
       "The frames of the camera path, the first and last on its first and last camera."});
  add({"highlight", KeyType::Text, 0, 0, nullptr, "", "Highlight",
       "Surfaces or element numbers to outline."});
  add({"figure", KeyType::Text, 0, 0, nullptr, "", "Figure",
       "Base name of the step's figure files (a-z, 0-9, '-')."});
  add({"caption", KeyType::Text, 0, 0, nullptr, "", "Caption",
       "The caption of the step's first figure in the book and the figures tab: what the reader should see "
       "in it, with {{placeholders}} for its numbers. Without it the view's own title is the caption."});
  add({"controls", KeyType::Text, 0, 0, nullptr, "", "Controls",
       "The keys of this table marked as controls that the app lets the reader change on this step."});
  return t;
}

template <class T>
std::string listText(const std::vector<T>& values) {
  std::ostringstream out;
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << values[i];
  return out.str();
}

}  // namespace

bool StepKey::acceptedBy(Stage stage) const {
  if (stages.empty()) return stage != Stage::Text || name == "stage";
  return std::find(stages.begin(), stages.end(), stage) != stages.end();
}

const std::vector<StepKey>& stepKeyTable() {
  static const std::vector<StepKey> table = makeTable();
  return table;
}

const StepKey* findStepKey(const std::string& name) {
  const std::string row = name.rfind("reflectance.", 0) == 0 && name.size() > 12 ? "reflectance" : name;
  for (const StepKey& k : stepKeyTable())
    if (k.name == row) return &k;
  return nullptr;
}

void applyStepValue(StepParameters& p, const StepKey& key, const std::string& name, const std::string& value,
                    const SourceLocation& where) {
  auto choice = [&](const std::string& v) {
    const auto known = key.allowed();
    const bool isMethod = key.choices == &knownMethods, isSolver = key.choices == &knownSolvers;
    const std::string what = isMethod ? "form-factor method" : isSolver ? "solver" : key.name;
    if (std::find(known.begin(), known.end(), v) == known.end())
      throw InputError(where, "unknown " + what + " '" + v + "' (known: " + joinedNames(known) + ")");
    return v;
  };
  if (key.name == "reflectance") {
    if (name.size() <= 12) throw InputError(where, "reflectance takes a surface: reflectance.<surface>");
    p.reflectance[name.substr(12)] = parseRgb(value, where, name, key.min, key.max);
    return;
  }
  // A key's bounds are doubles (ff-budget's reaches 1e15); only integer slots read them as ints, clamped.
  const auto asIntBound = [](double v) {
    return static_cast<int>(
        std::clamp(v, double(std::numeric_limits<int>::min()), double(std::numeric_limits<int>::max())));
  };
  const int lo = asIntBound(key.min), hi = asIntBound(key.max);
  std::visit(
      [&](auto slot) {
        using S = decltype(slot);
        if constexpr (std::is_same_v<S, std::monostate>) {
          throw InputError(where, "'" + key.name + "' is not a parameter");
        } else if constexpr (std::is_same_v<S, std::optional<int> P::*> || std::is_same_v<S, int P::*>) {
          p.*slot = parseInt(value, where, key.name, lo, hi);
        } else if constexpr (std::is_same_v<S, std::optional<std::uint64_t> P::*>) {
          p.*slot = static_cast<std::uint64_t>(parseInt(value, where, key.name, lo, hi));
        } else if constexpr (std::is_same_v<S, std::optional<double> P::*> ||
                             std::is_same_v<S, double P::*>) {
          p.*slot = parseDouble(value, where, key.name, key.min, key.max);
        } else if constexpr (std::is_same_v<S, bool P::*>) {
          p.*slot = parseBool(value, where, key.name);
        } else if constexpr (std::is_same_v<S, std::string P::*>) {
          p.*slot = key.type == KeyType::Choice ? choice(value) : value;
        } else if constexpr (std::is_same_v<S, std::vector<std::string> P::*>) {
          auto list = parseList(value);
          for (const auto& v : list) choice(v);
          p.*slot = list;
        } else if constexpr (std::is_same_v<S, std::vector<int> P::*>) {
          p.*slot = parseIntList(value, where, key.name, lo, hi);
        }
      },
      key.slot);
}

std::optional<std::string> stepValueText(const StepParameters& p, const StepKey& key,
                                         const std::string& name) {
  if (key.name == "reflectance") {
    auto it = p.reflectance.find(name.size() > 12 ? name.substr(12) : "");
    if (it == p.reflectance.end()) return std::nullopt;
    return number(it->second[0]) + " " + number(it->second[1]) + " " + number(it->second[2]);
  }
  return std::visit(
      [&](auto slot) -> std::optional<std::string> {
        using S = decltype(slot);
        if constexpr (std::is_same_v<S, std::monostate>) {
          return std::nullopt;
        } else if constexpr (std::is_same_v<S, std::optional<int> P::*> ||
                             std::is_same_v<S, std::optional<double> P::*> ||
                             std::is_same_v<S, std::optional<std::uint64_t> P::*>) {
          if (!(p.*slot)) return std::nullopt;
          return number(static_cast<double>(*(p.*slot)));
        } else if constexpr (std::is_same_v<S, int P::*> || std::is_same_v<S, double P::*>) {
          return number(static_cast<double>(p.*slot));
        } else if constexpr (std::is_same_v<S, bool P::*>) {
          return std::string(p.*slot ? "true" : "false");
        } else if constexpr (std::is_same_v<S, std::string P::*>) {
          if ((p.*slot).empty()) return std::nullopt;
          return p.*slot;
        } else {
          if ((p.*slot).empty()) return std::nullopt;
          return listText(p.*slot);
        }
      },
      key.slot);
}

std::string stepKeyTableMarkdown() {
  std::ostringstream out;
  out << "| key | value | default | control | stages | meaning |\n|---|---|---|---|---|---|\n";
  for (const StepKey& k : stepKeyTable()) {
    std::string value;
    switch (k.type) {
      case KeyType::Int:
        value = "whole number in [" + number(k.min) + ", " + number(k.max) + "]";
        break;
      case KeyType::Double:
        value = "number in [" + number(k.min) + ", " + number(k.max) + "]";
        break;
      case KeyType::Bool:
        value = "true or false";
        break;
      case KeyType::Choice:
        value = "one of " + joinedNames(k.allowed());
        break;
      case KeyType::Choices:
        value = "list of " + joinedNames(k.allowed());
        break;
      case KeyType::Ints:
        value = "list of whole numbers in [" + number(k.min) + ", " + number(k.max) + "]";
        break;
      case KeyType::Rgb:
        value = "r g b (or one grey value) in [0, 1)";
        break;
      case KeyType::Vec3:
        value = "x y z";
        break;
      case KeyType::Text:
        value = "text";
        break;
    }
    std::vector<std::string> stages;
    for (Stage s : k.stages) stages.push_back(toString(s));
    const std::string name = k.name == "reflectance" ? "reflectance.<surface>" : k.name;
    out << "| `" << name << "` | " << value << " | " << (k.defaultText.empty() ? "-" : k.defaultText) << " | "
        << (k.control ? "yes" : "") << " | " << (stages.empty() ? "all" : joinedNames(stages)) << " | "
        << k.tooltip << " |\n";
  }
  return out.str();
}

}  // namespace rt::lesson
