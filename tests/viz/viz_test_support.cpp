#include "viz/viz_test_support.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/polygon.h"
#include "support/test_paths.h"

namespace rt::vizt {
namespace {

vtkSmartPointer<vtkImageData> readPng(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": no such file");
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  if (!reader->CanReadFile(path.c_str())) throw std::runtime_error(path + ": not a PNG");
  reader->SetFileName(path.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}

void addPatch(Scene& scene, int surface, Polygon polygon) {
  Patch patch;
  patch.vertices = std::move(polygon);
  patch.normal = newellNormal(patch.vertices).normalized();
  patch.area = polygonArea(patch.vertices);
  patch.surface = surface;
  scene.patches.push_back(std::move(patch));
}

}  // namespace

Scene openRoom() {
  Scene scene;
  scene.name = "open room";
  auto material = [&](const std::string& name, Rgb rho, Rgb emission) {
    scene.materials.push_back({name, rho, emission});
    return static_cast<int>(scene.materials.size()) - 1;
  };
  const int white = material("white", Rgb(0.75, 0.75, 0.75), Rgb::Zero());
  const int red = material("red", Rgb(0.75, 0.15, 0.12), Rgb::Zero());
  const int green = material("green", Rgb(0.15, 0.7, 0.2), Rgb::Zero());
  const int light = material("light", Rgb(0.8, 0.8, 0.8), Rgb(20, 19, 17));
  auto surface = [&](const std::string& name, int m) {
    scene.surfaces.push_back({name, m});
    return static_cast<int>(scene.surfaces.size()) - 1;
  };
  // CCW seen from inside the room.
  addPatch(scene, surface("floor", white), {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}});
  addPatch(scene, surface("ceiling", white), {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}});
  addPatch(scene, surface("back", white), {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  addPatch(scene, surface("left", red), {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}});
  addPatch(scene, surface("right", green), {{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}});
  addPatch(scene, surface("light", light),
           {{0.35, 0.999, 0.35}, {0.65, 0.999, 0.35}, {0.65, 0.999, 0.65}, {0.35, 0.999, 0.65}});
  Camera camera;
  camera.position = Vec3(0.5, 0.5, 2.6);
  camera.target = Vec3(0.5, 0.45, 0.4);
  camera.fovYDegrees = 38;
  scene.camera = camera;
  return scene;
}

Mesh openRoomMesh(int count) {
  MeshOptions o;
  o.mode = MeshOptions::Mode::Count;
  o.count = count;
  return buildMesh(openRoom(), o);
}

RgbField syntheticRadiosity(const Mesh& mesh) {
  RgbField B(static_cast<Eigen::Index>(mesh.size()), 3);
  const Vec3 light(0.5, 1.0, 0.5);
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& element = mesh.elements[e];
    const Vec3 toLight = light - element.centroid;
    const double cosine = std::max(0.0, element.normal.dot(toLight.normalized()));
    const double irradiance = 3.0 * (0.15 + cosine) / (0.3 + toLight.squaredNorm());
    B.row(e) = (mesh.emission.row(e).array() + mesh.reflectance.row(e).array() * irradiance).matrix();
  }
  return B;
}

PngStats pngStats(const std::string& path) {
  vtkSmartPointer<vtkImageData> image = readPng(path);
  PngStats stats;
  int dims[3];
  image->GetDimensions(dims);
  stats.width = dims[0];
  stats.height = dims[1];
  vtkDataArray* pixels = image->GetPointData()->GetScalars();
  const int channels = pixels->GetNumberOfComponents();
  const vtkIdType n = pixels->GetNumberOfTuples();
  double sum = 0, sum2 = 0;
  for (vtkIdType i = 0; i < n; ++i)
    for (int c = 0; c < std::min(channels, 3); ++c) {
      const double v = pixels->GetComponent(i, c);
      stats.mean[c] += v / static_cast<double>(n);
      sum += v;
      sum2 += v * v;
    }
  const double count = static_cast<double>(n) * std::min(channels, 3);
  stats.stddev = std::sqrt(std::max(0.0, sum2 / count - (sum / count) * (sum / count)));
  return stats;
}

PngLuminance pngLuminance(const std::string& path) {
  vtkSmartPointer<vtkImageData> image = readPng(path);
  int dims[3];
  image->GetDimensions(dims);
  PngLuminance result;
  result.width = dims[0];
  result.height = dims[1];
  result.values.resize(static_cast<std::size_t>(dims[0]) * dims[1]);
  vtkDataArray* pixels = image->GetPointData()->GetScalars();
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      const vtkIdType i = static_cast<vtkIdType>(dims[1] - 1 - y) * dims[0] + x;  // VTK's rows start below
      result.values[static_cast<std::size_t>(y) * dims[0] + x] = 0.2126 * pixels->GetComponent(i, 0) +
                                                                 0.7152 * pixels->GetComponent(i, 1) +
                                                                 0.0722 * pixels->GetComponent(i, 2);
    }
  return result;
}

double pngDifference(const std::string& a, const std::string& b) {
  vtkSmartPointer<vtkImageData> ia = readPng(a), ib = readPng(b);
  int da[3], db[3];
  ia->GetDimensions(da);
  ib->GetDimensions(db);
  if (da[0] != db[0] || da[1] != db[1]) return -1;
  vtkDataArray* pa = ia->GetPointData()->GetScalars();
  vtkDataArray* pb = ib->GetPointData()->GetScalars();
  double worst = 0;
  for (int c = 0; c < 3; ++c) {
    double sum = 0;
    for (vtkIdType i = 0; i < pa->GetNumberOfTuples(); ++i)
      sum += std::abs(pa->GetComponent(i, std::min(c, pa->GetNumberOfComponents() - 1)) -
                      pb->GetComponent(i, std::min(c, pb->GetNumberOfComponents() - 1)));
    worst = std::max(worst, sum / static_cast<double>(pa->GetNumberOfTuples()));
  }
  return worst;
}

double compareWithBaseline(const std::string& rendered, const std::string& name) {
  const std::string baseline = rt::test::sourcePath("tests/baselines/" + name);
  if (std::getenv("RT_UPDATE_BASELINES") != nullptr) {
    std::filesystem::copy_file(rendered, baseline, std::filesystem::copy_options::overwrite_existing);
    return 0.0;
  }
  if (!std::filesystem::exists(baseline)) return -1;
  return pngDifference(rendered, baseline);
}

std::string readFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace rt::vizt
