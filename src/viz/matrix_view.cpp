#include "viz/matrix_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rt::viz {
namespace {

constexpr Rgb8 kZero{228, 228, 228};
constexpr Rgb8 kMarker{213, 94, 0};  // Okabe-Ito vermillion: not in viridis or cividis

// The value shown for block (r, c): the entry with the largest magnitude, so that isolated couplings stay
// visible.
double blockValue(const Eigen::MatrixXd& m, int r0, int c0, int block) {
  double best = 0;
  for (int r = r0; r < std::min<int>(r0 + block, static_cast<int>(m.rows())); ++r)
    for (int c = c0; c < std::min<int>(c0 + block, static_cast<int>(m.cols())); ++c)
      if (std::abs(m(r, c)) > std::abs(best)) best = m(r, c);
  return best;
}

}  // namespace

Drawing matrixDrawing(const Eigen::MatrixXd& matrix, const MatrixViewOptions& options) {
  if (matrix.rows() == 0 || matrix.rows() != matrix.cols())
    throw std::invalid_argument("the matrix view needs a non-empty square matrix (got " +
                                std::to_string(matrix.rows()) + " x " + std::to_string(matrix.cols()) + ")");
  const int n = static_cast<int>(matrix.rows());
  if (!options.groups.empty() && static_cast<int>(options.groups.size()) != n)
    throw std::invalid_argument("the matrix view has " + std::to_string(options.groups.size()) +
                                " group labels for " + std::to_string(n) + " elements");
  const int block = std::max(1, (n + std::max(1, options.maxCells) - 1) / std::max(1, options.maxCells));
  const int cells = (n + block - 1) / block;

  Drawing d;
  d.width = options.size.width;
  d.height = options.size.height;
  const double font = std::max(11.0, 0.026 * d.height * options.size.fontScale());

  // Layout: labels left and top, colour bar right, title at the very top.
  const double left = 3.2 * font, right = 7.5 * font, top = 4.9 * font, bottom = 1.2 * font;
  const double side = std::max(10.0, std::min(d.width - left - right, d.height - top - bottom));
  const double x0 = left, y0 = d.height - top - side;  // bottom-left of the cell area
  const double cell = side / cells;

  // Colour scale over |values| (log) or values (linear).
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  bool negative = false;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const double v = matrix(r, c);
      if (!std::isfinite(v)) continue;
      negative |= v < 0;
      const double shown = options.logScale ? std::abs(v) : v;
      if (options.logScale && shown <= 0) continue;
      lo = std::min(lo, shown);
      hi = std::max(hi, shown);
    }
  if (!std::isfinite(lo)) lo = hi = options.logScale ? 1.0 : 0.0;
  // A nearly constant matrix stays nearly one colour: the scale spans at least a decade (log) or reaches zero
  // (linear), so that 0.1998 and 0.2000 do not land at opposite ends of the map.
  if (options.logScale)
    lo = std::min(lo, hi / 10);
  else if (hi - lo < 0.1 * std::max(std::abs(lo), std::abs(hi)))
    lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
  if (std::isfinite(options.min)) lo = options.min;
  if (std::isfinite(options.max)) hi = options.max;
  if (options.logScale) {
    // Six decades are what the eye can tell apart on one map; smaller non-zero entries get the lowest colour.
    if (!std::isfinite(options.min)) lo = std::max(lo, hi * 1e-6);
    if (hi <= lo) hi = lo * 10;
  } else if (hi <= lo) {
    hi = lo + 1;
  }
  auto colourOf = [&](double v) -> Rgb8 {
    if (!std::isfinite(v)) return {255, 0, 255};
    if (options.logScale) {
      if (v == 0) return kZero;
      return sampleColourMap(options.map,
                             (std::log10(std::abs(v)) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)));
    }
    return sampleColourMap(options.map, (v - lo) / (hi - lo));
  };

  std::vector<double> shownValues(static_cast<std::size_t>(cells) * cells);
  for (int r = 0; r < cells; ++r)
    for (int c = 0; c < cells; ++c) {
      const double v = block == 1 ? matrix(r, c) : blockValue(matrix, r * block, c * block, block);
      shownValues[static_cast<std::size_t>(r) * cells + c] = v;
      // Row 0 at the top, as matrices are written.
      d.rectangle(x0 + c * cell, y0 + side - (r + 1) * cell, cell + 0.02, cell + 0.02, colourOf(v));
    }

  // Numbers in the cells of small matrices, dark on light colours and light on dark ones.
  if (block == 1 && n <= options.numbersUpTo) {
    const double cellFont = std::clamp(cell * 0.22, 9.0, 1.2 * font);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const double v = matrix(r, c);
        const Rgb8 bg = colourOf(v);
        const double luminance = 0.2126 * bg[0] + 0.7152 * bg[1] + 0.0722 * bg[2];
        d.text(formatValue(v), {x0 + (c + 0.5) * cell, y0 + side - (r + 0.5) * cell}, cellFont,
               Drawing::Align::Centre, Drawing::Align::Centre,
               luminance > 140 ? Rgb8{15, 15, 15} : Rgb8{250, 250, 250});
      }
  }

  // Separators where the group label changes.
  const double separatorWidth = std::max(1.0, 1.5 * options.size.fontScale());
  if (!options.groups.empty())
    for (int k = 1; k < n; ++k) {
      if (options.groups[k] == options.groups[k - 1]) continue;
      const double at = static_cast<double>(k) / block * cell;
      d.line({x0 + at, y0}, {x0 + at, y0 + side}, separatorWidth, {255, 255, 255});
      d.line({x0, y0 + side - at}, {x0 + side, y0 + side - at}, separatorWidth, {255, 255, 255});
    }

  // Selection.
  const double markerWidth = std::max(2.0, 3.0 * options.size.fontScale());
  if (options.selectedRow >= 0 && options.selectedRow < n) {
    const int r = options.selectedRow / block;
    d.outline({{x0, y0 + side - (r + 1) * cell},
               {x0 + side, y0 + side - (r + 1) * cell},
               {x0 + side, y0 + side - r * cell},
               {x0, y0 + side - r * cell}},
              markerWidth, kMarker);
  }
  if (options.selectedColumn >= 0 && options.selectedColumn < n) {
    const int c = options.selectedColumn / block;
    d.outline({{x0 + c * cell, y0},
               {x0 + (c + 1) * cell, y0},
               {x0 + (c + 1) * cell, y0 + side},
               {x0 + c * cell, y0 + side}},
              markerWidth, kMarker);
  }
  d.outline({{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}}, 1.0, {40, 40, 40});

  // Index labels: every element when few, about ten otherwise.
  const double labelFont = 0.8 * font;
  const int stride = n <= 20 ? 1 : std::max(1, static_cast<int>(std::ceil(n / 10.0)));
  for (int k = 0; k < n; k += stride) {
    const double at = (k + 0.5) / block * cell;
    d.text(std::to_string(k), {x0 - 0.3 * font, y0 + side - at}, labelFont, Drawing::Align::End,
           Drawing::Align::Centre);
    d.text(std::to_string(k), {x0 + at, y0 + side + 0.3 * font}, labelFont, Drawing::Align::Centre,
           Drawing::Align::Start);
  }
  d.text(options.columnLabel, {x0 + 0.5 * side, y0 + side + 1.6 * font}, font, Drawing::Align::Centre,
         Drawing::Align::Start);
  d.text(options.rowLabel, {0.8 * font, y0 + 0.5 * side}, font, Drawing::Align::Centre,
         Drawing::Align::Centre, {20, 20, 20}, false, 90);
  std::string title = options.title;
  if (block > 1)
    title += "  (" + std::to_string(block) + "x" + std::to_string(block) + " blocks, largest |value|)";
  d.text(title, {0.5 * d.width, d.height - 0.4 * font}, 1.15 * font, Drawing::Align::Centre,
         Drawing::Align::End, {10, 10, 10}, true);

  std::string valueTitle = options.valueLabel;
  if (options.logScale && negative) valueTitle = "|" + valueTitle + "|";
  drawColourBar(d, x0 + side + 1.2 * font, y0 + 0.1 * side, 1.3 * font, 0.75 * side, options.map, lo, hi,
                options.logScale, valueTitle, 0.8 * font);
  if (options.logScale) {
    const double y = y0 + 0.1 * side - 2.2 * font;
    d.rectangle(x0 + side + 1.2 * font, y, 1.3 * font, 1.3 * font, kZero, 1.0, {40, 40, 40});
    d.text("0", {x0 + side + 3.2 * font, y + 0.65 * font}, 0.8 * font, Drawing::Align::Start,
           Drawing::Align::Centre);
  }
  return d;
}

void writeMatrixFigure(const Eigen::MatrixXd& matrix, const MatrixViewOptions& options,
                       const std::string& path) {
  writeDrawing(matrixDrawing(matrix, options), path);
}

}  // namespace rt::viz
