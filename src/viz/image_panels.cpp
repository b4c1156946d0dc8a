#include "viz/image_panels.h"

#include <algorithm>
#include <stdexcept>

#include "viz/colour_map.h"

namespace rt::viz {

double panelExposure(const std::vector<ImagePanel>& panels, const ImagePanelsOptions& options) {
  if (options.exposure > 0) return options.exposure;
  if (panels.empty() || panels.front().image.pixels.empty()) return 1.0;
  std::vector<double> brightest;
  for (const Rgb& p : panels.front().image.pixels)
    if (p.maxCoeff() > 0) brightest.push_back(p.maxCoeff());
  if (brightest.empty()) return 1.0;
  // A picture's bright surfaces (the top of a block, the lit ceiling) cover more than a tenth of its pixels,
  // where they are a few of many elements in a scene view: the 98th percentile keeps them from clipping.
  const auto k = static_cast<std::ptrdiff_t>(0.98 * static_cast<double>(brightest.size() - 1));
  std::nth_element(brightest.begin(), brightest.begin() + k, brightest.end());
  const double white = options.toneMap == ToneMap::Reinhard ? 2.0 : 1.0;  // Reinhard: x/(1+x) = 2/3
  return brightest[static_cast<std::size_t>(k)] > 0 ? white / brightest[static_cast<std::size_t>(k)] : 1.0;
}

Drawing imagePanelsDrawing(const std::vector<ImagePanel>& panels, const ImagePanelsOptions& o) {
  if (panels.empty()) throw std::invalid_argument("no images to show");
  Drawing d;
  d.width = o.size.width;
  d.height = o.size.height;
  const double font = 0.035 * d.height;
  const double titleBand = o.title.empty() ? 0.5 * font : 2.0 * font;
  const double captionBand = 2.0 * font;
  const double barBand = o.scalar ? 0.12 * d.width : 0.0;
  const double gap = 0.02 * d.width;
  const auto n = static_cast<double>(panels.size());
  // Square-ish panels as large as fit in a row, keeping each image's proportions.
  const ImagePanel& first = panels.front();
  const double aspect =
      first.image.height > 0 ? static_cast<double>(first.image.width) / first.image.height : 1;
  double w = (d.width - barBand - gap * (n + 1)) / n;
  double h = w / aspect;
  const double room = d.height - titleBand - captionBand - gap;
  if (h > room) {
    h = room;
    w = h * aspect;
  }
  const double left = 0.5 * (d.width - barBand - (n * w + (n - 1) * gap));
  const double bottom = captionBand + 0.5 * (room - h);
  if (!o.title.empty())
    d.text(o.title, Vec2(0.5 * d.width, d.height - 0.5 * font), 1.15 * font, Drawing::Align::Centre,
           Drawing::Align::End, {20, 20, 20}, true);

  DisplaySettings display;
  display.exposure = panelExposure(panels, o);
  display.toneMap = o.toneMap;
  display.srgbGamma = o.srgbGamma;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const RgbImage& image = panels[k].image;
    std::vector<Rgb8> pixels;
    pixels.reserve(image.pixels.size());
    for (const Rgb& p : image.pixels)
      pixels.push_back(o.scalar ? sampleColourMap(o.map, p.mean() / o.scale / o.full)
                                : displayColour(p, display));
    const double x = left + static_cast<double>(k) * (w + gap);
    d.image(x, bottom, w, h, image.width, image.height, std::move(pixels));
    d.outline({Vec2(x, bottom), Vec2(x + w, bottom), Vec2(x + w, bottom + h), Vec2(x, bottom + h)}, 1.0,
              {120, 120, 120});
    d.text(panels[k].title, Vec2(x + 0.5 * w, bottom - 0.4 * font), font, Drawing::Align::Centre,
           Drawing::Align::End);
  }
  if (o.scalar)
    drawColourBar(d, d.width - barBand + 0.15 * barBand, bottom, 0.2 * barBand, h, o.map, 0.0, o.full, false,
                  o.legend, 0.8 * font);
  return d;
}

void writeImagePanelsFigure(const std::vector<ImagePanel>& panels, const ImagePanelsOptions& options,
                            const std::string& path) {
  writeDrawing(imagePanelsDrawing(panels, options), path);
}

}  // namespace rt::viz
