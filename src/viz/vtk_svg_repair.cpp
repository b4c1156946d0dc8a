#include "viz/vtk_svg_repair.h"

#include <vtkSmartPointer.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace rt::viz {
namespace {

void replaceAll(std::string& svg, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = svg.find(from, at)) != std::string::npos; at += to.size())
    svg.replace(at, from.size(), to);
}

// Passes the value of every `name` attribute through `rewrite`.
template <typename Rewrite>
void rewriteAttribute(std::string& svg, const std::string& name, Rewrite rewrite) {
  const std::string attribute = name + "=\"";
  for (std::size_t at = 0; (at = svg.find(attribute, at)) != std::string::npos;) {
    at += attribute.size();
    const std::size_t end = svg.find('"', at);
    if (end == std::string::npos) return;
    std::string value = svg.substr(at, end - at);
    rewrite(value);
    svg.replace(at, end - at, value);
    at += value.size();
  }
}

// vtkSVGExporter clips a chart's plotted lines with a <g> that has both a transform (data to page) and a
// clip-path whose rectangle is in page units. SVG applies the clip in the group's own, transformed, units,
// so browsers (and the book's PDF) clip every line away. Splitting the group in two, the clip outside and the
// transform inside, clips in page units as the exporter meant.
// The "</g>" that closes the group whose content starts at `from`, or npos.
std::size_t matchingGroupEnd(const std::string& svg, std::size_t from) {
  int depth = 1;
  for (std::size_t at = from; (at = svg.find('<', at)) != std::string::npos; ++at) {
    if (svg.compare(at, 4, "</g>") == 0 && --depth == 0) return at;
    if (svg.compare(at, 3, "<g ") == 0 || svg.compare(at, 3, "<g>") == 0) ++depth;
  }
  return std::string::npos;
}

void clipInPageUnits(std::string& svg) {
  const std::string open = "<g transform=\"";
  for (std::size_t at = 0; (at = svg.find(open, at)) != std::string::npos;) {
    const std::size_t tagEnd = svg.find('>', at);
    const std::size_t clip = svg.find("\" clip-path=\"", at);
    const std::size_t close = tagEnd == std::string::npos ? tagEnd : matchingGroupEnd(svg, tagEnd + 1);
    if (tagEnd == std::string::npos || clip == std::string::npos || clip > tagEnd ||
        close == std::string::npos) {
      at += open.size();
      continue;
    }
    const std::string transform = svg.substr(at + 3, clip + 1 - (at + 3));   // transform="..."
    const std::string clipPath = svg.substr(clip + 2, tagEnd - (clip + 2));  // clip-path="..."
    svg.replace(close, 4, "</g></g>");
    const std::string replacement = "<g " + clipPath + "><g " + transform + ">";
    svg.replace(at, tagEnd + 1 - at, replacement);
    at += replacement.size();
  }
}

// vtkSVGExporter places text with alignment-baseline, which SVG applies to <tspan> but not to <text>, and
// with the value "top", which SVG does not have: a title meant to hang from the top edge is drawn above it,
// outside the picture, and tick labels meant to hang under their axis stand on it. Every viewer moves text
// by dy (dominant-baseline, the other way, is unknown to librsvg, the SVG library of most Linux desktops):
// the baseline goes down by the height of capitals for "top", by half of it for "central", and up by the
// depth of descenders for "bottom", VTK's boxes of the glyphs.
void placeTextOnItsBaseline(std::string& svg) {
  const std::pair<const char*, const char*> baselines[] = {
      {"top", "0.72em"}, {"central", "0.36em"}, {"bottom", "-0.2em"}};
  for (const auto& [vtk, shift] : baselines)
    replaceAll(svg, std::string("alignment-baseline=\"") + vtk + "\"", std::string("dy=\"") + shift + "\"");
}

// vtkSVGExporter writes VTK's font size, which VTK draws as pixels (its text renderer works at 72 dpi), in
// points: every text is a third larger than VTK laid it out, wider than the room left for it.
void sizeTextInPixels(std::string& svg) {
  rewriteAttribute(svg, "font-size", [](std::string& size) {
    if (size.size() > 2 && size.compare(size.size() - 2, 2, "pt") == 0)
      size.replace(size.size() - 2, 2, "px");
  });
}

