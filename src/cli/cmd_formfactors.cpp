// radiosity formfactors SCENE [--method NAME] [mesh options] [--resolution R] [--samples N] [--seed S]
//                            [--tolerance T]
//                            [--enforce-reciprocity] [--normalize-rows] [--output F.csv|F.mtx|F.npy|F.tex]
// Computes the form-factor matrix of a scene's mesh, prints one summary line and one diagnostics line.
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "core/formfactor/formfactor_method.h"
#include "core/io/matrix_export.h"

namespace rt::cli {
namespace {

struct FormFactorsArguments {
  std::string scene;
  std::string method = "analytic";
  MeshArguments mesh;
  FormFactorOptions options;
  bool enforceReciprocity = false;
  bool normalizeRows = false;
  bool quiet = false;
  std::string output;
};

void run(const FormFactorsArguments& a) {
  const Scene scene = loadSceneReportingWarnings(a.scene);
  const Mesh mesh = buildMesh(scene, a.mesh.options());
  const auto method = makeFormFactorMethod(a.method);
  FormFactorStats stats;
  ProgressLine progress(!a.quiet);
  FormFactorMatrix F = method->compute(mesh, a.options, progress, stats);
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
  std::cout << a.method << ": " << stats.summary() << "\n";
  std::cout << "diagnostics: " << diagnose(F, areas).summary() << repairs << "\n";
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
  command->add_option("--method", arguments->method, "Form-factor method: " + methods)->capture_default_str();
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
          "element; nusselt: segments per arc")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      ->add_option("--tolerance", arguments->options.tolerance,
                   "exact: relative tolerance of every entry (the cubature refines until its error estimate "
                   "is below it; occluded pairs take much longer at small values)")
      ->check(CLI::Range(1e-14, 0.5))
      ->capture_default_str();
  command->add_option("--seed", arguments->options.seed, "Seed of the stochastic methods")
      ->capture_default_str();
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
