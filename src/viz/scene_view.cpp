#include "viz/scene_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "viz/vertex_interpolation.h"

namespace rt::viz {
namespace {

void requireRows(const RgbField& field, const Mesh& mesh, const char* what) {
  if (static_cast<std::size_t>(field.rows()) != mesh.size())
    throw std::invalid_argument(std::string(what) + " has " + std::to_string(field.rows()) + " rows for " +
                                std::to_string(mesh.size()) + " elements");
}

// Resolves the legend's limits from the finite (and, for log scales, positive) values.
ScalarLegend resolveLegend(ScalarLegend legend, const Eigen::VectorXd& values) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values)
    if (std::isfinite(v) && (!legend.logScale || v > 0)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  if (!std::isfinite(lo)) lo = hi = legend.logScale ? 1.0 : 0.0;
  if (!std::isfinite(legend.min)) legend.min = lo;
  if (!std::isfinite(legend.max)) legend.max = hi;
  if (legend.logScale) {
    legend.min = std::max(legend.min, 1e-300);
    if (legend.max <= legend.min) legend.max = legend.min * 10;
  } else if (legend.max <= legend.min) {
    legend.max = legend.min + (legend.min == 0 ? 1.0 : std::abs(legend.min) * 0.1);
  }
  return legend;
}

double normalised(double v, const ScalarLegend& legend) {
  if (std::isnan(v)) return v;
  if (legend.logScale) {
    if (v <= 0) return 0.0;
    return (std::log10(v) - std::log10(legend.min)) / (std::log10(legend.max) - std::log10(legend.min));
  }
  return (v - legend.min) / (legend.max - legend.min);
}

std::string defaultTitle(SceneColouring colouring, ErrorMeasure measure) {
  switch (colouring) {
    case SceneColouring::UnshotPower:
      return "unshot\npower (W)";
    case SceneColouring::Error:
      return measure == ErrorMeasure::Relative      ? "|B - B_ref|\n/ B_ref"
             : measure == ErrorMeasure::OfBrightest ? "|B - B_ref| /\nbrightest B_ref"
                                                    : "|B - B_ref|\n(W/m^2)";
    default:
      return "value";
  }
}

}  // namespace

SceneColouring sceneColouringFromName(const std::string& name) {
  if (name == "radiosity") return SceneColouring::Radiosity;
  if (name == "reflectance") return SceneColouring::Reflectance;
  if (name == "emission") return SceneColouring::Emission;
  if (name == "element" || name == "element-id") return SceneColouring::ElementId;
  if (name == "unshot") return SceneColouring::UnshotPower;
  if (name == "error") return SceneColouring::Error;
  if (name == "scalar") return SceneColouring::Scalar;
  throw std::invalid_argument("unknown colouring '" + name +
                              "' (radiosity, reflectance, emission, element, unshot, error, scalar)");
}

std::string toString(SceneColouring colouring) {
  switch (colouring) {
    case SceneColouring::Radiosity:
      return "radiosity";
    case SceneColouring::Reflectance:
      return "reflectance";
    case SceneColouring::Emission:
      return "emission";
    case SceneColouring::ElementId:
      return "element";
    case SceneColouring::UnshotPower:
      return "unshot";
    case SceneColouring::Error:
      return "error";
    case SceneColouring::Scalar:
      return "scalar";
  }
  return "radiosity";
}

Eigen::VectorXd unshotPower(const Mesh& mesh, const RgbField& unshot) {
  requireRows(unshot, mesh, "the unshot radiosity");
  return unshot.rowwise().mean().cwiseProduct(mesh.areas());
}

Eigen::VectorXd absoluteError(const RgbField& B, const RgbField& reference) {
  if (B.rows() != reference.rows())
    throw std::invalid_argument("the reference radiosity has " + std::to_string(reference.rows()) +
                                " rows, B has " + std::to_string(B.rows()));
  return (B - reference).cwiseAbs().rowwise().mean();
}

Eigen::VectorXd relativeError(const RgbField& B, const RgbField& reference) {
  const Eigen::VectorXd difference = absoluteError(B, reference);
  const Eigen::VectorXd scale = reference.cwiseAbs().rowwise().mean();
  const double floor = std::max(1e-3 * (scale.size() > 0 ? scale.mean() : 0.0), 1e-300);
  return difference.array() / scale.array().max(floor);
}

Eigen::VectorXd errorOfBrightest(const Mesh& mesh, const RgbField& B, const RgbField& reference) {
  const Eigen::VectorXd difference = absoluteError(B, reference);
  double brightest = 0;
  for (Eigen::Index i = 0; i < reference.rows(); ++i)
    if (i >= mesh.emission.rows() || mesh.emission.row(i).maxCoeff() <= 0)
      brightest = std::max(brightest, reference.row(i).cwiseAbs().mean());
  return brightest > 0 ? Eigen::VectorXd(difference / brightest) : difference;
}

ErrorMeasure errorMeasureFromName(const std::string& name) {
  if (name == "relative") return ErrorMeasure::Relative;
  if (name == "absolute") return ErrorMeasure::Absolute;
  if (name == "brightest") return ErrorMeasure::OfBrightest;
  throw std::invalid_argument("unknown error measure '" + name + "' (relative, absolute, brightest)");
}

