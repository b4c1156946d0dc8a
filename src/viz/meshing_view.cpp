#include "viz/meshing_view.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/polygon.h"
#include "viz/vtk_geometry.h"
#include "viz/vtk_render.h"
#include "viz/vtk_views.h"

namespace rt::viz {
namespace {

bool containsPoint(const Polygon& polygon, const Vec3& point, const Vec3& normal, double tolerance) {
  const Vec3 n = newellNormal(polygon).normalized();
  if (n.dot(normal) < 0.999 || std::abs(n.dot(point - polygon[0])) > tolerance) return false;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3& a = polygon[k];
    const Vec3& b = polygon[(k + 1) % polygon.size()];
    if (n.dot((b - a).cross(point - a)) < -tolerance * (b - a).norm()) return false;
  }
  return true;
}

// Lines with one colour per segment.
vtkSmartPointer<vtkActor> colouredLinesActor(const std::vector<Vec3>& ends, const std::vector<Rgb8>& colours,
                                             double width, double opacity) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
  scalars->SetNumberOfComponents(3);
  for (std::size_t k = 0; k + 1 < ends.size(); k += 2) {
    lines->InsertNextCell(2);
    for (std::size_t j = 0; j < 2; ++j)
      lines->InsertCellPoint(points->InsertNextPoint(ends[k + j].x(), ends[k + j].y(), ends[k + j].z()));
    scalars->InsertNextTypedTuple(colours[k / 2].data());
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  data->GetCellData()->SetScalars(scalars);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

// A point moved towards the camera by `distance`: lines drawn on a surface stay in front of it.
Vec3 towards(const Vec3& point, const Camera& camera, double distance) {
  return point + distance * (camera.position - point).normalized();
}

double sceneSize(const Mesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  return box.isEmpty() ? 1.0 : std::max(box.diagonal().norm(), 1e-9);
}

void addColourBar(vtkRenderWindow* window, ColourMap map, double min, double max, bool logScale,
                  const std::string& title, int labels, const char* format, int height, double scale) {
  auto barRenderer = vtkSmartPointer<vtkRenderer>::New();
  barRenderer->SetViewport(0.78, 0.0, 1.0, 1.0);
  barRenderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  auto bar = makeColourBar(map, min, max, logScale, title, readableFontSize(height, scale, 0.024));
  bar->SetPosition(0.08, 0.08);
  bar->SetPosition2(0.84, 0.8);
  bar->SetNumberOfLabels(labels);
  if (format) bar->SetLabelFormat(format);
  barRenderer->AddViewProp(bar);
  window->AddRenderer(barRenderer);
}

}  // namespace

LinkColouring linkColouringFromName(const std::string& name) {
  if (name == "level") return LinkColouring::Level;
  if (name == "formfactor") return LinkColouring::FormFactor;
  throw std::invalid_argument("unknown link colouring '" + name + "' (level, formfactor)");
}

std::vector<int> linksGatheredBy(const RefinedSolution& solution, int element) {
  if (element < 0 || static_cast<std::size_t>(element) >= solution.mesh.size())
    throw std::invalid_argument("element " + std::to_string(element) + " is not in the mesh of " +
                                std::to_string(solution.mesh.size()) + " elements");
  const Element& leaf = solution.mesh.elements[static_cast<std::size_t>(element)];
  const double tolerance = 1e-6 * sceneSize(solution.mesh);
  std::vector<int> out;
  for (std::size_t k = 0; k < solution.links.size(); ++k)
    if (solution.links[k].to.size() >= 3 &&
        containsPoint(solution.links[k].to, leaf.centroid, leaf.normal, tolerance))
      out.push_back(static_cast<int>(k));
  return out;
}

void writeLinksFigure(const RefinedSolution& solution, const Camera& camera, const LinksViewOptions& options,
                      const std::string& path) {
  figureFormatOf(path);
  if (solution.links.empty())
    throw std::invalid_argument("the links view needs a hierarchical solution (it has no links)");
  if (solution.elementLevel.size() != solution.mesh.size())
    throw std::invalid_argument("the solution has no level for each element");
  std::vector<int> shown;
  if (options.element >= 0) {
    shown = linksGatheredBy(solution, options.element);
  } else {
    shown.resize(solution.links.size());
    for (std::size_t k = 0; k < shown.size(); ++k) shown[k] = static_cast<int>(k);
  }
  const double scale = options.size.fontScale();
  int maxLevel = 1;
  for (int level : solution.elementLevel) maxLevel = std::max(maxLevel, level);
  for (const HierarchyLink& link : solution.links)
    maxLevel = std::max({maxLevel, link.fromLevel, link.toLevel});

  // The leaves by depth, through the scene view's scalar colouring (one colour bar: the levels).
  SceneViewOptions sceneOptions;
  sceneOptions.colouring = SceneColouring::Scalar;
  sceneOptions.image.width = options.size.width;
  sceneOptions.image.height = options.size.height;
  sceneOptions.image.showEdges = true;
  sceneOptions.dpi = options.size.dpi;
  sceneOptions.legend.map = options.map;
  sceneOptions.legend.min = 0;
  sceneOptions.legend.max = maxLevel;
  sceneOptions.highlightElement = options.element;
  SceneViewData data;
  data.scalar = Eigen::Map<const Eigen::VectorXi>(solution.elementLevel.data(),
                                                  static_cast<Eigen::Index>(solution.elementLevel.size()))
                    .cast<double>();
  const ScenePaint paint = paintScene(solution.mesh, data, sceneOptions);

  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  const double viewport[4] = {0.0, 0.0, 0.78, 1.0};
  vtkSmartPointer<vtkRenderer> renderer =
      makeSceneRenderer(solution.mesh, camera, paint, sceneOptions, options.size.height, viewport);
  window->AddRenderer(renderer);
  enableDepthPeeling(window, renderer);  // hundreds of translucent lines cross each other

  // Link lines from node centre to node centre, a little off the surfaces so that they are not buried.
  double minF = std::numeric_limits<double>::infinity(), maxF = 0;
  for (int k : shown)
    if (const double f = solution.links[static_cast<std::size_t>(k)].formFactor; f > 0) {
      minF = std::min(minF, f);
      maxF = std::max(maxF, f);
    }
  if (!(maxF > 0)) minF = maxF = 1;
  minF = std::max(minF, maxF * 1e-6);  // six decades are enough to read
  const double lift = 0.004 * sceneSize(solution.mesh);
  std::vector<Vec3> ends;
  std::vector<Rgb8> colours;
  for (int k : shown) {
    const HierarchyLink& link = solution.links[static_cast<std::size_t>(k)];
    if (link.from.size() < 3 || link.to.size() < 3) continue;
    ends.push_back(towards(polygonCentroid(link.from), camera, lift));
    ends.push_back(towards(polygonCentroid(link.to), camera, lift));
    const double t = options.colouring == LinkColouring::Level
                         ? static_cast<double>(std::max(link.fromLevel, link.toLevel)) / maxLevel
                         : (std::log10(std::max(link.formFactor, minF)) - std::log10(minF)) /
                               std::max(std::log10(maxF) - std::log10(minF), 1e-12);
    colours.push_back(sampleColourMap(options.map, t));
  }
  // Many links: thin and translucent; a few (one element's): bold.
  const std::size_t count = ends.size() / 2;
  const bool few = count <= 60;
  const double opacity = few ? 0.95 : count <= 400 ? 0.6 : 0.3;
  renderer->AddActor(colouredLinesActor(ends, colours,
                                        (few            ? 3.0
                                         : count <= 400 ? 1.5
                                                        : 1.0) *
                                            scale,
                                        opacity));
  if (few) {
    std::vector<Vec3> nodes;
    for (std::size_t k = 0; k < ends.size(); k += 2) nodes.push_back(ends[k]);
    renderer->AddActor(pointsActor(nodes, {0.835, 0.369, 0.0}, 0.006 * sceneSize(solution.mesh)));
  }
  renderer->ResetCameraClippingRange();

  std::string caption = options.caption;
  if (caption.empty()) {
    char text[240];
    if (options.element >= 0)
      std::snprintf(text, sizeof text, "element %d gathers over %zu links (dots: the nodes it gathers from)",
                    options.element, ends.size() / 2);
    else
      std::snprintf(text, sizeof text, "hierarchy: %zu leaves by depth, %zu links", solution.mesh.size(),
                    ends.size() / 2);
    caption = text;
  }
  renderer->AddViewProp(
      makeCaption(caption, readableFontSize(options.size.height, scale, 0.028), options.size.width));
  if (options.colouring == LinkColouring::Level)
    addColourBar(window, options.map, 0, maxLevel, false, "level\n(leaves,\nlinks)", maxLevel + 1, "%.0f",
                 options.size.height, scale);
  else
    addColourBar(window, options.map, minF, maxF, true, "link F\n(leaves:\nlevel)", 5, nullptr,
                 options.size.height, scale);
  writeRenderWindow(window, path, options.size.dpi);
}

CriticalLineCounts countCriticalLines(const RefinedSolution& solution) {
  CriticalLineCounts counts;
  for (const CriticalSegment& s : solution.discontinuities)
    (s.extremal ? counts.extremal : counts.interior)++;
  return counts;
}

namespace {

// The refined mesh's radiosity with its element edges light and thin, in a window of the figure's size: the
// lines or points drawn over it are what the meshing views are about.
vtkSmartPointer<vtkRenderer> refinedMeshRenderer(const RefinedSolution& solution, const Camera& camera,
                                                 const DiscontinuityViewOptions& options,
                                                 vtkRenderWindow* window) {
  SceneViewOptions sceneOptions;
  sceneOptions.image = options.image;
  sceneOptions.image.width = options.size.width;
  sceneOptions.image.height = options.size.height;
  sceneOptions.image.showEdges = true;
  sceneOptions.edgeColour = {0.55, 0.55, 0.58};
  sceneOptions.edgeWidth = 0.75;
  sceneOptions.dpi = options.size.dpi;
  SceneViewData data;
  data.B = solution.B;
  const ScenePaint paint = paintScene(solution.mesh, data, sceneOptions);
  const double full[4] = {0, 0, 1, 1};
  vtkSmartPointer<vtkRenderer> renderer =
      makeSceneRenderer(solution.mesh, camera, paint, sceneOptions, options.size.height, full);
  window->AddRenderer(renderer);
  return renderer;
}

// A line of the key at the foot of a figure, in (a readable shade of) the colour of what it names.
void addKeyLine(vtkRenderer* renderer, const std::string& text, const Colour& colour, int font, double x) {
  auto key = makeCaption(text, font);
  key->GetTextProperty()->SetColor(colour[0], colour[1], colour[2]);
  key->GetTextProperty()->SetBackgroundColor(0.12, 0.12, 0.13);
  key->GetTextProperty()->SetBackgroundOpacity(0.8);
  key->GetPositionCoordinate()->SetValue(x, 0.06);
  renderer->AddViewProp(key);
}

}  // namespace

void writeDiscontinuityFigure(const RefinedSolution& solution, const Camera& camera,
                              const DiscontinuityViewOptions& options, const std::string& path) {
  figureFormatOf(path);
  const double scale = options.size.fontScale();
  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  vtkSmartPointer<vtkRenderer> renderer = refinedMeshRenderer(solution, camera, options, window);

  const double lift = 0.002 * sceneSize(solution.mesh);
  std::vector<Vec3> extremal, interior;
  for (const CriticalSegment& s : solution.discontinuities) {
    std::vector<Vec3>& out = s.extremal ? extremal : interior;
    out.push_back(towards(s.a, camera, lift));
    out.push_back(towards(s.b, camera, lift));
  }
  const Colour vermillion{0.835, 0.369, 0.0}, sky{0.337, 0.706, 0.914};
  if (!interior.empty()) renderer->AddActor(linesActor(interior, sky, 2.0 * scale));
  if (!extremal.empty()) renderer->AddActor(linesActor(extremal, vermillion, 3.0 * scale));
  renderer->ResetCameraClippingRange();

  const int font = readableFontSize(options.size.height, scale, 0.028);
  std::string caption = options.caption;
  if (caption.empty()) {
    char text[240];
    std::snprintf(text, sizeof text, "discontinuity mesh: %zu elements, %zu critical segments",
                  solution.mesh.size(), solution.discontinuities.size());
    caption = text;
  }
  renderer->AddViewProp(makeCaption(caption, font, options.size.width));
  // The key at the bottom, in the lines' own colours.
  const CriticalLineCounts counts = countCriticalLines(solution);
  const int keyFont = static_cast<int>(0.85 * font);
  addKeyLine(renderer, "umbra / penumbra boundary (" + std::to_string(counts.extremal) + ")",
             {vermillion[0] * 1.15, vermillion[1] * 1.15, vermillion[2]}, keyFont, 0.3);
  addKeyLine(renderer, "inside the penumbra (" + std::to_string(counts.interior) + ")", sky, keyFont, 0.75);
  writeRenderWindow(window, path, options.size.dpi);
}

std::string writeTVertexFigure(const RefinedSolution& solution, const Camera& camera,
                               const DiscontinuityViewOptions& options, const std::string& path) {
  figureFormatOf(path);
  const double scale = options.size.fontScale();
  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  vtkSmartPointer<vtkRenderer> renderer = refinedMeshRenderer(solution, camera, options, window);

  // Each T-vertex as a dot, and the whole long edge it splits, which the large element alone interpolates.
  const double size = sceneSize(solution.mesh);
  std::vector<Vec3> edges, dots;
  for (const TVertex& v : solution.tVertices) {
    edges.push_back(towards(solution.mesh.vertices[v.edgeStart], camera, 0.002 * size));
    edges.push_back(towards(solution.mesh.vertices[v.edgeEnd], camera, 0.002 * size));
    dots.push_back(towards(solution.mesh.vertices[v.vertex], camera, 0.004 * size));
  }
  const Colour vermillion{0.835, 0.369, 0.0}, sky{0.337, 0.706, 0.914};
  if (!edges.empty()) renderer->AddActor(linesActor(edges, sky, 2.5 * scale));
  if (!dots.empty()) renderer->AddActor(pointsActor(dots, vermillion, 0.006 * size));
  renderer->ResetCameraClippingRange();

  const int font = readableFontSize(options.size.height, scale, 0.028);
  const std::string caption = options.caption.empty()
                                  ? std::to_string(solution.mesh.size()) + " elements, " +
                                        std::to_string(solution.tVertices.size()) + " T-vertices"
                                  : options.caption;
  renderer->AddViewProp(makeCaption(caption, font, options.size.width));
  const int keyFont = static_cast<int>(0.85 * font);
  addKeyLine(renderer, "T-vertex", {vermillion[0] * 1.15, vermillion[1] * 1.15, vermillion[2]}, keyFont, 0.3);
  addKeyLine(renderer, "the long edge it splits", sky, keyFont, 0.7);
  writeRenderWindow(window, path, options.size.dpi);
  return caption;
}

}  // namespace rt::viz
