#include "viz/walks_view.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <algorithm>
#include <stdexcept>

#include "viz/colour_map.h"
#include "viz/faded_scene.h"
#include "viz/vtk_geometry.h"
#include "viz/vtk_render.h"

namespace rt::viz {
namespace {

// One colour per walk: the Okabe-Ito palette without its black, which marks absorption.
Colour walkColour(std::size_t walk) {
  const Rgb8 c = qualitativeColour(static_cast<int>(walk % 7));
  return {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
}

void checkWalks(const Mesh& mesh, const std::vector<WalksPanel>& panels) {
  if (panels.empty()) throw std::invalid_argument("the walks view needs at least one solver's walks");
  const int n = static_cast<int>(mesh.size());
  for (const WalksPanel& panel : panels)
    for (const RecordedWalk& walk : panel.walks) {
      const bool inside =
          walk.source >= 0 && walk.source < n &&
          std::all_of(walk.landings.begin(), walk.landings.end(), [n](int e) { return e >= 0 && e < n; }) &&
          walk.points.size() == walk.landings.size() + 1;
      if (!inside)
        throw std::invalid_argument("a walk of " + panel.title + " leaves the mesh of " + std::to_string(n) +
                                    " elements");
    }
}

void addWalks(vtkRenderer* renderer, const WalksPanel& panel, double scale) {
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const double size = Vec3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]).norm();
  const double lineWidth = std::max(2.0, 2.5 * scale);
  std::vector<Vec3> absorbedAt;
  for (std::size_t w = 0; w < panel.walks.size(); ++w) {
    const RecordedWalk& walk = panel.walks[w];
    const Colour colour = walkColour(w);
    std::vector<Vec3> segments;
    for (std::size_t k = 0; k + 1 < walk.points.size(); ++k) {
      segments.push_back(walk.points[k]);
      segments.push_back(walk.points[k + 1]);
    }
    if (!segments.empty()) renderer->AddActor(linesActor(segments, colour, lineWidth));
    renderer->AddActor(pointsActor({walk.points.front()}, colour, 0.012 * size));
    const std::vector<Vec3> landings(walk.points.begin() + 1, walk.points.end());
    if (!landings.empty()) renderer->AddActor(pointsActor(landings, colour, 0.006 * size));
    if (walk.end == RecordedWalk::End::Absorbed && !landings.empty()) absorbedAt.push_back(landings.back());
  }
  if (!absorbedAt.empty()) renderer->AddActor(pointsActor(absorbedAt, {0.1, 0.1, 0.1}, 0.011 * size));
}

}  // namespace

void writeWalksFigure(const Mesh& mesh, const Camera& camera, const std::vector<WalksPanel>& panels,
                      const WalksViewOptions& options, const std::string& path) {
  figureFormatOf(path);
  checkWalks(mesh, panels);
  const double scale = options.size.fontScale();
  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  const double count = static_cast<double>(panels.size());
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const double viewport[4] = {k / count, 0.0, (k + 1) / count, 1.0};
    vtkSmartPointer<vtkRenderer> renderer = addFadedScene(mesh, camera, options.size, window, viewport);
    // A panel narrower than it is tall keeps the camera's angle across, not up: the whole room in view.
    if (options.size.width < count * options.size.height)
      renderer->GetActiveCamera()->UseHorizontalViewAngleOn();
    addWalks(renderer, panels[k], scale);
    renderer->ResetCameraClippingRange();
    const int panelWidth = static_cast<int>(options.size.width / count);
    renderer->AddViewProp(
        makeCaption(panels[k].title, readableFontSize(options.size.height, scale, 0.026), panelWidth));
  }
  writeRenderWindow(window, path, options.size.dpi);
}

}  // namespace rt::viz
