// radiosity formfactors SCENE [--method NAME] [mesh options] [--resolution R] [--samples N] [--seed S]
//                            [--ff-tolerance T] [--ff-budget N]
//                            [--enforce-reciprocity] [--normalize-rows] [--output F.csv|F.mtx|F.npy|F.tex]
//                            [--compare-to REFERENCE.npy] [--explain I,J]
// Computes the form-factor matrix of a scene's mesh, prints one summary line and one diagnostics line, and
// with --compare-to one line of its error against a reference matrix saved earlier (e.g. by --method exact).
// With --explain I,J it computes one pair of the quadrature method instead and prints how.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/setting_options.h"
#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/quadrature/pair_explanation.h"
#include "core/input_error.h"
#include "core/io/matrix_export.h"
#include "core/io/matrix_import.h"

namespace rt::cli {
namespace {

struct FormFactorsArguments {
  std::string scene;
  std::string method = defaultFormFactorMethod();
  MeshArguments mesh;
  FormFactorOptions options;
  double budget = 0;  // --ff-budget: the table's number, options.workBudget once whole
  std::string sampling = "random";
  bool enforceReciprocity = false;
  bool normalizeRows = false;
  bool quiet = false;
  std::string output;
  std::string compareTo;
  std::vector<int> explain;  // I, J: one pair's way through the quadrature method, no matrix
};

// --explain I,J: the route the pair takes through the quadrature method's stages, what each found, F_ij.
void explainPair(const Mesh& mesh, const FormFactorsArguments& a) {
  if (a.method != "quadrature")
    throw CLI::ValidationError(
        "--explain", "it follows the quadrature method's stages; --method " + a.method + " has none to show");
  const int n = static_cast<int>(mesh.size());
  for (int k : a.explain)
    if (k < 0 || k >= n)
      throw CLI::ValidationError("--explain", "element " + std::to_string(k) + " is not in the mesh (0 to " +
                                                  std::to_string(n - 1) + ")");
  QuadratureExplainer explain(mesh, a.options.tolerance);
  std::cout << explain(a.explain[0], a.explain[1]).text();
}

void checkShape(const Eigen::MatrixXd& reference, Eigen::Index n, const std::string& path) {
  if (reference.rows() != n || reference.cols() != n)
    throw InputError({path, 0, {}}, "the reference is " + std::to_string(reference.rows()) + " x " +
                                        std::to_string(reference.cols()) + ", this mesh has " +
                                        std::to_string(n) + " elements (same scene and mesh options?)");
}

// One line: RMS and largest error of F against the reference, and the RMS error relative to the reference's
// RMS (the figure that says "F to 1 %").
void printComparison(const FormFactorMatrix& F, const Eigen::MatrixXd& reference, const std::string& path) {
  const Eigen::MatrixXd difference = F - reference;
  Eigen::Index row = 0, col = 0;
  const double largest = difference.cwiseAbs().maxCoeff(&row, &col);
  const double rms = std::sqrt(difference.squaredNorm() / static_cast<double>(difference.size()));
  const double norm = reference.norm();
  const double rowSums = (F.rowwise().sum() - reference.rowwise().sum()).cwiseAbs().maxCoeff();
  std::printf(
      "against %s: rms error %.3e, relative rms %.3g %%, max error %.3e at (%ld, %ld), max row-sum "
      "difference %.3e\n",
      path.c_str(), rms, norm > 0 ? 100 * difference.norm() / norm : 0.0, largest, static_cast<long>(row),
      static_cast<long>(col), rowSums);
}

void run(const FormFactorsArguments& a) {
  const Scene scene = loadSceneReportingWarnings(a.scene);
  const Mesh mesh = buildMesh(scene, a.mesh.options());
  if (!a.explain.empty()) return explainPair(mesh, a);
  const auto method = makeFormFactorMethod(a.method);
  // Read the reference first: a wrong path should not cost a whole computation.
  const Eigen::MatrixXd reference = a.compareTo.empty() ? Eigen::MatrixXd() : readNpyMatrix(a.compareTo);
  if (!a.compareTo.empty()) checkShape(reference, static_cast<Eigen::Index>(mesh.size()), a.compareTo);
  FormFactorStats stats;
  ProgressLine progress(!a.quiet);
  FormFactorOptions options = a.options;
  options.sampling = parseLineSampling(a.sampling).value_or(LineSampling::Random);
  options.workBudget = std::lround(a.budget);
  FormFactorMatrix F = method->compute(mesh, options, progress, stats);
  progress.finish();
  const Eigen::VectorXd areas = mesh.areas();
  std::string repairs;
  if (a.enforceReciprocity) {
    enforceReciprocity(F, areas);
    repairs += " (reciprocity enforced)";
  }
  if (a.normalizeRows) {
    normalizeRows(F);
    repairs += " (rows normalised)";
  }
  reportFormFactorStats(std::cout, a.method, stats);
  std::cout << "diagnostics: " << diagnose(F, areas).summary() << repairs << "\n";
  std::cout.flush();
  if (!a.compareTo.empty()) printComparison(F, reference, a.compareTo);
  if (!a.output.empty()) {
    writeMatrix(F, a.output);
    std::cout << "wrote " << a.output << " (" << F.rows() << " x " << F.cols() << ")\n";
  }
}

}  // namespace

void addFormFactorsCommand(CLI::App& app) {
  auto arguments = std::make_shared<FormFactorsArguments>();
  auto* command = app.add_subcommand("formfactors", "Compute the form-factor matrix of a scene");
  command->add_option("scene", arguments->scene, "Scene file (.json or .obj)")->required();
  std::string methods;
  for (const std::string& name : formFactorMethodNames()) methods += (methods.empty() ? "" : ", ") + name;
  addSettingOption(*command, "method", arguments->method)
      ->default_str(defaultFormFactorMethod())
      ->description("Form-factor method: " + methods);
  arguments->mesh.add(*command);
  command
      ->add_option("--resolution", arguments->options.hemicubeResolution,
                   "Hemicube resolution (top face edge)")
      ->check(CLI::Range(2, 8192))
      ->capture_default_str();
  command
      ->add_option(
          "--samples", arguments->options.samples,
          "raycast/analytic-visibility: sample pairs per element pair (1..1024); montecarlo: rays per "
          "element; nusselt: segments per arc; hybrid: rays per 1 % of an occluded pair's form factor")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  // --tolerance is the solver's in every other command; here it was the form factors' and still works.
  addDeprecatedAlias(*command, "--tolerance",
                     addSettingOption(*command, "ff-tolerance", arguments->options.tolerance));
  addSettingOption(*command, "ff-budget", arguments->budget);
  command
      ->add_option("--explain", arguments->explain,
                   "I,J: print the route the pair I -> J takes through the quadrature method's stages, the "
                   "occluders found and kept, the source's pieces and F_IJ (no matrix)")
      ->delimiter(',')
      ->expected(2);
  command->add_option(
      "--compare-to", arguments->compareTo,
      "Print the error against a reference matrix (.npy, e.g. written by --method exact --output)");
  command->add_option("--seed", arguments->options.seed, "Seed of the stochastic methods")
      ->capture_default_str();
  addSettingOption(*command, "sampling", arguments->sampling);
  command->add_option("--threads", arguments->options.threads, "Worker threads (0 = all cores)")
      ->check(CLI::NonNegativeNumber);
  command->add_flag(
      "--enforce-reciprocity", arguments->enforceReciprocity,
      "Opt-in repair: replace F_ij, F_ji by the area-weighted average that satisfies reciprocity");
  command->add_flag("--normalize-rows", arguments->normalizeRows,
                    "Opt-in repair: scale every row to sum to 1 (right only for closed scenes)");
  command->add_flag("--quiet", arguments->quiet, "No progress line");
  command->add_option("--output,-o", arguments->output, "Write F as .csv (17 digits), .mtx, .npy or .tex");
  command->callback([arguments] { run(*arguments); });
}

}  // namespace rt::cli
