#include "viz/lesson_scaling_figures.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "viz/chart.h"
#include "viz/cluster_view.h"

namespace rt::viz::detail {
namespace {

// A straight line in log-log through (x0, y0) with slope `power`, from x0 to x1.
Series powerLine(const std::string& name, double x0, double y0, double x1, double power) {
  return {name, {x0, x1}, {y0, y0 * std::pow(x1 / x0, power)}};
}

// The links of the step's `scenes`, one series per scene with its fitted power law (dashed), against the n^2
// element pairs a dense F would hold over the same range of n.
std::string renderSceneLinks(const lesson::ScalingData& d, const StepFigureSettings& s,
                             const std::string& path) {
  std::vector<Series> all;
  std::string slopes;
  double lowest = 0, highest = 0;
  for (const lesson::SceneLinksSeries& scene : d.sceneLinks) {
    Series links{"links, " + scene.name + ": slope " + formatted("%.2f", scene.slope), {}, {}};
    for (const lesson::SceneLinksPoint& p : scene.points) {
      const double n = static_cast<double>(p.elements);
      links.x.push_back(n);
      links.y.push_back(static_cast<double>(p.links));
      lowest = lowest > 0 ? std::min(lowest, n) : n;
      highest = std::max(highest, n);
    }
    slopes += (slopes.empty() ? "" : ", ") + scene.name + " " + formatted("%.2f", scene.slope);
    all.push_back(std::move(links));
    if (all.back().x.size() >= 2)
      all.push_back(fittedPowerLaw(all.back(), scene.slope, static_cast<int>(all.size()) - 1));
  }
  all.push_back(powerLine("element pairs n^2", lowest, lowest * lowest, highest, 2.0));
  ChartOptions o{"Links against n", "elements n", "count", true, true, s.width, s.height};
  writeLineChart(all, o, path);
  return "The links hierarchical radiosity with clustering keeps on each scene at several sizes, against the "
         "n^2 element pairs a dense F would hold (log-log); fitted slopes of the links: " +
         slopes;
}

}  // namespace

std::string renderScalingView(lesson::View view, const lesson::Step& step, const lesson::StepResult& r,
                              const StepFigureSettings& s, const std::string& path) {
  if (!r.scaling) throw std::runtime_error(path + ": the step measured no scaling");
  const lesson::ScalingData& d = *r.scaling;
  const bool meshes = view == lesson::View::Memory || view == lesson::View::Cost ||
                      (view == lesson::View::Links && d.sceneLinks.empty());
  if (meshes && d.points.empty()) throw std::runtime_error(path + ": the step lists no `subdivisions`");
  const lesson::ScalingPoint first = d.points.empty() ? lesson::ScalingPoint{} : d.points.front();
  const lesson::ScalingPoint last = d.points.empty() ? lesson::ScalingPoint{} : d.points.back();
  const double n0 = static_cast<double>(first.elements), n1 = static_cast<double>(last.elements);
  // The charts reach past the n whose F fills the memory, so that the crossing shows.
  const double reach = std::max(2.0 * d.elementsThatFit, 2.0 * n1);
  switch (view) {
    case lesson::View::Memory: {
      Series dense{"F: 8 n^2 bytes", {}, {}}, clustered{"clustering: tree + links", {}, {}};
      for (const auto& p : d.points) {
        dense.x.push_back(static_cast<double>(p.elements));
        dense.y.push_back(p.denseBytes);
        clustered.x.push_back(static_cast<double>(p.elements));
        clustered.y.push_back(p.clusterBytes);
      }
      const Series extrapolated = powerLine("F beyond (8 n^2)", n1, last.denseBytes, reach, 2.0);
      const Series memory{"this machine's memory", {n0, reach}, {d.memoryBytes, d.memoryBytes}};
      ChartOptions o{"Memory against n", "elements n", "bytes", true, true, s.width, s.height};
      writeLineChart({extrapolated, memory, dense, clustered}, o, path);
      return "Bytes of the dense form-factor matrix (8 n^2) and of the clustering solver's tree and links "
             "against the elements n (log-log); F no longer fits in this machine's memory above n = " +
             formatted("%.0f", d.elementsThatFit);
    }
    case lesson::View::Cost: {
      Series dense{"form factors (" + r.method + ")", {}, {}}, clustered{"clustering: links + solve", {}, {}},
          direct{"direct solve (LU)", {}, {}}, sweep{"one Jacobi sweep", {}, {}};
      for (const auto& p : d.points) {
        const double n = static_cast<double>(p.elements);
        dense.x.push_back(n);
        dense.y.push_back(std::max(p.formFactorSeconds, 1e-6));
        clustered.x.push_back(n);
        clustered.y.push_back(std::max(p.clusterSeconds, 1e-6));
        direct.x.push_back(n);
        direct.y.push_back(std::max(p.directSeconds, 1e-6));
        sweep.x.push_back(n);
        sweep.y.push_back(std::max(p.sweepSeconds, 1e-6));
      }
      const Series extrapolated =
          powerLine("form factors beyond (n^2)", n1, std::max(last.formFactorSeconds, 1e-6), reach, 2.0);
      ChartOptions o{"Time against n", "elements n", "seconds", true, true, s.width, s.height};
      writeLineChart({extrapolated, dense, direct, sweep, clustered}, o, path);
      return "Seconds to compute F with " + r.method +
             ", to solve with it directly and to sweep it once, and to link and solve with clustering, "
             "against "
             "n (log-log); the measured slopes: F " +
             formatted("%.2f", d.formFactorSlope) + ", direct solve " + formatted("%.2f", d.directSlope) +
             ", one sweep " + formatted("%.2f", d.sweepSlope);
    }
    case lesson::View::Links: {
      if (!d.sceneLinks.empty()) return renderSceneLinks(d, s, path);
      Series pairs{"element pairs n^2", {}, {}}, links{"links (clustering)", {}, {}},
          nodes{"nodes 2n - 1", {}, {}};
      for (const auto& p : d.points) {
        const double n = static_cast<double>(p.elements);
        pairs.x.push_back(n);
        pairs.y.push_back(n * n);
        links.x.push_back(n);
        links.y.push_back(static_cast<double>(p.links));
        nodes.x.push_back(n);
        nodes.y.push_back(static_cast<double>(p.nodes));
      }
      ChartOptions o{"Links against element pairs", "elements n", "count", true, true, s.width, s.height};
      writeLineChart({pairs, links, nodes}, o, path);
      return "The n^2 element pairs a dense F holds against the links hierarchical radiosity with clustering "
             "keeps (log-log): links grow like n^" +
             formatted("%.2f", d.linksSlope);
    }
    case lesson::View::Noise: {
      Series reported{"reported standard error: slope " + formatted("%.2f", d.noiseSlope), {}, {}};
      for (const auto& p : d.noise) {
        reported.x.push_back(p.raysPerElement);
        reported.y.push_back(p.standardError);
      }
      if (reported.x.size() < 2) throw std::runtime_error(path + ": fewer than two noise points");
      const Series fitted = fittedPowerLaw(reported, d.noiseSlope, 0);
      ChartOptions o{"Local lines: noise against rays",
                     "rays per element",
                     "standard error / ||B||",
                     true,
                     true,
                     s.width,
                     s.height};
      writeLineChart({reported, fitted}, o, path);
      return "The standard error local lines reports, relative to ||B||, against the rays per element "
             "(log-log): the fitted slope (dashed) is " +
             formatted("%.2f", d.noiseSlope) + ", and 1/sqrt(rays) would be -0.5";
    }
    case lesson::View::Clusters: {
      ClusterViewOptions o;
      o.size = {s.width, s.height, 96.0};
      o.caption = std::to_string(d.boxes.size()) + " clusters at depth " + std::to_string(d.clusterDepth) +
                  " of the tree over " + std::to_string(r.mesh.size()) + " elements";
      writeClusterFigure(r.mesh, r.B, r.camera, d.boxes, o, path);
      return "The cluster hierarchy cut at depth " + std::to_string(d.clusterDepth) +
             ": each box is one node, and one link between two boxes stands for every pair of their elements";
    }
    default:
      break;
  }
  (void)step;
  throw std::runtime_error(path + ": not a view of the scaling stage");
}

std::string renderSamplingView(const lesson::StepResult& r, const StepFigureSettings& s,
                               const std::string& path) {
  if (!r.sampling || r.sampling->empty()) throw std::runtime_error(path + ": the step measured no sampling");
  std::vector<Series> all;
  std::string slopes;
  for (const SamplingSeries& v : *r.sampling) {
    Series points{v.variant.name + ": slope " + formatted("%.2f", v.slope), {}, {}};
    for (const SamplingPoint& p : v.points) {
      points.x.push_back(p.rays);
      points.y.push_back(p.error);
    }
    if (points.x.size() < 2) throw std::runtime_error(path + ": fewer than two ray counts");
    slopes += (slopes.empty() ? "" : ", ") + v.variant.name + " " + formatted("%.2f", v.slope);
    all.push_back(std::move(points));
    all.push_back(fittedPowerLaw(all.back(), v.slope, static_cast<int>(all.size()) - 1));
  }
  ChartOptions o{"Error against rays", "rays", "RMS error / B", true, true, s.width, s.height};
  writeLineChart(all, o, path);
  return "RMS error against the direct solution (F by " + r.method +
         ") against the rays used, each point over " +
         std::to_string(static_cast<int>(r.value("seeds").value_or(0))) +
         " seeds (log-log), each with its fitted power law (dashed); fitted slopes: " + slopes;
}

}  // namespace rt::viz::detail
