#include "viz/hits_chart.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rt::viz {
namespace {

constexpr Rgb8 kBar{86, 180, 233};      // Okabe-Ito sky blue
constexpr Rgb8 kReference{213, 94, 0};  // Okabe-Ito vermillion
constexpr Rgb8 kInk{20, 20, 20};
constexpr Rgb8 kGrid{215, 215, 215};

// A round step for about five ticks over [0, top].
double tickStep(double top) {
  const double raw = top / 5.0;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

}  // namespace

Drawing hitsDrawing(const std::vector<HitRow>& rows, const HitsChartOptions& options) {
  if (rows.empty()) throw std::invalid_argument("the hits chart needs at least one surface");
  Drawing d;
  d.width = options.size.width;
  d.height = options.size.height;
  const double font = std::max(11.0, 0.026 * d.height * options.size.fontScale());
  double top = 0;
  std::size_t longest = 0;
  for (const HitRow& r : rows) {
    top = std::max({top, r.estimate + 2 * r.standardError, r.reference});
    longest = std::max(longest, r.label.size());
  }
  top = top > 0 ? 1.08 * top : 1.0;
  const double step = tickStep(top);
  top = std::ceil(top / step - 1e-9) * step;

  // Labels left, legend and title above, tick labels below.
  const double left = std::min(0.4 * d.width, 0.62 * font * static_cast<double>(longest) + 1.5 * font);
  const double right = 1.5 * font, bottom = 3.2 * font, above = (options.title.empty() ? 2.6 : 4.2) * font;
  const double x0 = left, x1 = d.width - right, y0 = bottom, y1 = d.height - above;
  auto x = [&](double v) { return x0 + (x1 - x0) * v / top; };
  const double band = (y1 - y0) / static_cast<double>(rows.size());

  for (double v = 0; v <= top + 1e-12; v += step) {
    d.line({x(v), y0}, {x(v), y1}, 1.0, kGrid);
    d.text(formatValue(v), {x(v), y0 - 0.4 * font}, font, Drawing::Align::Centre, Drawing::Align::End, kInk);
  }
  d.text("fraction of the lines (bars: N_ij / N with 2 standard errors; marks: F_ij)",
         {(x0 + x1) / 2, 0.4 * font}, font, Drawing::Align::Centre, Drawing::Align::Start, kInk);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const HitRow& r = rows[k];
    const double yc = y1 - (static_cast<double>(k) + 0.5) * band;
    const double h = std::min(0.55 * band, 2.2 * font);
    d.rectangle(x0, yc - h / 2, std::max(0.0, x(r.estimate) - x0), h, kBar, 1.0, {60, 120, 160});
    const double lo = std::max(0.0, r.estimate - 2 * r.standardError), hi = r.estimate + 2 * r.standardError;
    const double cap = 0.3 * h, width = std::max(1.5, 0.12 * font);
    d.line({x(lo), yc}, {x(hi), yc}, width, kInk);
    d.line({x(lo), yc - cap}, {x(lo), yc + cap}, width, kInk);
    d.line({x(hi), yc - cap}, {x(hi), yc + cap}, width, kInk);
    // The reference: a diamond, wide enough to see where it sits under an error bar.
    const double s = 0.45 * font;
    d.polygon({{x(r.reference), yc - h / 2 - s},
               {x(r.reference) + s, yc - h / 2},
               {x(r.reference), yc - h / 2 + s},
               {x(r.reference) - s, yc - h / 2}},
              kReference, 1.0, kInk);
    d.text(r.label, {x0 - 0.5 * font, yc}, font, Drawing::Align::End, Drawing::Align::Centre, kInk);
  }
  d.line({x0, y0}, {x0, y1}, 1.5, kInk);
  d.line({x0, y0}, {x1, y0}, 1.5, kInk);

  // Legend.
  const double ly = d.height - 1.6 * font;
  d.rectangle(x0, ly - 0.4 * font, 1.6 * font, 0.8 * font, kBar, 1.0, {60, 120, 160});
  d.text("local lines N_ij / N, +/- 2 standard errors", {x0 + 2.1 * font, ly}, font, Drawing::Align::Start,
         Drawing::Align::Centre, kInk);
  const double rx = x0 + 0.55 * (x1 - x0), s = 0.45 * font;
  d.polygon({{rx, ly - s}, {rx + s, ly}, {rx, ly + s}, {rx - s, ly}}, kReference, 1.0, kInk);
  d.text("reference F_ij", {rx + 1.2 * font, ly}, font, Drawing::Align::Start, Drawing::Align::Centre, kInk);
  if (!options.title.empty())
    d.text(options.title, {d.width / 2, d.height - 3.3 * font}, 1.1 * font, Drawing::Align::Centre,
           Drawing::Align::Centre, kInk, true);
  return d;
}

void writeHitsChart(const std::vector<HitRow>& rows, const HitsChartOptions& options,
                    const std::string& path) {
  writeDrawing(hitsDrawing(rows, options), path);
}

}  // namespace rt::viz
