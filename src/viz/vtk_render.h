// VTK-facing helpers shared by the views: offscreen windows, writing what a window shows in every figure
// format, text and colour-bar actors with sizes readable on a projector. Includes VTK: used by viz sources
// and the app only.
#pragma once

#include <vtkSmartPointer.h>

#include <functional>
#include <string>
#include <vector>

#include "viz/colour_map.h"
#include "viz/figure_output.h"

class vtkContextView;
class vtkRenderWindow;
class vtkRenderer;
class vtkTextActor;
class vtkScalarBarActor;
class vtkTextProperty;

namespace rt::viz {

// The neutral grey every 3D view uses as background (figures are printed and projected: no pure black or
// white).
inline constexpr double kBackground[3] = {0.32, 0.32, 0.34};

// An offscreen window of the given pixel size (needs an X server: Xvfb in tests and scripts).
vtkSmartPointer<vtkRenderWindow> makeOffscreenWindow(int width, int height);

// From now on, the calling thread keeps the offscreen window of the figure it drew last for its next one,
// emptied of that figure's renderers: its OpenGL context with the shaders compiled for it. A new window
// costs its context and the compilation of every shader its first frame uses, most of a 3D figure's time
// in a software renderer. For a thread that draws figures one after another (the app's figure thread);
// while that window is still held (a figure drawing another inside it), a new one is made as before. The
// window goes when the thread ends, its context current there.
void keepOffscreenWindowsOnThisThread();

// Translucent surfaces drawn in the order of their actors look wrong where they overlap (a far face painted
// over a near one). Depth peeling sorts the fragments per pixel; it needs alpha bit planes and no
// multisampling. Call after the renderer is added to the window.
void enableDepthPeeling(vtkRenderWindow* window, vtkRenderer* renderer);

// The renderer of a 3D construction with glass parts (the Nusselt hemisphere, the solid angle's sphere): the
// background grey, FXAA, added to `window`, with depth peeling.
vtkSmartPointer<vtkRenderer> addConstructionRenderer(vtkRenderWindow* window);

// Renders the window and reads its RGB pixels (bottom row first).
std::vector<unsigned char> captureRgb(vtkRenderWindow* window, int& width, int& height);

// 3D views: PNG; PDF and SVG embed the rendered image (there is no vector form of a shaded 3D scene here).
void writeRenderWindow(vtkRenderWindow* window, const std::string& path, double dpi);

// 2D views built from context items (charts, matrix, hemicube faces, Nusselt disk): PNG, or true vectors in
// SVG/PDF. VTK draws SVG text as paths (viewers disagree on text sizes), so an SVG also gets `title` and
// `description` (e.g. the words on the figure) as its <title> and <desc>: searchable and read by screen
// readers. `amendSvg`, where given, edits the SVG's text before it is written (e.g. to embed pictures).
void writeContextView(vtkContextView* view, const std::string& path, const std::string& title = {},
                      const std::string& description = {},
                      const std::function<void(std::string& svg)>& amendSvg = {});

// Font size in pixels that stays readable on a projector: a fraction of the figure height, scaled by dpi
// / 96.
int readableFontSize(int figureHeight, double fontScale, double fraction = 0.032);
void styleText(vtkTextProperty* text, int fontSize, bool bold = false);

// A caption at the top centre of a 3D view. With `figureWidth` (pixels), lines too long for the figure are
// wrapped at spaces so that nothing is cut at the edges.
vtkSmartPointer<vtkTextActor> makeCaption(const std::string& text, int fontSize, int figureWidth = 0);

// A vertical colour bar for a scalar field shown through `map` over [min, max] (log10 when logScale).
vtkSmartPointer<vtkScalarBarActor> makeColourBar(ColourMap map, double min, double max, bool logScale,
                                                 const std::string& title, int fontSize);

}  // namespace rt::viz
