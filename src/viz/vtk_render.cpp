#include "viz/vtk_render.h"

#include "lesson/markdown_html.h"
#include "viz/display_check.h"
#include "viz/vtk_svg_repair.h"

#include <vtkContextView.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkMathTextFreeTypeTextRenderer.h>
#include <vtkObjectFactory.h>
#include <vtkPDFExporter.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkSVGExporter.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace rt::viz {
namespace {

// VTK 9.1 takes every string with an unescaped '|' for MathText (a column separator): "|K_ij|" on a colour
// bar, "|KB - E| / |E|" on an axis. Without matplotlib FreeType draws such text all the same, except in PDF:
// vtkPDFContextDevice2D::DrawString draws it as outlines (no longer searchable) and strokes a red rectangle
// beside it, a debugging aid left in VTK. The figures' text is never MathText, and this renderer says so for
// every string, to every device. It takes VTK's place during static initialisation, before any text is
// drawn: text actors keep the renderer they were built with.
class PlainTextRenderer : public vtkMathTextFreeTypeTextRenderer {
 public:
  static PlainTextRenderer* New();
  int DetectBackend(const vtkStdString&) override { return FreeType; }
  int DetectBackend(const vtkUnicodeString&) override { return FreeType; }  // the SVG device asks this one

  static bool install() {
    PlainTextRenderer* renderer = PlainTextRenderer::New();
    SetInstance(renderer);
    renderer->Delete();
    return true;
  }

  vtkTypeMacro(PlainTextRenderer, vtkMathTextFreeTypeTextRenderer)
};
vtkStandardNewMacro(PlainTextRenderer);
[[maybe_unused]] const bool plainTextInstalled = PlainTextRenderer::install();

std::string base64(const unsigned char* data, std::size_t size) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const unsigned v =
        (data[i] << 16) | ((i + 1 < size ? data[i + 1] : 0) << 8) | (i + 2 < size ? data[i + 2] : 0);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += i + 1 < size ? alphabet[(v >> 6) & 63] : '=';
    out += i + 2 < size ? alphabet[v & 63] : '=';
  }
  return out;
}

vtkSmartPointer<vtkImageData> grab(vtkRenderWindow* window) {
  window->Render();
  auto filter = vtkSmartPointer<vtkWindowToImageFilter>::New();
  // The frame just rendered is read as it is: the filter's own render would draw it a second time (a
  // construction figure's depth peeling costs a tenth of a second per frame in a software renderer).
  filter->ShouldRerenderOff();
  filter->SetInput(window);
  filter->SetInputBufferTypeToRGB();
  filter->ReadFrontBufferOff();
  filter->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(filter->GetOutput());
  return image;
}

void writePng(vtkImageData* image, const std::string& path) {
  std::ofstream probe(path,
                      std::ios::binary);  // vtkPNGWriter only reports failures through its error observer
  if (!probe) throw std::runtime_error(path + ": cannot write the file");
  probe.close();
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0) throw std::runtime_error(path + ": cannot write the PNG");
}

void writeRasterSvg(vtkImageData* image, const std::string& path) {
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->WriteToMemoryOn();
  writer->SetInputData(image);
  writer->Write();
  vtkUnsignedCharArray* png = writer->GetResult();
  int dims[3];
  image->GetDimensions(dims);
  std::ofstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot write the file");
  file << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
       << "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" << dims[0] << "\" height=\"" << dims[1]
       << "\" viewBox=\"0 0 " << dims[0] << " " << dims[1] << "\">\n<image width=\"" << dims[0]
       << "\" height=\"" << dims[1] << "\" xlink:href=\"data:image/png;base64,"
       << base64(png->GetPointer(0), static_cast<std::size_t>(png->GetNumberOfValues())) << "\"/>\n</svg>\n";
  if (!file) throw std::runtime_error(path + ": cannot write the SVG");
}

thread_local bool keepWindows = false;
thread_local vtkSmartPointer<vtkRenderWindow> keptWindow;

// Whether anyone but this thread's store holds `window` (a figure still drawing in it): a context view's
// interactor and the window hold each other, which is no figure's use.
bool inUse(vtkRenderWindow* window) {
  vtkRenderWindowInteractor* interactor = window->GetInteractor();
  const int cycle = interactor && interactor->GetRenderWindow() == window ? 1 : 0;
  return window->GetReferenceCount() > 1 + cycle;
}