ScenePaint paintScene(const Mesh& mesh, const SceneViewData& data, const SceneViewOptions& options,
                      const SmoothInterpolation* smoothing) {
  ScenePaint paint;
  paint.highlightElement = options.highlightElement;
  const bool smooth = options.image.smooth;
  // Flat views convert each element's value once and repeat the colour at its corners.
  auto fromElements = [&](const RgbField& perElement, auto&& toColour) {
    paint.firstCorner.assign(mesh.size() + 1, 0);
    for (std::size_t e = 0; e < mesh.size(); ++e)
      paint.firstCorner[e + 1] = paint.firstCorner[e] + static_cast<int>(mesh.elements[e].vertices.size());
    paint.colours.resize(static_cast<std::size_t>(paint.firstCorner.back()));
    for (std::size_t e = 0; e < mesh.size(); ++e) {
      const Rgb8 colour = toColour(Rgb(perElement.row(static_cast<Eigen::Index>(e)).transpose().array()));
      std::fill(paint.colours.begin() + paint.firstCorner[e],
                paint.colours.begin() + paint.firstCorner[e + 1], colour);
    }
  };
  auto fromCorners = [&](const RgbField& perElement, bool smoothed, auto&& toColour) {
    if (!smoothed) return fromElements(perElement, toColour);
    const CornerField corners = smoothing && smoothing->elements() == mesh.size()
                                    ? smoothing->apply(perElement)
                                    : smoothCornerValues(mesh, perElement);
    paint.firstCorner = corners.firstCorner;
    paint.colours.resize(static_cast<std::size_t>(corners.values.rows()));
    for (Eigen::Index k = 0; k < corners.values.rows(); ++k)
      paint.colours[static_cast<std::size_t>(k)] = toColour(Rgb(corners.values.row(k).transpose().array()));
  };

  Eigen::VectorXd scalar;
  switch (options.colouring) {
    case SceneColouring::Radiosity: {
      requireRows(data.B, mesh, "the radiosity");
      const DisplaySettings display = displaySettingsFor(options.image, data.B, &mesh.emission);
      if (data.corners.rows() > 0) {
        fromElements(data.B, [](const Rgb&) { return Rgb8{}; });  // the corner layout
        if (data.corners.rows() != static_cast<Eigen::Index>(paint.colours.size()))
          throw std::invalid_argument("the corner radiosity has " + std::to_string(data.corners.rows()) +
                                      " rows for " + std::to_string(paint.colours.size()) + " corners");
        for (Eigen::Index k = 0; k < data.corners.rows(); ++k)
          paint.colours[static_cast<std::size_t>(k)] =
              displayColour(Rgb(data.corners.row(k).transpose().array()), display);
        return paint;
      }
      fromCorners(data.B, smooth, [&](const Rgb& v) { return displayColour(v, display); });
      return paint;
    }
    case SceneColouring::Emission: {
      const DisplaySettings display = displaySettingsFor(options.image, mesh.emission);
      fromElements(mesh.emission, [&](const Rgb& v) { return displayColour(v, display); });
      return paint;
    }
    case SceneColouring::Reflectance:
      fromElements(mesh.reflectance, [&](const Rgb& v) { return albedoColour(v, options.image.srgbGamma); });
      return paint;
    case SceneColouring::ElementId: {
      RgbField ids(static_cast<Eigen::Index>(mesh.size()), 3);
      for (Eigen::Index e = 0; e < ids.rows(); ++e) ids.row(e).setConstant(static_cast<double>(e));
      fromElements(ids, [](const Rgb& v) { return categoryColour(static_cast<int>(v[0])); });
      return paint;
    }
    case SceneColouring::UnshotPower:
      scalar = unshotPower(mesh, data.unshot);
      break;
    case SceneColouring::Error:
      requireRows(data.B, mesh, "the radiosity");
      requireRows(data.reference, mesh, "the reference radiosity");
      scalar = options.errorMeasure == ErrorMeasure::Relative ? relativeError(data.B, data.reference)
               : options.errorMeasure == ErrorMeasure::OfBrightest
                   ? errorOfBrightest(mesh, data.B, data.reference)
                   : absoluteError(data.B, data.reference);
      break;
    case SceneColouring::Scalar:
      if (static_cast<std::size_t>(data.scalar.size()) != mesh.size())
        throw std::invalid_argument("the scalar field has " + std::to_string(data.scalar.size()) +
                                    " values for " + std::to_string(mesh.size()) + " elements");
      scalar = data.scalar;
      break;
  }
  ScalarLegend legend = options.legend;
  if (legend.title.empty()) legend.title = defaultTitle(options.colouring, options.errorMeasure);
  paint.legend = resolveLegend(legend, scalar);
  paint.colourBar = options.colourBar;
  RgbField broadcast = scalar.replicate(1, 3);
  fromCorners(broadcast, smooth, [&](const Rgb& v) {
    return sampleColourMap(paint.legend.map, normalised(v[0], paint.legend));
  });
  return paint;
}

}  // namespace rt::viz
