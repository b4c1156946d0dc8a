#include "cli/lesson_figures.h"

#include <filesystem>
#include <stdexcept>

#ifdef RT_HAVE_VIZ
#include "viz/chart.h"
#include "viz/scene_view.h"
#endif

namespace rt::cli {

bool canRenderFigures() {
#ifdef RT_HAVE_VIZ
  return true;
#else
  return false;
#endif
}

#ifdef RT_HAVE_VIZ
namespace {

using lesson::StepResult;
using lesson::View;

viz::SceneViewOptions sceneOptions(const lesson::Step& step, const StepResult& r, const FigureSettings& s) {
  viz::SceneViewOptions o;
  const auto& p = step.parameters;
  o.image.width = s.width;
  o.image.height = s.height;
  o.image.exposure = p.exposure;
  o.image.toneMap = p.toneMap == "reinhard" ? viz::ToneMap::Reinhard : viz::ToneMap::LinearClamp;
  o.image.srgbGamma = p.gamma;
  o.image.smooth = p.smooth;
  o.image.showEdges = p.edges;
  o.highlightElement = r.highlighted.empty() ? -1 : r.highlighted.front();
  return o;
}

// A form-factor row seen on the scene: how much of element `source`'s power reaches each element.
void formFactorRow(const lesson::Step& step, const StepResult& r, const FigureSettings& s,
                   const std::string& title, const std::string& path) {
  if (!r.F) throw std::runtime_error(path + ": the step computed no form factors");
  viz::SceneViewOptions o = sceneOptions(step, r, s);
  o.colouring = viz::SceneColouring::Scalar;
  o.highlightElement = r.sourceElement;
  o.legend.title = title;
  o.caption = title;
  viz::SceneViewData data;
  data.scalar = r.F->row(r.sourceElement).transpose();
  viz::writeSceneFigure(r.mesh, r.camera, data, o, path);
}

std::string renderView(View view, const lesson::Step& step, const StepResult& r, const FigureSettings& s,
                       const std::string& path) {
  const std::string from = "element " + std::to_string(r.sourceElement);
  switch (view) {
    case View::Scene:
    case View::Local: {
      viz::SceneViewOptions o = sceneOptions(step, r, s);
      viz::SceneViewData data;
      if (view == View::Local) {
        data.B = r.local;
        o.caption = "Direct light + ambient term";
      } else if (r.B.rows() > 0) {
        data.B = r.B;
        o.caption = r.runs.empty() ? "Radiosity" : "Radiosity (" + r.runs.back().label + ")";
      } else {
        o.colouring = viz::SceneColouring::Reflectance;
        o.caption = "Reflectance of the surfaces";
      }
      viz::writeSceneFigure(r.mesh, r.camera, data, o, path);
      return o.caption;
    }
    case View::FormFactor:
      formFactorRow(step, r, s, "F from " + from + " (" + r.method + ")", path);
      return "Form factors from " + from + " to every element (" + r.method + ")";
    case View::Hemicube:
    case View::Nusselt:
    case View::Rays:
    case View::Visibility:
      formFactorRow(step, r, s, "F from " + from + " (" + r.method + ")", path);
      return "What " + from + " sees, by the " + r.method + " method";
    case View::Matrix: {
      if (!r.F) throw std::runtime_error(path + ": the step computed no form factors");
      std::vector<viz::Series> series;
      const int rows = std::min<int>(static_cast<int>(r.F->rows()), 4);
      for (int i = 0; i < rows; ++i) {
        viz::Series row{"row " + std::to_string(i), {}, {}};
        for (Eigen::Index j = 0; j < r.F->cols(); ++j) {
          row.x.push_back(static_cast<double>(j));
          row.y.push_back((*r.F)(i, j));
        }
        series.push_back(row);
      }
      viz::ChartOptions o{
          "Rows of the form-factor matrix", "column j", "F_ij", false, false, s.width, s.height};
      viz::writeLineChart(series, o, path);
      return "The first rows of F: entry F_ij against column j";
    }
    case View::Convergence: {
      std::vector<viz::Series> series;
      for (const auto& run : r.runs) {
        viz::Series line{run.label, {}, {}};
        for (std::size_t k = 0; k < run.residuals.size(); ++k) {
          if (!(run.residuals[k] > 0)) continue;
          line.x.push_back(run.iteration[k]);
          line.y.push_back(run.residuals[k]);
        }
        if (!line.x.empty()) series.push_back(line);
      }
      if (series.empty()) throw std::runtime_error(path + ": no convergence history to plot");
      viz::ChartOptions o{"Convergence", "iteration", "relative residual", false, true, s.width, s.height};
      viz::writeLineChart(series, o, path);
      return "Relative residual ||K B - E|| / ||E|| after each iteration";
    }
    case View::RuntimeError: {
      std::vector<viz::Series> series;
      for (const auto& point : r.benchmark) {
        if (series.empty() || series.back().name != point.method) series.push_back({point.method, {}, {}});
        series.back().x.push_back(std::max(point.seconds, 1e-6));
        series.back().y.push_back(std::max(point.error, 1e-16));
      }
      viz::ChartOptions o{
          "Run time against error", "seconds", "relative error of F", true, true, s.width, s.height};
      viz::writeLineChart(series, o, path);
      return "Relative error of F against run time, reference: " + r.method;
    }
    case View::Error: {
      viz::SceneViewOptions o = sceneOptions(step, r, s);
      viz::SceneViewData data;
      data.B = r.B;
      data.reference = r.reference;
      if (data.reference.rows() == 0 && r.variants.size() >= 2 &&
          r.variants.front().B.rows() == r.variants.back().B.rows()) {
        data.B = r.variants.back().B;
        data.reference = r.variants.front().B;
      }
      if (data.reference.rows() != data.B.rows())
        throw std::runtime_error(path + ": no reference to compare with");
      o.colouring = viz::SceneColouring::Error;
      o.caption = "|B - B_reference|";
      viz::writeSceneFigure(r.mesh, r.camera, data, o, path);
      return "Difference from the reference solution";
    }
  }
  return "";
}

}  // namespace
#endif

std::vector<lesson::RenderedFigure> renderStepFigures(const lesson::Lesson& lesson, const lesson::Step& step,
                                                      const lesson::StepResult& result,
                                                      const std::string& dir,
                                                      const FigureSettings& settings) {
  std::vector<lesson::RenderedFigure> figures;
  const auto files = step.figureFiles();
#ifdef RT_HAVE_VIZ
  std::filesystem::create_directories(dir);
  for (std::size_t k = 0; k < files.size(); ++k) {
    const std::string path = (std::filesystem::path(dir) / files[k]).string();
    const std::string caption = renderView(step.views[k], step, result, settings, path);
    figures.push_back({lesson.id + "/" + files[k], caption});
  }
#else
  (void)lesson, (void)result, (void)dir, (void)settings, (void)files;
#endif
  return figures;
}

}  // namespace rt::cli
