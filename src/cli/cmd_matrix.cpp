// radiosity matrix: scene -> mesh -> F -> one of F, K, rho, E, B written as CSV / Matrix Market / .npy /
// LaTeX, with the numbers that say how hard the system is (spectral radius of rho F, condition number of K
// for small n).
#include <cstdio>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/setting_options.h"
#include "core/assembly.h"
#include "core/formfactor/formfactor_method.h"
#include "core/io/matrix_export.h"
#include "core/io/scene_loader.h"
#include "core/solvers/direct_solver.h"

namespace rt::cli {
namespace {

struct MatrixArguments {
  std::string scene;
  std::string formFactors = defaultFormFactorMethod();
  FormFactorOptions formFactorOptions;
  std::string output;
  std::string what = "K";
  std::string channel = "r";
  MeshArguments mesh;
};

void run(const MatrixArguments& a) {
  const Scene scene = loadSceneReportingWarnings(a.scene);
  if (a.what == "B") requireLight(scene);
  const Mesh mesh = buildMesh(scene, a.mesh.options());
  const MatrixFormat format = matrixFormatFromPath(a.output);  // fail before the expensive part
  const auto n = static_cast<int>(mesh.size());
  const bool square = a.what == "F" || a.what == "K";
  if (format == MatrixFormat::Latex && n > kMaxLatexSize) {  // before F is computed, not after
    throw InputError({a.output, 0, {}},
                     "LaTeX output is limited to " + std::to_string(kMaxLatexSize) + " x " +
                         std::to_string(kMaxLatexSize) + " matrices, this one is " + std::to_string(n) +
                         " x " + std::to_string(square ? n : 3) +
                         "; use .csv, .mtx or .npy instead (or a coarser mesh, e.g. --no-subdivide)");
  }
  ProgressLine progress;
  const FormFactorMatrix F = computeFormFactorsReporting(mesh, a.formFactors, a.formFactorOptions, progress);

  const RadiositySystem system = RadiositySystem::fromMesh(mesh, F);
  const int c = channelIndex(a.channel);
  const Eigen::VectorXd rho = system.reflectance.col(c);

  const SpectralRadiusEstimate radius = spectralRadius(F, rho);
  std::printf("elements: %d\n", n);
  std::printf("channel: %c\n", "rgb"[c]);
  std::printf("fill of F: %.4f (%s storage for K)\n", fillFraction(F),
              fillFraction(F) < kSparseFillThreshold ? "sparse" : "dense");
  std::printf("spectral radius of rho F: %.10g%s\n", radius.value,
              radius.converged ? "" : " (not converged)");
  if (static_cast<Eigen::Index>(n) <= kMaxConditionSize) {
    const auto cond = conditionNumber(assembleDense(F, rho));
    std::printf("condition number of K (2-norm): %.10g\n", *cond);
  } else {
    std::printf("condition number of K: not computed for n > %ld\n", static_cast<long>(kMaxConditionSize));
  }

  if (a.what == "F") {
    writeMatrix(F, a.output, format);
  } else if (a.what == "K") {
    writeMatrix(assembleDense(F, rho), a.output, format);
  } else if (a.what == "rho") {
    writeMatrix(system.reflectance, a.output, format);
  } else if (a.what == "E") {
    writeMatrix(system.emission, a.output, format);
  } else {
    RgbField B;
    const SolverStatus status = directSolve(system, B, {});
    if (status != SolverStatus::Success)
      throw std::runtime_error("the direct solve failed: " + toString(status));
    writeMatrix(B, a.output, format);
  }
  std::cerr << a.what << " written to " << a.output << "\n";
}

}  // namespace

void addMatrixCommand(CLI::App& app) {
  auto a = std::make_shared<MatrixArguments>();
  auto* command = app.add_subcommand(
      "matrix",
      "Export F, K = I - diag(rho) F, rho, E or B (csv, mtx, npy, tex); print spectral radius and condition");
  command->add_option("scene", a->scene, "Scene file (.json or .obj)")->required()->check(CLI::ExistingFile);
  a->mesh.add(*command);
  addDeprecatedAlias(
      *command, "--formfactors",
      addSettingOption(*command, "method", a->formFactors)->default_str(defaultFormFactorMethod()));
  command
      ->add_option(
          "--output", a->output,
          "Output file; the extension picks the format: .csv (17 digits), .mtx (Matrix Market), .npy, "
          ".tex (n <= 20)")
      ->required();
  command->add_option("--what", a->what, "F, K (one channel), rho or E (n x 3), B (n x 3, direct solution)")
      ->capture_default_str()
      ->check(CLI::IsMember({"F", "K", "rho", "E", "B"}));
  addSettingOption(*command, "resolution", a->formFactorOptions.hemicubeResolution);
  addSettingOption(*command, "samples", a->formFactorOptions.samples);
  addSettingOption(*command, "ff-tolerance", a->formFactorOptions.tolerance);
  addSettingOption(*command, "seed", a->formFactorOptions.seed);
  command->add_option("--channel", a->channel, "Colour channel of K and of the spectral radius: r, g or b")
      ->capture_default_str();
  command->callback([a] { run(*a); });
}

}  // namespace rt::cli