// The kept window as a new one would be: no renderer, no interactor, the figure's size and the settings
// makeOffscreenWindow gives. Its context is current on this thread, where its renderers release their
// graphics resources.
void empty(vtkRenderWindow* window, int width, int height) {
  vtkRendererCollection* renderers = window->GetRenderers();
  while (vtkRenderer* renderer = renderers->GetFirstRenderer()) window->RemoveRenderer(renderer);
  window->SetInteractor(nullptr);
  window->SetSize(width, height);
  window->SetAlphaBitPlanes(0);
  window->SetMultiSamples(0);
}

}  // namespace

void keepOffscreenWindowsOnThisThread() {
  keepWindows = true;
}

vtkSmartPointer<vtkRenderWindow> makeOffscreenWindow(int width, int height) {
  if (width < 16 || height < 16 || width > 16384 || height > 16384)
    throw std::invalid_argument("figure size " + std::to_string(width) + " x " + std::to_string(height) +
                                " is outside 16..16384 pixels");
  if (keepWindows && keptWindow && !inUse(keptWindow)) {
    empty(keptWindow, width, height);
    return keptWindow;
  }
  requireDisplay();
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->SetMultiSamples(0);  // FXAA on the renderers instead: MSAA is unreliable in offscreen framebuffers
  if (keepWindows && !keptWindow) keptWindow = window;
  return window;
}

void enableDepthPeeling(vtkRenderWindow* window, vtkRenderer* renderer) {
  window->SetAlphaBitPlanes(1);
  window->SetMultiSamples(0);
  renderer->SetUseDepthPeeling(1);
  renderer->SetMaximumNumberOfPeels(12);
  renderer->SetOcclusionRatio(0.0);  // exact: peel until no fragment is left (bounded by the peel count)
}

vtkSmartPointer<vtkRenderer> addConstructionRenderer(vtkRenderWindow* window) {
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  renderer->UseFXAAOn();
  window->AddRenderer(renderer);
  enableDepthPeeling(window, renderer);
  return renderer;
}

std::vector<unsigned char> captureRgb(vtkRenderWindow* window, int& width, int& height) {
  vtkSmartPointer<vtkImageData> image = grab(window);
  int dims[3];
  image->GetDimensions(dims);
  width = dims[0];
  height = dims[1];
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!scalars) throw std::runtime_error("the render window gave no pixels");
  const unsigned char* begin = scalars->GetPointer(0);
  return {begin, begin + static_cast<std::size_t>(width) * height * 3};
}

void writeRenderWindow(vtkRenderWindow* window, const std::string& path, double dpi) {
  const FigureFormat format = figureFormatOf(path);
  if (format == FigureFormat::Pdf) {
    int width = 0, height = 0;
    const std::vector<unsigned char> rgb = captureRgb(window, width, height);
    writeRasterPdf(rgb.data(), width, height, dpi, path);
    return;
  }
  vtkSmartPointer<vtkImageData> image = grab(window);
  if (format == FigureFormat::Png)
    writePng(image, path);
  else
    writeRasterSvg(image, path);
}

