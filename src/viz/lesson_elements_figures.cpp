#include "viz/lesson_elements_figures.h"

#include <stdexcept>

#include "viz/chart.h"

namespace rt::viz::detail {

std::string renderBasisErrorView(const lesson::StepResult& r, const StepFigureSettings& s,
                                 const std::string& path) {
  if (!r.elements || r.elements->series.empty())
    throw std::runtime_error(path + ": the step measured no bases");
  const lesson::ElementsData& d = *r.elements;
  std::vector<Series> all;
  std::string orders;
  // Error against n; the orders are in the element size h, and n grows like h^-2, so a line of order p
  // has the slope -p/2 here.
  const auto add = [&](const lesson::BasisSeries& b, const std::string& surface) {
    const std::string name = b.basis + (surface.empty() ? "" : ", " + surface);
    const double order = surface.empty() ? b.order : b.surfaceOrder.at(surface);
    Series points{name + ": order " + formatted("%.2f", order), {}, {}};
    for (const lesson::BasisErrorPoint& p : b.points) {
      points.x.push_back(static_cast<double>(p.elements));
      points.y.push_back(surface.empty() ? p.error : p.surfaceError.at(surface));
    }
    orders += (orders.empty() ? "" : "; ") + name + " " + formatted("%.2f", order);
    all.push_back(std::move(points));
    all.push_back(fittedPowerLaw(all.back(), -order / 2, static_cast<int>(all.size()) - 1));
  };
  for (const lesson::BasisSeries& b : d.series) {
    add(b, "");
    for (const std::string& surface : d.surfaces) add(b, surface);
  }
  ChartOptions o{"Error against elements", "elements n", "relative L1 error", true, true, s.width, s.height};
  writeLineChart(all, o, path);
  return "Relative L1 error of the constant and the linear basis against the linear basis on " +
         std::to_string(d.referenceElements) +
         " elements, against the elements n (log-log), each with its fitted power law (dashed); orders in "
         "the "
         "element size: " +
         orders;
}

}  // namespace rt::viz::detail
