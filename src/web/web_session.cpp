#include "web/web_session.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/input_error.h"
#include "core/io/radiosity_csv.h"
#include "core/io/scene_loader.h"
#include "web/web_settings.h"

namespace rt::web {
namespace {

using Json = nlohmann::json;

std::string errorJson(const std::string& message) {
  return Json{{"error", message}}.dump();
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

Json rgb(const Rgb& c) {
  return Json::array({c[0], c[1], c[2]});
}

}  // namespace

WebSession::WebSession() : pipeline_(2) {
  settings_.recordHistory = true;
}

void WebSession::putFile(const std::string& name, const std::string& text) {
  files_[name] = text;
}

std::string WebSession::load(const std::string& name) {
  const auto file = files_.find(name);
  if (file == files_.end()) return name + ": no such file was given";
  try {
    Scene scene;
    if (endsWith(name, ".json")) {
      scene = parseSceneJson(file->second, name);
    } else if (endsWith(name, ".obj")) {
      // The OBJ names its libraries relative to its own folder: look them up by their file name.
      scene =
          parseSceneObj(file->second, name, [this](const std::string& path) -> std::optional<std::string> {
            const auto mtl = files_.find(std::filesystem::path(path).filename().string());
            if (mtl == files_.end()) return std::nullopt;
            return mtl->second;
          });
    } else {
      return name + ": not a scene file (.json or .obj)";
    }
    scene_ = std::make_shared<const Scene>(std::move(scene));
    sceneName_ = name;
    solved_ = false;
    return readSettings("{}", *scene_, settings_);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return name + ": " + e.what();
  }
}

std::string WebSession::configure(const std::string& settingsJson) {
  if (!scene_) return "settings: load a scene first";
  return readSettings(settingsJson, *scene_, settings_);
}

std::string WebSession::run() {
  if (!scene_) return errorJson("load a scene first");
  try {
    requireLight(*scene_);
    output_ = pipeline_.run(*scene_, settings_);
    solved_ = true;
  } catch (const InputError& e) {
    solved_ = false;
    return errorJson(e.what());
  } catch (const std::exception& e) {
    solved_ = false;
    return errorJson(e.what());
  }
  const SolveOutcome& solve = output_.solve;
  Json surfaces = Json::array();
  for (const Surface& s : output_.scene->surfaces) {
    const Material& m = output_.scene->materials[std::size_t(s.material)];
    surfaces.push_back(
        {{"name", s.name}, {"reflectance", rgb(m.reflectance)}, {"emission", rgb(m.emission)}});
  }
  // The emitters, which a view leaves out of its exposure (the light would set it, and the room be dark).
  Json emitters = Json::array();
  const Mesh& mesh = *output_.mesh;
  for (Eigen::Index i = 0; i < mesh.emission.rows(); ++i)
    if (mesh.emission.row(i).maxCoeff() > 0) emitters.push_back(i);
  // The scene's camera, or one that frames the whole scene, as the desktop views start from.
  const Camera camera = output_.scene->cameraOrDefault();
  auto vec = [](const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); };
  const Json view{{"position", vec(camera.position)},
                  {"target", vec(camera.target)},
                  {"up", vec(camera.up)},
                  {"fov", camera.fovYDegrees}};
  return Json{{"scene", sceneName_},
              {"elements", elements()},
              {"method", output_.formFactorMethod},
              {"formFactorsReused", output_.formFactorsReused},
              {"formFactorSeconds", output_.formFactorStats.seconds},
              {"solver", solve.solverName},
              {"status", toString(solve.status)},
              {"iterations", iterations()},
              {"residual", solve.residual},
              {"seconds", solve.seconds},
              {"surfaces", surfaces},
              {"emitters", emitters},
              {"camera", view},
              {"note", output_.note}}
      .dump();
}

int WebSession::elements() const {
  return solved_ ? static_cast<int>(output_.mesh->size()) : 0;
}

int WebSession::iterations() const {
  return solved_ ? static_cast<int>(output_.solve.history.size()) : 0;
}

std::vector<float> WebSession::trianglePositions() const {
  std::vector<float> out;
  if (!solved_) return out;
  const Mesh& mesh = *output_.mesh;
  for (const Element& e : mesh.elements)
    for (std::size_t k = 1; k + 1 < e.vertices.size(); ++k)
      for (const int v : {e.vertices[0], e.vertices[k], e.vertices[k + 1]})
        for (int c = 0; c < 3; ++c) out.push_back(static_cast<float>(mesh.vertices[std::size_t(v)][c]));
  return out;
}

std::vector<int> WebSession::triangleElements() const {
  std::vector<int> out;
  if (!solved_) return out;
  const Mesh& mesh = *output_.mesh;
  for (std::size_t e = 0; e < mesh.size(); ++e)
    for (std::size_t k = 1; k + 1 < mesh.elements[e].vertices.size(); ++k) out.push_back(static_cast<int>(e));
  return out;
}

std::vector<double> WebSession::radiosity(int k) const {
  std::vector<double> out;
  if (!solved_) return out;
  const auto& history = output_.solve.history;
  const RgbField& B =
      k >= 0 && k < static_cast<int>(history.size()) ? history[std::size_t(k)].B : output_.solve.B;
  out.reserve(std::size_t(B.rows()) * 3);
  for (Eigen::Index i = 0; i < B.rows(); ++i)
    for (int c = 0; c < 3; ++c) out.push_back(B(i, c));
  return out;
}

std::vector<double> WebSession::formFactorRow(int i) const {
  std::vector<double> out;
  if (!solved_ || !output_.F || i < 0 || i >= output_.F->rows()) return out;
  out.reserve(std::size_t(output_.F->cols()));
  for (Eigen::Index j = 0; j < output_.F->cols(); ++j) out.push_back((*output_.F)(i, j));
  return out;
}

std::vector<double> WebSession::residuals() const {
  std::vector<double> out;
  if (!solved_) return out;
  for (const IterationRecord& r : output_.solve.history) out.push_back(r.residual);
  return out;
}

std::string WebSession::csv() const {
  if (!solved_) return "";
  return radiosityCsv(*output_.scene, *output_.mesh, output_.solve.B);
}

}  // namespace rt::web
