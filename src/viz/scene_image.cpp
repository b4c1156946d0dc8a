#include "viz/scene_image.h"

#include "viz/scene_view.h"

namespace rt::viz {

void renderRadiosityImage(const Mesh& mesh, const RgbField& B, const Camera& camera,
                          const ImageOptions& options, const std::string& pngPath) {
  renderRadiosityImage(mesh, B, RgbField(), camera, options, pngPath);
}

void renderRadiosityImage(const Mesh& mesh, const RgbField& B, const RgbField& corners, const Camera& camera,
                          const ImageOptions& options, const std::string& pngPath) {
  SceneViewData data;
  data.B = B;
  data.corners = corners;
  SceneViewOptions view;
  view.colouring = SceneColouring::Radiosity;
  view.image = options;
  writeSceneFigure(mesh, camera, data, view, pngPath);
}

}  // namespace rt::viz
