// radiosity figure: every view of the visualisation layer, headless, as PNG (all views), SVG/PDF (true
// vectors for the 2D views; 3D views embed a high-resolution raster). The command computes what the view
// needs through core.
#include <iostream>
#include <memory>
#include <stdexcept>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/setting_options.h"
#include "core/formfactor/formfactor_method.h"
#include "core/refine/refine.h"
#include "viz/figure_request.h"
#ifdef RT_HAVE_VIZ
#include "viz/figure_driver.h"
#endif

namespace rt::cli {
namespace {

struct FigureArguments {
  std::string scene;
  MeshArguments mesh;
  CameraArgument camera;
  std::string channel = "g";  // r, g or b
  viz::FigureRequest request;
  FigureArguments() { request.formFactors = defaultFormFactorMethod(); }
};

#ifdef RT_HAVE_VIZ
void run(FigureArguments& arguments, const CLI::App& command) {
  viz::FigureRequest& a = arguments.request;
  // What the reader gave: each view picks a telling default for the rest.
  a.solverGiven = command.count("--solver") > 0;
  a.iterationsGiven = command.count("--iterations") > 0;
  a.referenceGiven = command.count("--reference-formfactors") > 0;
  a.resolutionGiven = command.count("--resolution") > 0;
  a.samplesGiven = command.count("--samples") > 0;
  a.colourGiven = command.count("--colour") > 0;
  a.channel = channelIndex(arguments.channel);
  a.note = [](const std::string& line) { std::cerr << line << "\n"; };
  ProgressLine progress;
  a.progress = &progress;
  if (!a.input.empty()) {
    viz::drawTimingTableFigure(a);
  } else {
    Scene scene = loadSceneReportingWarnings(arguments.scene);
    arguments.camera.applyTo(scene);
    viz::drawFigure(scene, arguments.mesh.options(), a);
  }
  progress.finish();
  std::cerr << "figure written to " << a.output << "\n";
}
#endif

}  // namespace

void addFigureCommand(CLI::App& app) {
  auto a = std::make_shared<FigureArguments>();
  auto* command =
      app.add_subcommand("figure", "Render a view of a scene or of its numbers to PNG, SVG or PDF");
  command->add_option("scene", a->scene, "Scene file (.json or .obj)")->required()->check(CLI::ExistingFile);
  command
      ->add_option("--view", a->request.view,
                   "scene, formfactor, hemicube, nusselt, rays, matrix, convergence, runtime-error, energy, "
                   "visibility, links, discontinuity")
      ->capture_default_str()
      ->check(CLI::IsMember(viz::figureViewNames()));
  command->add_option("--output", a->request.output, "Figure file: .png, .svg or .pdf")->required();
  command->add_option("--width", a->request.width, "Width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 16384));
  command->add_option("--height", a->request.height, "Height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 16384));
  command->add_option("--dpi", a->request.dpi, "Scales fonts and lines (dpi/96); PDF page size")
      ->capture_default_str()
      ->check(CLI::Range(24.0, 1200.0));
  a->mesh.add(*command);
  a->camera.add(*command);
  addDeprecatedAlias(
      *command, "--formfactors",
      addSettingOption(*command, "method", a->request.formFactors)->default_str(defaultFormFactorMethod()));
  command->add_option(
      "--reference-formfactors", a->request.referenceFormFactors,
      "formfactor/matrix: show the difference to this method; scene --colour error: the reference");
  addSettingOption(*command, "solver", a->request.solver)->default_str("chosen by the scene's size");
  command
      ->add_option("--solvers", a->request.solvers,
                   "convergence, runtime-error: solvers to compare (comma-separated)")
      ->delimiter(',');
  addDeprecatedAlias(
      *command, "--max-iterations",
      addSettingOption(*command, "iterations", a->request.maxIterations)->default_str("the view's own"));
  addSettingOption(*command, "resolution", a->request.resolution);
  addSettingOption(*command, "ff-tolerance", a->request.formFactorTolerance);
  command->add_option("--samples", a->request.samples, "Ray samples (rays view, ray-cast methods)")
      ->capture_default_str();
  command
      ->add_option("--colour", a->request.colour,
                   "scene: radiosity, reflectance, emission, element, unshot, error; hemicube: items, delta")
      ->capture_default_str();
  command
      ->add_option("--error", a->request.errorMeasure,
                   "scene --colour error: relative (|B - B_ref| / B_ref), absolute (W/m^2) or brightest "
                   "(|B - B_ref| / the brightest reflecting B_ref)")
      ->capture_default_str()
      ->check(CLI::IsMember({"relative", "absolute", "brightest"}));
  addSettingOption(*command, "tone-map", a->request.toneMap);
  command->add_option("--exposure", a->request.exposure, "Exposure multiplier (0 = automatic)")
      ->capture_default_str();
  command->add_flag("--smooth", a->request.smooth, "Per-vertex interpolated shading");
  command->add_flag("--edges", a->request.edges, "Show mesh edges");
  command->add_flag("--no-gamma", a->request.noGamma, "Skip the sRGB encoding");
  command->add_flag("--log", a->request.logScale, "Log colour scale");
  command->add_flag("--no-colour-bar", a->request.noColourBar, "Hide the colour bar of scalar views");
  command->add_option("--colour-map", a->request.colourMap, "viridis, cividis or grey")
      ->capture_default_str();
  command->add_option("--element", a->request.element, "The element the view is about (default: chosen)");
  command->add_option("--target", a->request.target,
                      "nusselt, rays: the receiving element (default: an emitter)");
  command->add_option("--matrix", a->request.matrix, "matrix: F or K")
      ->capture_default_str()
      ->check(CLI::IsMember({"F", "K"}));
  command->add_option("--channel", a->channel, "matrix K: the colour channel, r, g or b")
      ->capture_default_str();
  command->add_option("--row", a->request.row, "matrix: highlighted row");
  command->add_option("--column", a->request.column, "matrix: highlighted column");
  command
      ->add_option(
          "--part", a->request.part,
          "nusselt: disk or hemisphere (auto: hemisphere for PNG); hemicube: faces or 3d (auto: faces)")
      ->capture_default_str();
  command->add_option(
      "--input", a->request.input,
      "runtime-error: draw this CSV of `bench formfactors` or `bench solvers` instead of timing "
      "the solvers now");
  command
      ->add_option("--mesh", a->request.refineMode,
                   "scene: the mesh of a refining solver (uniform, adaptive, discontinuity, hierarchical)")
      ->check(CLI::IsMember({"uniform", "adaptive", "discontinuity", "hierarchical"}));
  command->add_option("--link-colour", a->request.linkColour, "links: level or formfactor")
      ->capture_default_str()
      ->check(CLI::IsMember({"level", "formfactor"}));
  command
      ->add_option("--link-tolerance", a->request.refine.linkTolerance,
                   "links, --mesh hierarchical: link threshold")
      ->capture_default_str();
  command->add_option("--max-elements", a->request.refine.maxElements, "--mesh adaptive: element budget")
      ->capture_default_str();
  command->add_option("--initial-edge", a->request.refine.initialMaxEdge,
                      "links, discontinuity, --mesh: starting max edge (0 = diagonal / 5)");
  command->add_option("--x", a->request.xAxis, "convergence: iteration or time")
      ->capture_default_str()
      ->check(CLI::IsMember({"iteration", "time"}));
  // The callback holds `a`: the options above write into it after this function returns.
#ifdef RT_HAVE_VIZ
  command->callback([a, command] { run(*a, *command); });
#else
  command->callback([a] {
    throw std::runtime_error("'figure' needs the visualisation library (configure with RT_BUILD_VIZ=ON)");
  });
#endif
}

}  // namespace rt::cli