// vtkSVGExporter writes right- and left-justified text as text-anchor="right" and "left", which SVG does not
// have (start, middle, end): viewers fall back to "start", and the tick labels of a left axis, which end at
// the axis, then start there and run over it and into the plot.
void anchorTextAsSvgSaysIt(std::string& svg) {
  replaceAll(svg, "text-anchor=\"right\"", "text-anchor=\"end\"");
  replaceAll(svg, "text-anchor=\"left\"", "text-anchor=\"start\"");
}

// vtkSVGExporter turns text by VTK's angle (counter-clockwise, y up) as rotate(angle) in SVG, whose y runs
// down: the text turns the other way. A left axis's title then reads downwards, and its glyphs, which VTK
// stands left of the anchor, stand right of it, on the tick labels.
void turnTextAsVtkDrewIt(std::string& svg) {
  for (std::size_t at = 0; (at = svg.find("<text ", at)) != std::string::npos;) {
    const std::size_t tagEnd = svg.find('>', at);
    if (tagEnd == std::string::npos) return;
    const std::size_t rotate = svg.find("rotate(", at);
    if (rotate == std::string::npos || rotate > tagEnd) {
      at = tagEnd;
      continue;
    }
    const std::size_t angleAt = rotate + 7;
    char* end = nullptr;
    const double angle = std::strtod(svg.c_str() + angleAt, &end);
    const auto angleEnd = static_cast<std::size_t>(end - svg.c_str());
    if (angleEnd == angleAt || angleEnd > tagEnd) {
      at = tagEnd;
      continue;
    }
    char turned[32];
    std::snprintf(turned, sizeof turned, "%g", angle == 0 ? 0.0 : -angle);
    svg.replace(angleAt, angleEnd - angleAt, turned);
    at = svg.find('>', at);
  }
}

// vtkSVGExporter names the font VTK drew with (its built-in "URW Gothic L"), which viewers seldom have: a
// browser then falls back to its default, a serif. The generic family after it keeps the text sans serif.
void fallBackToSansSerif(std::string& svg) {
  rewriteAttribute(svg, "font-family", [](std::string& family) {
    if (family.find(',') == std::string::npos) family = "'" + family + "', sans-serif";
  });
}

// The text of an element as VTK had it: entities undone, the layout's white space around it dropped.
std::string plainText(std::string text) {
  const std::pair<const char*, const char*> entities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [entity, character] : entities) replaceAll(text, entity, character);
  const std::size_t first = text.find_first_not_of(" \n\t");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \n\t") + 1 - first);
}

// Viewers draw text in the fonts they have, mostly wider than the sans serif VTK measured it with (DejaVu
// Sans on Debian): a tick label then reaches into the axis title beside it. textLength gives each text the
// width VTK laid it out for, whatever the font. The figures' text is VTK's Arial (styleText, the charts'
// defaults).
void fitTextToItsWidth(std::string& svg) {
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  if (!renderer) return;
  auto property = vtkSmartPointer<vtkTextProperty>::New();
  property->SetFontFamilyToArial();
  for (std::size_t at = 0; (at = svg.find("<text ", at)) != std::string::npos;) {
    const std::size_t tagEnd = svg.find('>', at);
    const std::size_t close = tagEnd == std::string::npos ? tagEnd : svg.find("</text>", tagEnd);
    if (close == std::string::npos) return;
    const std::string tag = svg.substr(at, tagEnd - at);
    const std::string text = plainText(svg.substr(tagEnd + 1, close - tagEnd - 1));
    const std::size_t size = tag.find("font-size=\"");
    at = close;
    if (text.empty() || text.find_first_of("<\n") != std::string::npos || size == std::string::npos) continue;
    property->SetFontSize(static_cast<int>(std::lround(std::strtod(tag.c_str() + size + 11, nullptr))));
    property->SetBold(tag.find("font-weight=\"bold\"") != std::string::npos);
    int box[4];
    if (!renderer->GetBoundingBox(property.Get(), vtkStdString(text), box, 72) || box[1] < box[0]) continue;
    const std::string length =
        " textLength=\"" + std::to_string(box[1] - box[0] + 1) + "\" lengthAdjust=\"spacingAndGlyphs\"";
    svg.insert(tagEnd, length);
    at = close + length.size();
  }
}

}  // namespace

void repairVtkSvg(std::string& svg) {
  clipInPageUnits(svg);
  anchorTextAsSvgSaysIt(svg);
  turnTextAsVtkDrewIt(svg);
  placeTextOnItsBaseline(svg);
  sizeTextInPixels(svg);
  fitTextToItsWidth(svg);
  fallBackToSansSerif(svg);
}

}  // namespace rt::viz
