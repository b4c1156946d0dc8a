#include "viz/image_png.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace rt::viz {

void writeRgbImagePng(const RgbImage& image, double scale, const std::string& path) {
  // vtkPNGWriter reports a path it cannot open only through its error observer: try it first.
  if (!std::ofstream(path, std::ios::binary)) throw std::runtime_error(path + ": cannot write the image");
  vtkNew<vtkImageData> data;
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      // VTK's rows go upwards; the image's top row comes first.
      auto* pixel = static_cast<unsigned char*>(data->GetScalarPointer(x, image.height - 1 - y, 0));
      for (int c = 0; c < 3; ++c) {
        const double v = std::clamp(image.at(x, y)(c) * scale, 0.0, 1.0);
        const double srgb = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
        pixel[c] = static_cast<unsigned char>(std::lround(255 * srgb));
      }
    }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  writer->Write();
}

}  // namespace rt::viz
