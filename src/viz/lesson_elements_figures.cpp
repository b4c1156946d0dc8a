#include "viz/lesson_elements_figures.h"

#include <stdexcept>

#include "viz/chart.h"

namespace rt::viz::detail {

std::string renderBasisErrorView(const lesson::StepResult& r, const StepFigureSettings& s,
                                 const std::string& path) {
  if (!r.elements || r.elements->series.empty())
    throw std::runtime_error(path + ": the step measured no bases");
  const lesson::ElementsData& d = *r.elements;
  std::vector<Series> measured, fitted;
  std::string orders;
  // Error against n; the orders are in the element size h, and n grows like h^-2, so a line of order p
  // has the slope -p/2 here.
  const auto add = [&](const lesson::BasisSeries& b, const std::string& surface) {
    Series points{b.basis + (surface.empty() ? "" : ", " + surface), {}, {}};
    for (const lesson::BasisErrorPoint& p : b.points) {
      points.x.push_back(static_cast<double>(p.elements));
      points.y.push_back(surface.empty() ? p.error : p.surfaceError.at(surface));
    }
    const double order = surface.empty() ? b.order : b.surfaceOrder.at(surface);
    fitted.push_back(
        fittedPowerLaw(points, -order / 2, points.name + " fit, order " + formatted("%.2f", order)));
    orders += (orders.empty() ? "" : "; ") + points.name + " " + formatted("%.2f", order);
    measured.push_back(std::move(points));
  };
  for (const lesson::BasisSeries& b : d.series) {
    add(b, "");
    for (const std::string& surface : d.surfaces) add(b, surface);
  }
  std::vector<Series> all = std::move(fitted);
  all.insert(all.end(), measured.begin(), measured.end());
  ChartOptions o{"Error against elements", "elements n", "relative L1 error", true, true, s.width, s.height};
  writeLineChart(all, o, path);
  return "Relative L1 error of the constant and the linear basis against the linear basis on " +
         std::to_string(d.referenceElements) +
         " elements, against the elements n (log-log); orders in the "
         "element size: " +
         orders;
}

}  // namespace rt::viz::detail
