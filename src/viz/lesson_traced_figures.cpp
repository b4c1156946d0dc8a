#include "viz/lesson_traced_figures.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/pathtrace/image_compare.h"
#include "viz/chart.h"
#include "viz/image_panels.h"

namespace rt::viz::detail {

ImagePanelsOptions stepPictureOptions(const lesson::Step& step, const StepFigureSettings& s,
                                      const std::string& title) {
  ImagePanelsOptions o;
  o.size = {s.width, s.height, 96.0};
  o.title = title;
  o.exposure = step.parameters.exposure;
  o.toneMap = toneMapFromName(step.parameters.toneMap);
  o.srgbGamma = step.parameters.gamma;
  return o;
}

std::string renderTracedView(lesson::View view, const lesson::Step& step, const lesson::StepResult& r,
                             const StepFigureSettings& s, const std::string& path) {
  if (!r.pictures) throw std::runtime_error(path + ": the step traced no images");
  const lesson::TracedPictures& t = *r.pictures;
  // The numbers the step ran with (a quick render caps them), not the ones the lesson wrote.
  const auto ran = [&r](const char* name) {
    return std::to_string(static_cast<int>(r.value(name).value_or(0)));
  };
  const std::string paths = ran("paths") + " paths per pixel";
  switch (view) {
    case lesson::View::Traced:
      // The path-traced image sets the one exposure, so that equal light looks equal in both.
      writeImagePanelsFigure({{"Path traced (" + paths + ")", t.pathTraced.B},
                              {"Radiosity (" + std::to_string(r.mesh.size()) + " elements)", t.radiosity}},
                             stepPictureOptions(step, s, "One equation, two solutions"), path);
      return "The path tracer's image (Monte Carlo, no mesh) beside the radiosity solution's flat elements, "
             "from the same camera at one exposure";
    case lesson::View::TwoPass:
      writeImagePanelsFigure({{"Two-pass (" + ran("gather-rays") + " gather rays)", t.twoPass},
                              {"Path traced (" + paths + ")", t.pathTraced.B}},
                             stepPictureOptions(step, s, "The radiosity solution read through a second pass"),
                             path);
      return "The two-pass image: direct light computed at each pixel's point, one bounce gathered from the "
             "radiosity solution; beside it the path-traced reference";
    case lesson::View::Difference: {
      ImagePanelsOptions o;
      o.size = {s.width, s.height, 96.0};
      o.title = "|image - path traced| / mean";
      o.scalar = true;
      o.scale = t.mean > 0 ? t.mean : 1.0;
      o.full = 0.3;
      o.legend = "relative";
      writeImagePanelsFigure({{"Radiosity", absoluteDifference(t.radiosity, t.pathTraced.B)},
                              {"Two-pass", absoluteDifference(t.twoPass, t.pathTraced.B)},
                              {"Path tracer's noise", t.pathTraced.error}},
                             o, path);
      return "Where each image differs from the path-traced one, relative to its mean: the radiosity "
             "image's mesh (element steps, smeared shadows), the two-pass image's smaller error, and the "
             "path tracer's own standard error per pixel";
    }
    case lesson::View::Noise: {
      Series measured{"measured (two seeds): slope " + formatted("%.2f", t.slope), {}, {}},
          reported{"reported standard error", {}, {}};
      for (const lesson::NoisePoint& p : t.noise) {
        measured.x.push_back(p.paths);
        measured.y.push_back(p.measured);
        reported.x.push_back(p.paths);
        reported.y.push_back(p.reported);
      }
      if (measured.x.empty()) throw std::runtime_error(path + ": no noise measured");
      // The fitted line through the measured points' centre of mass in log-log.
      const Series fitted = fittedPowerLaw(measured, t.slope, 0);
      ChartOptions o{"Path tracer's noise against paths per pixel",
                     "paths per pixel",
                     "RMS noise / mean",
                     true,
                     true,
                     s.width,
                     s.height};
      writeLineChart({measured, fitted, reported}, o, path);
      return "RMS noise of the path-traced image relative to its mean, against the paths per pixel "
             "(log-log): the fitted slope (dashed) is " +
             formatted("%.2f", t.slope) + ", and 1/sqrt(paths) would be -0.5";
    }
    default:
      break;
  }
  throw std::runtime_error(path + ": not a view of the pathtrace stage");
}

}  // namespace rt::viz::detail