namespace {

// vtkSVGExporter writes "VTK Exported Scene" as both the <title> and the <desc>: put the figure's own there.
void tidySvg(const std::string& path, const std::string& title, const std::string& description,
             const std::function<void(std::string& svg)>& amendSvg) {
  std::string svg;
  {
    std::ifstream in(path, std::ios::binary);
    svg.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string placeholder = "VTK Exported Scene";
  const std::string replacements[2] = {lesson::escapeHtml(title.empty() ? description : title),
                                       lesson::escapeHtml(description.empty() ? title : description)};
  std::size_t at = 0;
  for (const std::string& replacement : replacements) {
    if (title.empty() && description.empty()) break;
    at = svg.find(placeholder, at);
    if (at == std::string::npos) break;
    svg.replace(at, placeholder.size(), replacement);
    at += replacement.size();
  }
  repairVtkSvg(svg);
  if (amendSvg) amendSvg(svg);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << svg;
  if (!out) throw std::runtime_error(path + ": cannot write the file");
}

}  // namespace

void writeContextView(vtkContextView* view, const std::string& path, const std::string& title,
                      const std::string& description, const std::function<void(std::string& svg)>& amendSvg) {
  const FigureFormat format = figureFormatOf(path);
  vtkRenderWindow* window = view->GetRenderWindow();
  // A chart lays itself out in its first frame and is drawn in that layout in the next (grab's).
  window->Render();
  if (format == FigureFormat::Png) {
    writePng(grab(window), path);
    return;
  }
  std::ofstream probe(path, std::ios::binary);
  if (!probe) throw std::runtime_error(path + ": cannot write the file");
  probe.close();
  if (format == FigureFormat::Svg) {
    auto exporter = vtkSmartPointer<vtkSVGExporter>::New();
    exporter->SetRenderWindow(window);
    exporter->SetFileName(path.c_str());
    exporter->SetDrawBackground(true);
    // Text as <text>, not as glyph outlines: a reader can search, select and edit the labels of a figure.
    exporter->SetTextAsPath(false);
    exporter->Write();
    tidySvg(path, title, description, amendSvg);
  } else {
    auto exporter = vtkSmartPointer<vtkPDFExporter>::New();
    exporter->SetRenderWindow(window);
    exporter->SetFileName(path.c_str());
    exporter->Write();
  }
  std::ifstream check(path, std::ios::binary | std::ios::ate);
  if (!check || check.tellg() <= 0) throw std::runtime_error(path + ": the exporter wrote nothing");
}

int readableFontSize(int figureHeight, double fontScale, double fraction) {
  return std::max(12, static_cast<int>(std::lround(fraction * figureHeight * std::max(0.25, fontScale))));
}

void styleText(vtkTextProperty* text, int fontSize, bool bold) {
  text->SetFontFamilyToArial();
  text->SetFontSize(fontSize);
  text->SetBold(bold);
  text->SetItalic(false);
  text->SetShadow(false);
  text->SetColor(0.96, 0.96, 0.96);
  // Light text on a dark translucent band: readable over a white furnace wall or a lit floor as well as over
  // the dark background, without hiding the picture under it.
  text->SetBackgroundColor(0.0, 0.0, 0.0);
  text->SetBackgroundOpacity(0.55);
}

namespace {

// Greedy word wrap by an estimated width: bold sans-serif glyphs with spaces average under 0.7 em.
std::string wrapToWidth(const std::string& text, int fontSize, int width) {
  if (width <= 0) return text;
  const auto maxChars = static_cast<std::size_t>(std::max(12.0, 0.92 * width / (0.7 * fontSize)));
  std::string out, line, word;
  auto flushWord = [&] {
    if (word.empty()) return;
    if (!line.empty() && line.size() + 1 + word.size() > maxChars) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    word.clear();
  };
  for (const char c : text) {
    if (c == ' ') {
      flushWord();
    } else if (c == '\n') {
      flushWord();
      out += line + "\n";
      line.clear();
    } else {
      word += c;
    }
  }
  flushWord();
  return out + line;
}

}  // namespace

vtkSmartPointer<vtkTextActor> makeCaption(const std::string& text, int fontSize, int figureWidth) {
  auto caption = vtkSmartPointer<vtkTextActor>::New();
  caption->SetInput(wrapToWidth(text, fontSize, figureWidth).c_str());
  styleText(caption->GetTextProperty(), fontSize, true);
  caption->GetTextProperty()->SetJustificationToCentered();
  caption->GetTextProperty()->SetVerticalJustificationToTop();
  caption->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  caption->GetPositionCoordinate()->SetValue(0.5, 0.975);
  return caption;
}

vtkSmartPointer<vtkScalarBarActor> makeColourBar(ColourMap map, double min, double max, bool logScale,
                                                 const std::string& title, int fontSize) {
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(256);
  if (logScale) {
    min = std::max(min, 1e-300);
    max = std::max(max, min * 10);
    table->SetScaleToLog10();
  }
  table->SetRange(min, max < min ? min : max);
  for (int i = 0; i < 256; ++i) {
    const auto rgb = sampleColourMapUnit(map, i / 255.0);
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  table->Build();
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(table);
  bar->SetTitle(title.c_str());
  bar->SetNumberOfLabels(5);
  bar->SetLabelFormat(logScale ? "%.1e" : "%.3g");
  bar->UnconstrainedFontSizeOn();
  styleText(bar->GetTitleTextProperty(), fontSize, true);
  styleText(bar->GetLabelTextProperty(), static_cast<int>(fontSize * 0.85));
  bar->SetBarRatio(0.25);
  bar->SetPosition(0.84, 0.1);
  bar->SetPosition2(0.15, 0.78);
  bar->SetTextPositionToPrecedeScalarBar();
  bar->SetVerticalTitleSeparation(fontSize);  // keeps the top label clear of the title
  return bar;
}

}  // namespace rt::viz
