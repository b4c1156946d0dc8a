#include "viz/drawing_images.h"

#include <vtkBase64Utilities.h>
#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace rt::viz {

vtkSmartPointer<vtkImageData> imageDataOf(const Drawing::Shape& shape) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(shape.pixelsWide, shape.pixelsHigh, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int y = 0; y < shape.pixelsHigh; ++y)
    for (int x = 0; x < shape.pixelsWide; ++x) {
      const Rgb8& c = shape.pixels[static_cast<std::size_t>(shape.pixelsHigh - 1 - y) * shape.pixelsWide + x];
      std::copy(c.begin(), c.end(), out + 3 * (static_cast<std::size_t>(y) * shape.pixelsWide + x));
    }
  return image;
}

namespace {

std::string pngBase64(const Drawing::Shape& shape) {
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetInputData(imageDataOf(shape));
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* png = writer->GetResult();
  const auto bytes = static_cast<unsigned long>(png->GetNumberOfValues());
  std::vector<unsigned char> encoded(4 * ((bytes + 2) / 3) + 1);
  const unsigned long length = vtkBase64Utilities::Encode(png->GetPointer(0), bytes, encoded.data());
  return std::string(reinterpret_cast<const char*>(encoded.data()), length);
}

// The <image> element of `shape`: the drawing's y runs up from the bottom, the SVG's down from the top.
std::string imageElement(const Drawing::Shape& shape, double drawingHeight) {
  const Vec2 low = shape.points[0], high = shape.points[1];
  char place[256];
  std::snprintf(place, sizeof place, R"(x="%g" y="%g" width="%g" height="%g")", low.x(),
                drawingHeight - high.y(), high.x() - low.x(), high.y() - low.y());
  // Each pixel a sharp square, as in the PNG figure.
  return std::string("<image ") + place +
         R"( preserveAspectRatio="none" style="image-rendering:pixelated" href="data:image/png;base64,)" +
         pngBase64(shape) + "\"/>";
}

}  // namespace

int embedDrawingImages(std::string& svg, const Drawing& drawing) {
  std::vector<const Drawing::Shape*> images;
  for (const Drawing::Shape& shape : drawing.shapes)
    if (shape.kind == Drawing::Kind::Image && shape.points.size() >= 2 && !shape.pixels.empty())
      images.push_back(&shape);
  int embedded = 0;
  std::size_t at = 0;
  for (const Drawing::Shape* shape : images) {
    const std::size_t reference = svg.find("#vtkEmbeddedImage", at);
    if (reference == std::string::npos) break;
    const std::size_t start = svg.rfind("<use", reference), end = svg.find("/>", reference);
    if (start == std::string::npos || end == std::string::npos) break;
    const std::string element = imageElement(*shape, drawing.height);
    svg.replace(start, end + 2 - start, element);
    at = start + element.size();
    ++embedded;
  }
  return embedded;
}

}  // namespace rt::viz
