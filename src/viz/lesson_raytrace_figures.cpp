#include "viz/lesson_raytrace_figures.h"

#include <stdexcept>

#include "viz/chart.h"
#include "viz/image_panels.h"
#include "viz/lesson_traced_figures.h"
#include "viz/ray_tree_view.h"

namespace rt::viz::detail {
namespace {

std::string count(double n) {
  return formatted("%.0f", n);
}

std::string epsilonText(double epsilon) {
  return "epsilon = " + formatted("%.3g", epsilon);
}

}  // namespace

std::string renderRayTraceView(lesson::View view, const lesson::Step& step, const lesson::StepResult& r,
                               const StepFigureSettings& s, const std::string& path) {
  if (!r.raytrace) throw std::runtime_error(path + ": the step traced no rays");
  const lesson::RayTraceData& d = *r.raytrace;
  const auto value = [&r](const char* name) { return r.value(name).value_or(0.0); };
  const std::string shadowRays =
      std::to_string(d.shadowRays) + (d.shadowRays == 1 ? " shadow ray" : " shadow rays");
  switch (view) {
    case lesson::View::RayTree: {
      const RayCounts n = d.tree.counts();
      RayTreeViewOptions o;
      o.size = {s.width, s.height, 96.0};
      o.caption = "Pixel (" + std::to_string(d.pixelX) + ", " + std::to_string(d.pixelY) +
                  "): " + std::to_string(n.total()) + " rays, 1 primary (blue), " +
                  std::to_string(n.reflection) + " reflected (purple), " + std::to_string(n.shadow) +
                  " shadow (orange; black: blocked)";
      writeRayTreeFigure(r.mesh, rayTreeCamera(r.mesh, r.camera), d.tree, o, path);
      return "The ray tree of one pixel in the scene: the primary ray from the eye, a shadow ray per light "
             "sample from every surface it reaches, and the mirror rays, up to depth " +
             std::to_string(d.depth);
    }
    case lesson::View::Shadows:
      writeImagePanelsFigure(
          {{"1 shadow ray per light (hard)", d.hard}, {shadowRays + " per light (soft)", d.whitted}},
          stepPictureOptions(step, s, "Hard and soft shadows"), path);
      return "The same Whitted picture with one shadow ray per light, to the light's centre (a point light), "
             "and with " +
             shadowRays + " spread over the light's area";
    case lesson::View::Epsilon:
      writeImagePanelsFigure({{epsilonText(0) + ": acne", d.epsilonZero},
                              {epsilonText(d.epsilon) + " (this step)", d.epsilonStep},
                              {epsilonText(d.largeEpsilon) + ": leaks", d.epsilonLarge}},
                             stepPictureOptions(step, s, "The self-intersection epsilon (1 shadow ray)"),
                             path);
      return "Shadow rays that count hits from 0 on find the surface they leave (" +
             formatted("%.0f%%", 100 * value("acne.zero")) + " of the lit points wrongly dark); from " +
             formatted("%.3g", d.epsilon) + " on, " + formatted("%.2f%%", 100 * value("acne.step")) +
             "; from " + formatted("%.3g", d.largeEpsilon) + " on they skip blockers near their start (" +
             formatted("%.1f%%", 100 * value("leaks.large")) + " of the shadowed points wrongly lit)";
    case lesson::View::RayCost: {
      const Series formula{"formula: full tree (every hit a mirror)", d.depths, d.formula};
      const Series counted{step.parameters.mirrors.empty()
                               ? "counted: no mirror"
                               : "counted: " + step.parameters.mirrors + " a mirror",
                           d.depths, d.counted};
      ChartOptions o{
          "Rays per pixel against depth (" + std::to_string(d.lights) + " light, " + shadowRays + ")",
          "depth (mirror reflections followed)",
          "rays per pixel",
          false,
          true,
          s.width,
          s.height};
      writeLineChart({formula, counted}, o, path);
      return "Rays per pixel against the depth limit: the cost formula's full tree, (1 + depth)(1 + lights x "
             "shadow rays), and the rays the tracer counted, " +
             count(value("rays-per-pixel")) + " per pixel at depth " + std::to_string(d.depth);
    }
    case lesson::View::Whitted:
      writeImagePanelsFigure({{"Whitted ray tracing", d.whitted},
                              {"Radiosity (" + std::to_string(r.mesh.size()) + " elements)", d.radiosity}},
                             stepPictureOptions(step, s, "Ray traced and radiosity"), path);
      return "The Whitted picture, direct light and mirror reflections only, beside the radiosity "
             "solution from the same camera at one exposure: only the second has light on the ceiling and "
             "colour bled from the walls";
    case lesson::View::Glossy: {
      const std::string rays =
          std::to_string(d.pixelSamples) + (d.pixelSamples == 1 ? " ray per pixel" : " rays per pixel");
      const std::string q = formatted("%.0f", d.gloss);
      writeImagePanelsFigure({{"ideal mirrors", d.idealMirrors}, {"glossy mirrors, q = " + q, d.whitted}},
                             stepPictureOptions(step, s, "Ideal and glossy reflection (" + rays + ")"), path);
      return "The same Whitted picture with ideal mirrors and with glossy ones, each reflected ray drawn "
             "from "
             "the Phong lobe cos^" +
             q + " about the mirror direction, " + rays + " averaging the lobe";
    }
    case lesson::View::Focus: {
      const std::string rays =
          std::to_string(d.pixelSamples) + (d.pixelSamples == 1 ? " ray per pixel" : " rays per pixel");
      const std::string lens = "lens radius " + formatted("%.3g", d.aperture) + ", focused at " +
                               formatted("%.4g", d.focusDistance);
      writeImagePanelsFigure({{"pinhole", d.pinhole}, {lens, d.whitted}},
                             stepPictureOptions(step, s, "Depth of field (" + rays + ")"), path);
      return "The same Whitted picture through a pinhole, everything sharp, and through a lens of radius " +
             formatted("%.3g", d.aperture) + " focused at distance " + formatted("%.4g", d.focusDistance) +
             ": each primary ray starts at its own point of the lens, so only the plane of focus stays sharp";
    }
    case lesson::View::Motion: {
      const std::string rays =
          std::to_string(d.pixelSamples) + (d.pixelSamples == 1 ? " ray per pixel" : " rays per pixel");
      const std::string moving = step.parameters.moving.empty() ? "nothing" : step.parameters.moving;
      const std::string motion = formatted("%.4g", d.motion);
      writeImagePanelsFigure({{"standing still", d.still}, {moving + " moving " + motion, d.whitted}},
                             stepPictureOptions(step, s, "Motion blur (" + rays + ")"), path);
      return "The same Whitted picture with everything standing still, and with " + moving + " moving by " +
             motion +
             " along x while the shutter is open: each primary ray sees it at its own time, so the rays of a "
             "pixel average its path";
    }
    case lesson::View::PathBounces: {
      std::vector<ImagePanel> panels;
      for (std::size_t k = 0; k < d.pathBounces.size(); ++k) {
        const int b = d.bounceLimits[k];
        const std::string title = b < 0    ? "every bounce"
                                  : b == 0 ? "direct light only"
                                  : b == 1 ? "1 bounce"
                                           : std::to_string(b) + " bounces";
        panels.push_back({title, d.pathBounces[k]});
      }
      // The full solution (the last panel) sets the one exposure, so that each bounce visibly adds light.
      ImagePanelsOptions o = stepPictureOptions(
          step, s,
          "The path tracer, one more bounce at a time (" + std::to_string(d.paths) + " paths per pixel)");
      if (o.exposure == 0 && !panels.empty()) o.exposure = panelExposure({panels.back()}, o);
      writeImagePanelsFigure(panels, o, path);
      return "Path-traced pictures of the same scene limited to direct light (what Whitted's diffuse "
             "surfaces show), to one and two diffuse bounces, and with every bounce, at one exposure";
    }
    default:
      break;
  }
  throw std::runtime_error(path + ": not a view of the raytrace stage");
}

}  // namespace rt::viz::detail
