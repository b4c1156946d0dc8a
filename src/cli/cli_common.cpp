#include "cli/cli_common.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "cli/setting_options.h"
#include "core/camera_path.h"
#include "core/io/scene_loader.h"
#include "core/time_left.h"

namespace rt::cli {

void MeshArguments::add(CLI::App& command) {
  auto* none = command.add_flag("--no-subdivide", noSubdivide, "One element per input face, in file order");
  auto* count = command.add_option("--subdivide", subdivide, "Split every patch N x N (triangles: N^2)")
                    ->check(CLI::PositiveNumber);
  auto* edge =
      command.add_option("--max-edge", maxEdge, "Split patches until no edge is longer than L (scene units)")
          ->check(CLI::PositiveNumber);
  auto* contacts =
      command.add_flag("--split-at-contacts", splitAtContacts,
                       "With --max-edge or --subdivide: first cut every patch along the lines where other "
                       "surfaces stand on it, "
                       "as the default mesh does, so that no element straddles a block's footprint");
  auto* gap = addSettingOption(command, "overlap-gap", overlapGap);
  none->excludes(count)->excludes(edge)->excludes(contacts)->excludes(gap);
  count->excludes(edge);
}

MeshOptions MeshArguments::options() const {
  MeshOptions o;
  if (subdivide > 0) {
    o.mode = MeshOptions::Mode::Count;
    o.count = subdivide;
  } else if (maxEdge > 0) {
    o.mode = MeshOptions::Mode::MaxEdge;
    o.maxEdge = maxEdge;
  }
  o.splitAtContacts = splitAtContacts && o.mode != MeshOptions::Mode::None;
  o.overlapGap = overlapGap;
  return o;
}

namespace {

// Which cuts the mesh makes, one line each on stderr, so that a reader sees which way a scene was meshed.
MeshOptions reportingCuts(const Scene& scene, const MeshOptions& options) {
  for (const std::string& line : describeMeshCuts(scene, meshCuts(scene, options)))
    std::cerr << "mesh: cut " << line << "\n";
  return options;
}

}  // namespace

MeshOptions MeshArguments::optionsFor(const Scene& scene) const {
  if (noSubdivide || subdivide > 0 || maxEdge > 0) return reportingCuts(scene, options());
  MeshOptions chosen = defaultMeshOptions(scene);
  chosen.overlapGap = overlapGap;
  if (chosen.mode != MeshOptions::Mode::MaxEdge) return chosen;
  char line[256];
  std::snprintf(
      line, sizeof line,
      "mesh: no mesh option given: --max-edge %g (%s) for about %.0f elements, cut where surfaces stand "
      "on others or lie just in front of them "
      "(--no-subdivide: one element per polygon; --max-edge or --subdivide: your own)",
      chosen.maxEdge, scene.unit.c_str(), estimatedElementCount(scene, chosen));
  std::cerr << line << "\n";
  return reportingCuts(scene, chosen);
}

void CameraArgument::add(CLI::App& command) {
  command.add_option("--camera", text,
                     "The view: a camera the scene names, or \"position x y z target x y z up x y z "
                     "fov_y_degrees f\" in scene units (default: the scene's camera, or one that frames the "
                     "whole scene)");
}

void CameraArgument::applyTo(Scene& scene) const {
  if (!text.empty()) scene.camera = cameraFromText(scene, text, {"--camera", 0, {}});
}

Scene loadSceneReportingWarnings(const std::string& path) {
  Scene scene = loadScene(path);
  for (const std::string& w : scene.warnings) std::cerr << w << "\n";
  return scene;
}

FormFactorMatrix computeFormFactorsReporting(const Mesh& mesh, const std::string& methodName,
                                             const FormFactorOptions& options, ProgressLine& progress) {
  const auto method = makeFormFactorMethod(methodName);
  FormFactorStats stats;
  FormFactorMatrix F = method->compute(mesh, options, progress, stats);
  progress.finish();
  reportFormFactorStats(std::cerr, "form factors (" + method->name() + ")", stats);
  return F;
}

void reportFormFactorStats(std::ostream& out, const std::string& method, const FormFactorStats& stats) {
  out << method << ": " << stats.summary() << "\n";
  out.flush();
  for (const std::string& w : stats.warnings) std::cerr << "warning: " << w << "\n";
}

ProgressLine::ProgressLine(bool enabled) : enabled_(enabled), terminal_(isatty(STDERR_FILENO) != 0) {}

ProgressLine::~ProgressLine() {
  finish();
}

void ProgressLine::report(double fraction, const std::string& stage) {
  if (!enabled_) return;
  const int percent = static_cast<int>(fraction * 100.0 + 0.5);
  const int step = terminal_ ? 1 : 10;
  if (stage == lastStage_ && percent / step == lastPercent_ / step) return;
  if (stage != lastStage_ && open_ && terminal_) std::fprintf(stderr, "\n");
  const auto now = std::chrono::steady_clock::now();
  if (stage != lastStage_) stageStart_ = now;
  lastStage_ = stage;
  lastPercent_ = percent;
  const std::string left =
      describeTimeLeft(std::chrono::duration<double>(now - stageStart_).count(), fraction);
  const std::string suffix = left.empty() ? "" : " (" + left + ")";
  if (terminal_) {
    std::fprintf(stderr, "\r%-24s %3d%%%-24s", stage.c_str(), percent, suffix.c_str());
    open_ = true;
  } else {
    std::fprintf(stderr, "%s %d%%%s\n", stage.c_str(), percent, suffix.c_str());
  }
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (open_ && terminal_) std::fprintf(stderr, "\n");
  open_ = false;
}

}  // namespace rt::cli
