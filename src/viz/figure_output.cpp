#include "viz/figure_output.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rt::viz {

FigureFormat figureFormatOf(const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string extension = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == "png") return FigureFormat::Png;
  if (extension == "svg") return FigureFormat::Svg;
  if (extension == "pdf") return FigureFormat::Pdf;
  throw std::invalid_argument(path + ": unknown figure format (use .png, .svg or .pdf)");
}

void writeRasterPdf(const unsigned char* rgbBottomUp, int width, int height, double dpi,
                    const std::string& path) {
  if (width <= 0 || height <= 0) throw std::runtime_error(path + ": empty image");
  // PDF images run top to bottom.
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  std::vector<unsigned char> raw(row * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    std::copy_n(rgbBottomUp + static_cast<std::size_t>(height - 1 - y) * row, row, raw.begin() + y * row);
  uLongf packedSize = compressBound(static_cast<uLong>(raw.size()));
  std::vector<unsigned char> packed(packedSize);
  if (compress2(packed.data(), &packedSize, raw.data(), static_cast<uLong>(raw.size()), 9) != Z_OK)
    throw std::runtime_error(path + ": cannot compress the image");

  const double scale = 72.0 / (dpi > 0 ? dpi : 96.0);
  auto number = [](double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
  };
  const std::string pageSize = number(width * scale) + " " + number(height * scale);
  const std::string contents =
      "q " + number(width * scale) + " 0 0 " + number(height * scale) + " 0 0 cm /Im0 Do Q\n";

  std::ostringstream out;
  std::vector<std::size_t> offsets;
  auto object = [&](const std::string& body) {
    offsets.push_back(static_cast<std::size_t>(out.tellp()));
    out << offsets.size() << " 0 obj\n" << body << "\nendobj\n";
  };
  out << "%PDF-1.4\n%\xe2\xe3\xcf\xd3\n";
  object("<< /Type /Catalog /Pages 2 0 R >>");
  object("<< /Type /Pages /Kids [3 0 R] /Count 1 >>");
  object("<< /Type /Page /Parent 2 0 R /MediaBox [0 0 " + pageSize +
         "] /Resources << /XObject << /Im0 4 0 R >> >> /Contents 5 0 R >>");
  std::ostringstream image;
  image << "<< /Type /XObject /Subtype /Image /Width " << width << " /Height " << height
        << " /ColorSpace /DeviceRGB /BitsPerComponent 8 /Filter /FlateDecode /Length " << packedSize
        << " >>\nstream\n";
  image.write(reinterpret_cast<const char*>(packed.data()), static_cast<std::streamsize>(packedSize));
  image << "\nendstream";
  object(image.str());
  object("<< /Length " + std::to_string(contents.size()) + " >>\nstream\n" + contents + "endstream");
  const auto xref = static_cast<std::size_t>(out.tellp());
  out << "xref\n0 " << offsets.size() + 1 << "\n0000000000 65535 f \n";
  for (std::size_t offset : offsets) {
    char line[24];
    std::snprintf(line, sizeof line, "%010zu 00000 n \n", offset);
    out << line;
  }
  out << "trailer\n<< /Size " << offsets.size() + 1 << " /Root 1 0 R >>\nstartxref\n" << xref << "\n%%EOF\n";

  std::ofstream file(path, std::ios::binary);
  const std::string bytes = out.str();
  if (!file || !file.write(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    throw std::runtime_error(path + ": cannot write the PDF");
}

}  // namespace rt::viz
