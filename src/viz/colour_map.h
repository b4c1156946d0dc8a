// Colour maps for scalar views: perceptually uniform and readable with colour-vision deficiencies (viridis,
// cividis), a grey ramp, and a qualitative palette (Okabe-Ito) for categories such as element ids or solver
// curves.
#pragma once

#include <string>

#include "viz/display_pipeline.h"

namespace rt::viz {

enum class ColourMap { Viridis, Cividis, Grey };

ColourMap colourMapFromName(
    const std::string& name);  // "viridis", "cividis", "grey"; throws std::invalid_argument
std::string toString(ColourMap map);

// t in [0,1] (clamped); NaN gives a neutral grey so that missing values stay visible.
Rgb8 sampleColourMap(ColourMap map, double t);
// Same colour as doubles in [0,1] (for VTK lookup tables and pens).
std::array<double, 3> sampleColourMapUnit(ColourMap map, double t);

// The eight Okabe-Ito colours (black last); index taken modulo 8.
Rgb8 qualitativeColour(int index);
// A colour per category that keeps neighbouring indices apart: cycles through the palette with lightness
// variants.
Rgb8 categoryColour(int index);

}  // namespace rt::viz
