#include "viz/rays_view.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <cstdio>
#include <stdexcept>

#include "core/formfactor/ray_scene.h"
#include "core/formfactor/sampling.h"
#include "viz/faded_scene.h"
#include "viz/scene_view.h"
#include "viz/vtk_geometry.h"
#include "viz/vtk_render.h"
#include "viz/vtk_views.h"

namespace rt::viz {

double RaySample::visibleFraction() const {
  if (rays.empty()) return 0.0;
  std::size_t visible = 0;
  for (const SampledRay& r : rays) visible += r.visible ? 1 : 0;
  return static_cast<double>(visible) / static_cast<double>(rays.size());
}

RaySample sampleRays(const Mesh& mesh, int from, int to, int count, std::uint64_t seed) {
  const int n = static_cast<int>(mesh.size());
  if (from < 0 || from >= n || to < 0 || to >= n || from == to)
    throw std::invalid_argument("rays need two different elements in 0.." + std::to_string(n - 1) + " (got " +
                                std::to_string(from) + " and " + std::to_string(to) + ")");
  if (count < 1) throw std::invalid_argument("rays need a positive sample count");
  const RayScene scene(mesh);
  const Polygon a = mesh.polygon(from), b = mesh.polygon(to);
  PairRandom random(seed, static_cast<std::uint64_t>(from), static_cast<std::uint64_t>(to));
  RaySample sample;
  sample.from = from;
  sample.to = to;
  for (int k = 0; k < count; ++k) {
    const Vec2 s = jitteredSample(k, count, random), t = jitteredSample(k, count, random);
    SampledRay ray;
    ray.from = pointOnPolygon(a, s.x(), s.y());
    ray.to = pointOnPolygon(b, t.x(), t.y());
    ray.visible = scene.visible(ray.from, ray.to, from, to);
    ray.hit = ray.to;
    if (!ray.visible) {
      const RayHit hit = scene.firstHit(ray.from, (ray.to - ray.from).normalized(), from);
      ray.occluder = hit.element;
      if (hit.element >= 0) ray.hit = ray.from + hit.distance * (ray.to - ray.from).normalized();
    }
    sample.rays.push_back(ray);
  }
  return sample;
}

void writeLocalLinesFigure(const Mesh& mesh, const Camera& camera, int from, int target,
                           const std::vector<LocalLine>& lines, long total, const RaysViewOptions& options,
                           const std::string& path) {
  figureFormatOf(path);
  const int n = static_cast<int>(mesh.size());
  if (from < 0 || from >= n)
    throw std::invalid_argument("local lines need an element in 0.." + std::to_string(n - 1));
  const double scale = options.size.fontScale();
  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  vtkSmartPointer<vtkRenderer> renderer = addFadedScene(mesh, camera, options.size, window);
  const Colour sky{0.337, 0.706, 0.914}, orange{0.902, 0.624, 0.0}, green{0.0, 0.62, 0.451};
  renderer->AddActor(polygonActor(mesh.polygon(from), sky, 1.0));
  if (target >= 0 && target < n && target != from)
    renderer->AddActor(polygonActor(mesh.polygon(target), orange, 1.0));
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const double size = Vec3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]).norm();
  std::vector<Vec3> onTarget, elsewhere, escaped, ends;
  std::size_t hits = 0;
  for (const LocalLine& line : lines) {
    const bool gone = line.struck < 0;
    const Vec3 end = line.origin + (gone ? 0.1 * size : line.distance) * line.direction;
    std::vector<Vec3>& into = gone ? escaped : line.hit == target ? onTarget : elsewhere;
    into.push_back(line.origin);
    into.push_back(end);
    if (!gone) ends.push_back(end);
    hits += line.hit == target ? 1 : 0;
  }
  const double lineWidth = std::max(1.0, 1.5 * scale);
  if (!elsewhere.empty()) renderer->AddActor(linesActor(elsewhere, green, lineWidth));
  if (!onTarget.empty()) renderer->AddActor(linesActor(onTarget, orange, 1.5 * lineWidth));
  if (!escaped.empty()) {
    auto faint = linesActor(escaped, {0.6, 0.6, 0.6}, 1.0);
    faint->GetProperty()->SetOpacity(0.5);
    renderer->AddActor(faint);
  }
  if (!ends.empty()) renderer->AddActor(pointsActor(ends, {0.2, 0.2, 0.2}, 0.0025 * size));
  renderer->ResetCameraClippingRange();
  std::string caption = options.caption;
  if (caption.empty()) {
    char text[240];
    std::snprintf(text, sizeof text,
                  "%zu of the %ld local lines from element %d (blue): %zu land first on element %d (orange)",
                  lines.size(), total, from, hits, target);
    caption = text;
  }
  renderer->AddViewProp(
      makeCaption(caption, readableFontSize(options.size.height, scale, 0.028), options.size.width));
  writeRenderWindow(window, path, options.size.dpi);
}

void writeRaysFigure(const Mesh& mesh, const Camera& camera, const RaySample& sample,
                     const RaysViewOptions& options, const std::string& path) {
  figureFormatOf(path);
  const double scale = options.size.fontScale();
  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  vtkSmartPointer<vtkRenderer> renderer = addFadedScene(mesh, camera, options.size, window);

  const Colour sky{0.337, 0.706, 0.914}, orange{0.902, 0.624, 0.0}, green{0.0, 0.62, 0.451},
      vermillion{0.835, 0.369, 0.0};
  renderer->AddActor(polygonActor(mesh.polygon(sample.from), sky, 1.0));
  renderer->AddActor(polygonActor(mesh.polygon(sample.to), orange, 1.0));
  std::vector<Vec3> clear, blocked, blockedRest, hits;
  for (const SampledRay& r : sample.rays) {
    if (r.visible) {
      clear.push_back(r.from);
      clear.push_back(r.to);
    } else {
      blocked.push_back(r.from);
      blocked.push_back(r.hit);
      blockedRest.push_back(r.hit);
      blockedRest.push_back(r.to);
      hits.push_back(r.hit);
    }
  }
  const double lineWidth = std::max(1.0, 1.5 * scale);
  if (!clear.empty()) renderer->AddActor(linesActor(clear, green, lineWidth));
  if (!blocked.empty()) {
    renderer->AddActor(linesActor(blocked, vermillion, lineWidth));
    auto rest = linesActor(blockedRest, {0.6, 0.6, 0.6}, 1.0);
    rest->GetProperty()->SetOpacity(0.5);
    renderer->AddActor(rest);
    double bounds[6];
    renderer->ComputeVisiblePropBounds(bounds);
    const double size = Vec3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]).norm();
    renderer->AddActor(pointsActor(hits, vermillion, 0.006 * size));
  }
  renderer->ResetCameraClippingRange();

  std::string caption = options.caption;
  if (caption.empty()) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "rays from element %d (blue) to %d (orange): %zu of %zu unoccluded (%.1f%%)", sample.from,
                  sample.to, static_cast<std::size_t>(sample.visibleFraction() * sample.rays.size() + 0.5),
                  sample.rays.size(), 100.0 * sample.visibleFraction());
    caption = text;
  }
  renderer->AddViewProp(
      makeCaption(caption, readableFontSize(options.size.height, scale, 0.028), options.size.width));
  writeRenderWindow(window, path, options.size.dpi);
}

}  // namespace rt::viz
