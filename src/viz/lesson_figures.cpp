#include "viz/lesson_figures.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "core/formfactor/hemicube.h"
#include "core/formfactor/ray_scene.h"
#include "core/solvers/solver.h"
#include "lesson/step_runner.h"
#include "viz/chart.h"
#include "viz/exact_visibility.h"
#include "viz/hemicube_view.h"
#include "viz/hits_chart.h"
#include "viz/lesson_elements_figures.h"
#include "viz/lesson_radiometry_figures.h"
#include "viz/lesson_raytrace_figures.h"
#include "viz/lesson_reflection_figures.h"
#include "viz/lesson_scaling_figures.h"
#include "viz/lesson_traced_figures.h"
#include "viz/matrix_view.h"
#include "viz/meshing_view.h"
#include "viz/nusselt_view.h"
#include "viz/rays_view.h"
#include "viz/scene_view.h"
#include "viz/walks_view.h"

namespace rt::viz {

namespace {

using lesson::StepResult;
using lesson::View;

SceneViewOptions sceneOptions(const lesson::Step& step, const StepResult& r, const StepFigureSettings& s) {
  SceneViewOptions o;
  const auto& p = step.parameters;
  o.image.width = s.width;
  o.image.height = s.height;
  o.image.exposure = p.exposure;
  o.image.toneMap = toneMapFromName(p.toneMap);
  o.image.srgbGamma = p.gamma;
  o.image.smooth = p.smooth;
  o.image.showEdges = p.edges;
  o.highlightElement = r.highlighted.empty() ? -1 : r.highlighted.front();
  return o;
}

// A form-factor row seen on the scene: how much of element `source`'s power reaches each element.
void formFactorRow(const lesson::Step& step, const StepResult& r, const StepFigureSettings& s,
                   const std::string& title, const std::string& path) {
  if (!r.F) throw std::runtime_error(path + ": the step computed no form factors");
  SceneViewOptions o = sceneOptions(step, r, s);
  o.colouring = SceneColouring::Scalar;
  o.highlightElement = r.sourceElement;
  // The bar's title is short (the strip beside the bar is narrow); the caption names the method.
  o.legend.title = "F[" + std::to_string(r.sourceElement) + ", j]";
  o.caption = title;
  SceneViewData data;
  data.scalar = r.F->row(r.sourceElement).transpose();
  writeSceneFigure(r.mesh, r.camera, data, o, path);
}

// A surface's name as a figure prints it: "back wall" for the scene's key `back_wall`.
std::string readable(std::string name) {
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

std::string surfaceNameOf(const StepResult& r, int element) {
  return readable(r.scene.surfaces[r.scene.patches[r.mesh.elements[element].patch].surface].name);
}

// The element a Nusselt or rays view looks at: the first highlighted element other than the source, otherwise
// the one the source sends most light to.
int targetElement(const StepResult& r) {
  for (int h : r.highlighted)
    if (h != r.sourceElement) return h;
  if (!r.F) throw std::runtime_error("the step computed no form factors");
  Eigen::Index best = 0;
  r.F->row(r.sourceElement).maxCoeff(&best);
  return static_cast<int>(best);
}

std::string renderView(View view, const lesson::Step& step, const StepResult& r, const StepFigureSettings& s,
                       const std::string& path) {
  const std::string from = "element " + std::to_string(r.sourceElement);
  switch (view) {
    case View::Scene:
    case View::Local: {
      SceneViewOptions o = sceneOptions(step, r, s);
      SceneViewData data;
      if (view == View::Local) {
        data.B = r.local;
        o.caption = "Direct light + ambient term";
      } else if (r.B.rows() > 0) {
        data.B = r.B;
        // A linear basis is drawn as it is, corner by corner.
        if (step.stage != lesson::Stage::Bounces) data.corners = r.corners;
        if (step.stage == lesson::Stage::Bounces) {
          const std::size_t bounces = r.bounceTerms.size() - 1;
          o.caption = "Radiosity after " + std::to_string(bounces) + (bounces == 1 ? " bounce" : " bounces");
        } else if (step.stage == lesson::Stage::Refine)
          o.caption = "Radiosity on the " + step.parameters.refine + " mesh";
        else if (r.corners.rows() > 0)
          o.caption = "Radiosity, linear basis (" + std::to_string(r.mesh.size()) + " elements)";
        else
          o.caption = r.runs.empty() ? "Radiosity" : "Radiosity (" + r.runs.back().label + ")";
      } else {
        o.colouring = SceneColouring::Reflectance;
        o.caption = r.mesh.emission.maxCoeff() > 0 ? "Reflectance of the surfaces (the light outlined)"
                                                   : "Reflectance of the surfaces";
      }
      writeSceneFigure(r.mesh, r.camera, data, o, path);
      return o.caption;
    }
    case View::FormFactor:
      formFactorRow(step, r, s, "F from " + from + " (" + r.method + ")", path);
      return "Form factors from " + from + " to every element (" + r.method + ")";
    case View::Hemicube: {
      const int resolution = step.parameters.resolution.value_or(64);
      const HemicubeFaces faces = renderHemicube(r.mesh, r.sourceElement, resolution);
      HemicubeViewOptions o;
      o.size = {s.width, s.height, 96.0};
      writeHemicubeFacesFigure(faces, r.mesh.size(), o, path);
      return "The hemicube of " + from + " unfolded (" + std::to_string(resolution) +
             " pixels across the top face), each pixel coloured by the element it sees";
    }
    case View::Nusselt: {
      const int to = targetElement(r);
      const Element& e = r.mesh.elements[r.sourceElement];
      const NusseltConstruction construction = nusseltConstruction(e.centroid, e.normal, r.mesh.polygon(to));
      NusseltViewOptions o;
      o.size = {s.width, s.height, 96.0};
      writeNusseltDiskFigure(construction, o, path);
      return "Element " + std::to_string(to) + " projected onto the unit disk from the centre of " + from;
    }
    case View::Rays: {
      const int to = targetElement(r);
      if (r.method == "montecarlo") {
        // The lines the Monte Carlo row counted (the same generator and seed), the first few hundred drawn.
        const int count =
            static_cast<int>(r.formFactorStats.raysCast / std::max<std::size_t>(1, r.mesh.size()));
        const RayScene scene(r.mesh);
        std::vector<LocalLine> lines =
            shootLocalLines(r.mesh, scene, r.sourceElement, count, step.parameters.seed.value_or(1),
                            parseLineSampling(step.parameters.sampling).value_or(LineSampling::Random));
        if (lines.size() > 300) lines.resize(300);
        RaysViewOptions o;
        o.size = {s.width, s.height, 96.0};
        std::size_t landed = 0;
        for (const LocalLine& line : lines) landed += line.hit == to ? 1 : 0;
        o.caption = std::to_string(lines.size()) + " of the " + std::to_string(count) +
                    " local lines from the " + surfaceNameOf(r, r.sourceElement) +
                    " (blue): " + std::to_string(landed) + " land first on the " + surfaceNameOf(r, to) +
                    " (orange)";
        writeLocalLinesFigure(r.mesh, r.camera, r.sourceElement, to, lines, count, o, path);
        return "Local lines from " + from +
               ": cosine-distributed rays from uniform points, each counted on the "
               "element it reaches first";
      }
      const RaySample sample =
          sampleRays(r.mesh, r.sourceElement, to, std::min(step.parameters.samples.value_or(32), 256),
                     step.parameters.seed.value_or(1));
      RaysViewOptions o;
      o.size = {s.width, s.height, 96.0};
      writeRaysFigure(r.mesh, r.camera, sample, o, path);
      return "Visibility rays from " + from + " to element " + std::to_string(to);
    }
    case View::Visibility: {
      // The same view as `radiosity figure --view visibility`: the exact visible part of the target.
      const int to = targetElement(r);
      VisibilityViewOptions o;
      o.size = {s.width, s.height, 96.0};
      writeVisibilityFigure(exactVisibilityRegions(r.mesh, r.sourceElement, to), o, path);
      return "What the centre of " + from + " sees of element " + std::to_string(to) +
             ": its visible part, exactly (the shadows of the occluders cut away)";
    }
    case View::Matrix: {
      if (!r.F) throw std::runtime_error(path + ": the step computed no form factors");
      // A matrix step says which matrix it shows (F, rho F or K); other steps show F.
      const std::string kind = r.shownMatrix ? step.parameters.matrix : "F";
      MatrixViewOptions o;
      o.size = {s.width, s.height, 96.0};
      for (const auto& e : r.mesh.elements) o.groups.push_back(e.patch);
      o.selectedRow = r.sourceElement;
      if (kind == "K") {
        o.title = "K = I - rho F, green channel (" + r.method + ")";
        o.valueLabel = "K_ij";
        writeMatrixFigure(*r.shownMatrix, o, path);
        return "The system matrix K = I - rho F: ones on the diagonal, -rho_i F_ij elsewhere";
      }
      if (kind == "rhoF") {
        o.title = "rho_i F_ij, green channel (" + r.method + ")";
        o.valueLabel = "rho_i F_ij";
        writeMatrixFigure(*r.shownMatrix, o, path);
        return "rho F: the share of element j's radiosity that element i reflects; its spectral radius sets "
               "how fast the iterations converge";
      }
      o.title = "Form factors F_ij (" + r.method + ")";
      writeMatrixFigure(Eigen::MatrixXd(*r.F), o, path);
      return "The form-factor matrix: row i is what element i sends to each element j";
    }
    case View::Convergence: {
      std::vector<Series> series;
      for (const auto& run : r.runs) {
        Series line{run.label, {}, {}};
        for (std::size_t k = 0; k < run.residuals.size(); ++k) {
          if (!(run.residuals[k] > 0)) continue;
          line.x.push_back(run.iteration[k]);
          line.y.push_back(run.residuals[k]);
        }
        if (!line.x.empty()) series.push_back(line);
      }
      if (series.empty()) throw std::runtime_error(path + ": no convergence history to plot");
      // A solver that traces its lines has no F to compute the residual with: it records its own measure.
      bool traced = false;
      for (const auto& run : r.runs)
        for (const SolverInfo& info : solverTable())
          traced |= info.name == run.label && info.input == SolverInput::Geometry;
      const char* measure = traced ? "residual or stopping measure" : "relative residual";
      ChartOptions o{"Convergence", "iteration", measure, false, true, s.width, s.height};
      writeLineChart(series, o, path);
      if (traced)
        return "After each iteration, the relative residual ||K B - E|| / ||E|| of the solvers that read F, "
               "and "
               "the measure they stop on for those that trace their lines (the text says which)";
      return "Relative residual ||K B - E|| / ||E|| after each iteration";
    }
    case View::RuntimeError: {
      std::vector<Series> series;
      for (const auto& point : r.benchmark) {
        if (series.empty() || series.back().name != point.method) series.push_back({point.method, {}, {}});
        series.back().x.push_back(std::max(point.seconds, 1e-6));
        series.back().y.push_back(std::max(point.error, 1e-16));
      }
      ChartOptions o{
          "Run time against error", "seconds", "relative error of F", true, true, s.width, s.height};
      writeLineChart(series, o, path);
      return "Relative error of F against run time, reference: " + r.method;
    }
    case View::SweepError: {
      // Error against the knob itself: with a tiny scene the run times are microseconds of noise, while the
      // error against the number of samples shows each method's rate (Monte Carlo's slope of one half).
      std::vector<Series> series;
      bool resolutions = false, samples = false;
      for (const auto& point : r.benchmark) {
        if (series.empty() || series.back().name != point.method) series.push_back({point.method, {}, {}});
        series.back().x.push_back(std::max<double>(point.parameter, 1));
        series.back().y.push_back(std::max(point.error, 1e-16));
        (point.method == "hemicube" || point.method == "nusselt" ? resolutions : samples) = true;
      }
      const std::string knob = resolutions && samples ? "resolution or samples"
                               : resolutions          ? "resolution"
                                                      : "samples";
      ChartOptions o{"Error against " + knob, knob, "relative error of F", true, true, s.width, s.height};
      writeLineChart(series, o, path);
      return "Relative error of F against the " + knob + ", reference: " + r.method;
    }
    case View::Error: {
      SceneViewOptions o = sceneOptions(step, r, s);
      SceneViewData data;
      data.B = r.B;
      data.reference = r.reference;
      if (data.reference.rows() == 0 && r.variants.size() >= 2 &&
          r.variants.front().B.rows() == r.variants.back().B.rows()) {
        data.B = r.variants.back().B;
        data.reference = r.variants.front().B;
      }
      if (data.reference.rows() != data.B.rows())
        throw std::runtime_error(path + ": no reference to compare with");
      // Measured as the lessons' texts quote it: against the brightest reflecting element, so that one dim
      // element's large ratio does not set the whole colour bar.
      o.colouring = SceneColouring::Error;
      o.errorMeasure = ErrorMeasure::OfBrightest;
      o.caption = "|B - B_reference| / brightest B_reference";
      writeSceneFigure(r.mesh, r.camera, data, o, path);
      return "Difference from the reference solution, relative to its brightest reflecting element";
    }
    case View::Walkthrough: {
      // The one solution from every camera of the path: the figure is the first frame, the others beside it.
      if (r.cameraPath.empty() || r.B.rows() == 0)
        throw std::runtime_error(path + ": the step has no camera path or no solution");
      SceneViewOptions o = sceneOptions(step, r, s);
      SceneViewData data;
      data.B = r.B;
      o.caption = "";
      for (std::size_t f = 0; f < r.cameraPath.size(); ++f) {
        writeSceneFigure(r.mesh, r.cameraPath[f], data, o,
                         lesson::walkthroughFrameFile(path, static_cast<int>(f)));
        if (f == 0) writeSceneFigure(r.mesh, r.cameraPath[f], data, o, path);
      }
      std::string route;
      for (const auto& name : step.camera.path) route += (route.empty() ? "" : " -> ") + name;
      return "One solution, " + std::to_string(r.cameraPath.size()) + " views along the cameras " + route +
             " (the first frame; the others are numbered beside it)";
    }
    case View::Noise:
      // The scaling stage measures a solver's noise against its rays, the pathtrace stage the tracer's, a
      // compare step each stochastic solver's own estimate of its noise after each iteration.
      if (r.scaling) return detail::renderScalingView(view, step, r, s, path);
      if (step.stage == lesson::Stage::Compare) {
        std::vector<Series> series;
        for (const auto& run : r.runs)
          if (!run.rays.empty()) series.push_back({run.label, run.rays, run.standardErrors});
        if (series.empty()) throw std::runtime_error(path + ": no stochastic solver to plot");
        ChartOptions o{"Noise against rays",
                       "rays (or walks) so far",
                       "relative standard error",
                       true,
                       true,
                       s.width,
                       s.height};
        writeLineChart(series, o, path);
        return "Each stochastic solver's relative standard error after each iteration, against the rays (or "
               "walks) it has used so far";
      }
      return detail::renderTracedView(view, step, r, s, path);
    case View::Traced:
    case View::Difference:
    case View::TwoPass:
      return detail::renderTracedView(view, step, r, s, path);
    case View::Hits: {
      std::vector<HitRow> rows;
      for (const auto& surface : r.scene.surfaces) {
        const auto estimate = r.value("lines." + surface.name);
        if (!estimate)
          throw std::runtime_error(path + ": the step counted no local lines (give it a reference)");
        const double reference = r.value("lines." + surface.name + ".reference").value_or(0.0);
        if (*estimate <= 0 && reference <= 0) continue;  // a surface the source cannot see
        rows.push_back({readable(surface.name), *estimate, r.value("lines-se." + surface.name).value_or(0.0),
                        reference});
      }
      // The lines that hit nothing: the part of the row that leaves through openings.
      const double escaped = r.value("lines.escaped").value_or(0.0),
                   escapedReference = r.value("lines.escaped.reference").value_or(0.0);
      if (escaped > 0 || escapedReference > 0) {
        const double lines = std::max(1.0, r.value("lines").value_or(1.0));
        rows.push_back({"(escaped)", escaped, std::sqrt(escaped * (1 - escaped) / lines), escapedReference});
      }
      HitsChartOptions o;
      o.size = {s.width, s.height, 96.0};
      o.title = std::to_string(static_cast<long>(r.value("lines").value_or(0))) + " local lines from the " +
                surfaceNameOf(r, r.sourceElement) + " against " + step.parameters.reference;
      writeHitsChart(rows, o, path);
      return "Where the local lines from " + from + " (the " + surfaceNameOf(r, r.sourceElement) +
             ") land first, per surface, against the form factors by " + step.parameters.reference;
    }
    case View::Memory:
    case View::Cost:
    case View::Links:
    case View::Clusters:
      return detail::renderScalingView(view, step, r, s, path);
    case View::SolidAngle:
    case View::CosineLaw:
    case View::InverseSquare:
      return detail::renderRadiometryView(view, r, s, path);
    case View::RayTree:
    case View::Shadows:
    case View::Epsilon:
    case View::RayCost:
    case View::Whitted:
    case View::PathBounces:
    case View::Glossy:
    case View::Focus:
    case View::Motion:
      return detail::renderRayTraceView(view, step, r, s, path);
    case View::Lobe:
    case View::PhongSweep:
    case View::Albedo:
    case View::PhongLocal:
      return detail::renderReflectionView(view, step, r, s, path);
    case View::SamplingError:
      return detail::renderSamplingView(r, s, path);
    case View::Discontinuity: {
      if (!r.refined) throw std::runtime_error(path + ": the step refined no mesh");
      DiscontinuityViewOptions o;
      o.size = {s.width, s.height, 96.0};
      o.image = sceneOptions(step, r, s).image;
      writeDiscontinuityFigure(*r.refined, r.camera, o, path);
      const CriticalLineCounts counts = countCriticalLines(*r.refined);
      return "The " + step.parameters.refine +
             " mesh with its critical lines: " + std::to_string(counts.extremal) +
             " umbra and penumbra boundaries, " + std::to_string(counts.interior) + " lines inside penumbrae";
    }
    case View::TVertices: {
      if (!r.refined) throw std::runtime_error(path + ": the step refined no mesh");
      DiscontinuityViewOptions o;
      o.size = {s.width, s.height, 96.0};
      o.image = sceneOptions(step, r, s).image;
      return writeTVertexFigure(*r.refined, r.camera, o, path);
    }
    case View::BasisError:
      return detail::renderBasisErrorView(r, s, path);
    case View::Walks: {
      if (r.walks.empty()) throw std::runtime_error(path + ": the step recorded no walks");
      std::vector<WalksPanel> panels;
      for (const lesson::DrawnWalks& drawn : r.walks) {
        std::size_t landings = 0, absorbed = 0;
        for (const RecordedWalk& walk : drawn.walks) {
          landings += walk.landings.size();
          absorbed += walk.end == RecordedWalk::End::Absorbed ? 1 : 0;
        }
        const bool photons = drawn.solver == "photon-density";
        panels.push_back({std::string(photons ? "Continuous walks (photons)" : "Discrete walks (rows of F)") +
                              ": the first " + std::to_string(drawn.walks.size()) + " of " + drawn.solver +
                              ", " + std::to_string(landings) + " landings, " + std::to_string(absorbed) +
                              " absorbed",
                          drawn.walks});
      }
      WalksViewOptions o;
      o.size = {s.width, s.height, 96.0};
      writeWalksFigure(r.mesh, r.camera, panels, o, path);
      return "The first walks of each walk solver, as it followed them";
    }
  }
  return "";
}

}  // namespace

std::vector<lesson::RenderedFigure> renderStepFigures(const lesson::Lesson& lesson, const lesson::Step& step,
                                                      const lesson::StepResult& result,
                                                      const std::string& dir,
                                                      const StepFigureSettings& settings) {
  std::vector<lesson::RenderedFigure> figures;
  auto files = step.figureFiles();
  for (std::string& file : files)
    if (settings.format != "png")
      file = std::filesystem::path(file).replace_extension(settings.format).string();
  std::filesystem::create_directories(dir);
  for (std::size_t k = 0; k < files.size(); ++k) {
    const std::string path = (std::filesystem::path(dir) / files[k]).string();
    // The picture keeps the view's short title; the book and the figures tab take the lesson's caption.
    const std::string title = renderView(step.views[k], step, result, settings, path);
    const std::string caption =
        step.views[k] == step.captionView ? lesson::resolvedCaption(lesson, step, result) : std::string();
    figures.push_back({lesson.id + "/" + files[k], caption.empty() ? title : caption});
  }
  return figures;
}

}  // namespace rt::viz
