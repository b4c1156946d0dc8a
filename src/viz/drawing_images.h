// The pixel images of a Drawing (Drawing::Kind::Image): as VTK image data for the context painter, and
// written into an exported SVG. vtkSVGExporter (VTK 9.1) refers to each image with <use href="#...">
// but leaves out the definitions it refers to, so every picture inside a 2D figure came out as an empty
// frame in the SVG and in the book made from it; the images are put in as <image> elements instead.
#pragma once

#include <vtkSmartPointer.h>

#include <string>

#include "viz/drawing.h"

class vtkImageData;

namespace rt::viz {

// The shape's pixels as RGB image data (VTK's rows run bottom-up).
vtkSmartPointer<vtkImageData> imageDataOf(const Drawing::Shape& image);

// Replaces, in order, each reference to an embedded image in `svg` (as the exporter wrote it for
// `drawing`) with the drawing's next image shape as a PNG <image> at its place. Returns how many.
int embedDrawingImages(std::string& svg, const Drawing& drawing);

}  // namespace rt::viz
