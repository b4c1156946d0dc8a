#include "web/web_session.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "core/input_error.h"
#include "core/io/radiosity_csv.h"
#include "core/io/scene_loader.h"
#include "core/pipeline/scene_overrides.h"
#include "core/solvers/row_providers.h"
#include "core/solvers/solver.h"
#include "web/web_settings.h"
#include "web/web_step.h"

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
  stepButLight_.clear();
  forgetPlan();
  return readSettings(settingsJson, *scene_, settings_);
}

std::string WebSession::configureStep(const std::string& stepJson) {
  if (!scene_) return "step: load a scene first";
  const std::string problem = readStep(stepJson, settings_);
  stepButLight_.clear();
  forgetPlan();
  if (problem.empty()) {
    Json step = Json::parse(stepJson);
    if (step.contains("parameters")) step["parameters"].erase("light-scale");
    stepButLight_ = step.dump();
  }
  return problem;
}

std::string WebSession::run(Progress& progress) {
  if (!scene_) return errorJson("load a scene first");
  try {
    requireLight(*scene_);
    if (onlyTheLightChanged()) {
      scaleTheLight();
    } else {
      const bool gathered = planned_.mesh && gathered_ && rowsGathered_ == gathered_->rows();
      if (gathered) keepGatheredRows();
      output_ = pipeline_.run(*scene_, settings_, progress);
      if (gathered) output_.formFactorsReused = false;  // computed for this run, only elsewhere
      solved_ = true;
      ranStep_ = stepButLight_;
      ranLight_ = settings_.lightScale;
    }
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

// B is linear in E: after a change of the light alone, every iterate of a deterministic solver (one that
// draws no random numbers: no seed among its settings) scales with it, the relative residuals and the
// iterations stay, so the session scales the last run instead of solving again, as the app does.
bool WebSession::onlyTheLightChanged() const {
  if (!solved_ || stepButLight_.empty() || stepButLight_ != ranStep_ || !(ranLight_ > 0) ||
      !(settings_.lightScale > 0) || settings_.basis != Basis::Constant)
    return false;
  const auto& seeded = solverInfo(output_.solve.solverName).settings;
  return std::find(seeded.begin(), seeded.end(), "seed") == seeded.end();
}

void WebSession::scaleTheLight() {
  const double ratio = settings_.lightScale / ranLight_;
  auto mesh = std::make_shared<Mesh>(*output_.mesh);
  mesh->emission *= ratio;
  output_.mesh = mesh;
  output_.scene =
      std::make_shared<const Scene>(applyOverrides(*scene_, settings_.reflectance, settings_.lightScale));
  output_.formFactorsReused = true;
  output_.solve.B *= ratio;
  for (IterationRecord& r : output_.solve.history) {
    r.B *= ratio;
    if (r.unshot.size() > 0) r.unshot *= ratio;
    r.unshotPower *= ratio;
    r.emittedPower *= ratio;
    r.absorbedPower *= ratio;
    r.escapedPower *= ratio;
  }
  ranLight_ = settings_.lightScale;
}

const Mesh& WebSession::plannedMesh() {
  if (!planned_.mesh) planned_ = meshScene(*scene_, settings_);
  return *planned_.mesh;
}

void WebSession::forgetPlan() {
  plannedRows_ = {};  // before the mesh it reads
  planned_ = {};
  gathered_.reset();
  rowIn_.clear();
  rowsGathered_ = 0;
}

int WebSession::rowPlan() {
  gathered_.reset();
  rowIn_.clear();
  rowsGathered_ = 0;
  plannedAt_ = std::chrono::steady_clock::now();
  if (!scene_ || settings_.basis != Basis::Constant || onlyTheLightChanged()) return 0;
  try {
    const std::string solver =
        settings_.solver.empty() ? chooseSolver(plannedMesh().size()) : settings_.solver;
    if (!solverNeedsMatrix(solver) || !makeFormFactorMethod(settings_.method)->rowsAreIndependent()) return 0;
    const Mesh& mesh = plannedMesh();
    return pipeline_.holdsFormFactors(mesh, settings_.method, settings_.formFactors)
               ? 0
               : static_cast<int>(mesh.size());
  } catch (const std::exception&) {
    return 0;  // run() reports what is wrong
  }
}

void WebSession::computeRows(int begin, int end, double* out) {
  const Mesh& mesh = plannedMesh();
  if (!plannedRows_) plannedRows_ = makeRowProvider(settings_.method, mesh, settings_.formFactors);
  const auto n = static_cast<std::size_t>(mesh.size());
  for (int i = begin; i < end; ++i) plannedRows_(i, {out + std::size_t(i - begin) * n, n});
}

std::span<const double> WebSession::formFactorRows(int begin, int end) {
  if (!scene_) return {};
  try {
    const auto n = static_cast<int>(plannedMesh().size());
    if (begin < 0 || end > n || begin >= end) return {};
    const std::size_t size = std::size_t(end - begin) * std::size_t(n);
    if (rowsOut_.size() < size) rowsOut_.resize(size);
    computeRows(begin, end, rowsOut_.data());
    return {rowsOut_.data(), size};
  } catch (const std::exception&) {
    return {};
  }
}

bool WebSession::fillFormFactorRows(int begin, int end) {
  try {
    const std::span<double> target = rowsToFill(begin, end);
    if (target.empty()) return false;
    computeRows(begin, end, target.data());
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

std::span<double> WebSession::rowsToFill(int begin, int end) {
  if (!planned_.mesh) return {};
  const auto n = static_cast<Eigen::Index>(planned_.mesh->size());
  if (begin < 0 || end > n || begin >= end) return {};
  if (!gathered_) {
    gathered_ = std::make_unique<FormFactorMatrix>(n, n);
    rowIn_.assign(std::size_t(n), false);
  }
  for (int i = begin; i < end; ++i)
    if (!rowIn_[std::size_t(i)]) rowIn_[std::size_t(i)] = true, ++rowsGathered_;
  return {gathered_->row(begin).data(), std::size_t(end - begin) * std::size_t(n)};
}

// The rows gathered become F of the planned mesh in the pipeline's cache, checked as the method checks its
// own, so that the run takes them as it takes a matrix it computed before.
void WebSession::keepGatheredRows() {
  auto cached = std::make_shared<CachedFormFactors>();
  const Mesh& mesh = *planned_.mesh;
  cached->F = makeFormFactorMethod(settings_.method)
                  ->fromRows(std::move(*gathered_), mesh, settings_.formFactors, cached->stats);
  cached->stats.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - plannedAt_).count();
  gathered_.reset();
  rowIn_.clear();
  rowsGathered_ = 0;
  pipeline_.storeFormFactors(mesh, settings_.method, settings_.formFactors, cached);
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

std::vector<double> WebSession::emission() const {
  std::vector<double> out;
  if (!solved_) return out;
  const RgbField& E = output_.mesh->emission;
  out.reserve(std::size_t(E.rows()) * 3);
  for (Eigen::Index i = 0; i < E.rows(); ++i)
    for (int c = 0; c < 3; ++c) out.push_back(E(i, c));
  return out;
}

std::vector<double> WebSession::formFactorRow(int i) const {
  std::vector<double> out;
  if (!solved_ || !output_.F || i < 0 || i >= output_.F->rows()) return out;
  out.reserve(std::size_t(output_.F->cols()));
  for (Eigen::Index j = 0; j < output_.F->cols(); ++j) out.push_back((*output_.F)(i, j));
  return out;
}

HemicubeFaces WebSession::hemicube(int element, int resolution) const {
  // The resolution within the step-key table's range for `resolution`.
  if (!solved_ || element < 0 || element >= elements() || resolution < 2 || resolution > 1024) return {};
  return renderHemicube(*output_.mesh, element, resolution);
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

std::string WebSession::formFactorFile(MatrixFormat format) const {
  if (!solved_ || !output_.F) return "";
  // Through the one writer of matrix files, in the module's own file system (memory in WebAssembly).
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "rt-web-form-factors";
  try {
    writeMatrix(*output_.F, path.string(), format);
  } catch (const InputError&) {
    return "";
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  std::filesystem::remove(path);
  return bytes.str();
}

}  // namespace rt::web
