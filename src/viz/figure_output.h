// Figure files: the format follows the extension (.png raster; .svg and .pdf vectors for 2D views, .pdf with
// an embedded high-resolution raster for 3D views). Public header: no VTK types.
#pragma once

#include <string>

namespace rt::viz {

enum class FigureFormat { Png, Svg, Pdf };

// Throws std::invalid_argument naming the path when the extension is none of .png, .svg, .pdf.
FigureFormat figureFormatOf(const std::string& path);

struct FigureSize {
  int width = 1200;
  int height = 900;
  double dpi = 96.0;  // scales fonts and line widths (dpi / 96) and sets the physical size of PDF pages
  double fontScale() const { return dpi > 0 ? dpi / 96.0 : 1.0; }
};

// A minimal PDF with one page showing an RGB image (bottom row first, as VTK stores it), scaled to width/dpi
// inches. Used for 3D views, which have no vector form. Throws std::runtime_error naming the path on failure.
void writeRasterPdf(const unsigned char* rgbBottomUp, int width, int height, double dpi,
                    const std::string& path);

}  // namespace rt::viz
