#include "web/web_settings.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/formfactor/formfactor_method.h"
#include "core/solvers/solver.h"

namespace rt::web {
namespace {

using Json = nlohmann::json;

std::string numberProblem(const Json& value, const std::string& key, double low, double high) {
  if (!value.is_number()) return "settings: \"" + key + "\" must be a number";
  const double x = value.get<double>();
  if (!std::isfinite(x) || x < low || x > high)
    return "settings: \"" + key + "\" is " + value.dump() + ", outside [" + Json(low).dump() + ", " +
           Json(high).dump() + "]";
  return "";
}

bool named(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string readReflectance(const Json& value, const Scene& scene, PipelineSettings& settings) {
  if (!value.is_object()) return "settings: \"reflectance\" must map surface names to [r, g, b]";
  for (const auto& item : value.items()) {
    const std::string surface = item.key();
    const Json& rho = item.value();
    const bool known = std::any_of(scene.surfaces.begin(), scene.surfaces.end(),
                                   [&](const Surface& s) { return s.name == surface; });
    if (!known) return "settings: \"reflectance\": the scene has no surface \"" + surface + "\"";
    if (!rho.is_array() || rho.size() != 3)
      return "settings: \"reflectance\".\"" + surface + "\" must be [r, g, b]";
    Rgb channels;
    for (int c = 0; c < 3; ++c) {
      const std::string problem = numberProblem(rho[std::size_t(c)], "reflectance." + surface, 0.0, 0.999);
      if (!problem.empty()) return problem;
      channels[c] = rho[std::size_t(c)].get<double>();
    }
    settings.reflectance[surface] = channels;
  }
  return "";
}

}  // namespace

std::string readSettings(const std::string& text, const Scene& scene, PipelineSettings& settings) {
  const Json json = Json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) return "settings: not a JSON object";
  PipelineSettings out;
  out.recordHistory = true;
  // The mesh as `radiosity solve` chooses it: the scene's default mesh unless a mesh key is given.
  bool meshGiven = false, splitAtContacts = false;
  for (const auto& item : json.items()) {
    const std::string key = item.key();
    const Json& value = item.value();
    std::string problem;
    if (key == "subdivide") {
      problem = numberProblem(value, key, 1, 64);
      if (problem.empty()) {
        out.mesh.mode = MeshOptions::Mode::Count;
        out.mesh.count = value.get<int>();
        meshGiven = true;
      }
    } else if (key == "maxEdge") {
      problem = numberProblem(value, key, 1e-9, 1e12);
      if (problem.empty()) {
        out.mesh.mode = MeshOptions::Mode::MaxEdge;
        out.mesh.maxEdge = value.get<double>();
        meshGiven = true;
      }
    } else if (key == "noSubdivide" || key == "splitAtContacts") {
      if (!value.is_boolean())
        problem = "settings: \"" + key + "\" must be true or false";
      else if (key == "splitAtContacts")
        splitAtContacts = value.get<bool>();
      else
        meshGiven = meshGiven || value.get<bool>();
    } else if (key == "method") {
      if (!value.is_string() || !named(formFactorMethodNames(), value.get<std::string>()))
        problem = "settings: \"method\" is " + value.dump() + ", not a form-factor method of this build";
      else
        out.method = value.get<std::string>();
    } else if (key == "solver") {
      if (!value.is_string() || !named(solverNames(), value.get<std::string>()))
        problem = "settings: \"solver\" is " + value.dump() + ", not a solver";
      else
        out.solver = value.get<std::string>();
    } else if (key == "samples") {
      problem = numberProblem(value, key, 1, 1 << 20);
      if (problem.empty()) out.formFactors.samples = value.get<int>();
    } else if (key == "resolution") {
      problem = numberProblem(value, key, 4, 2048);
      if (problem.empty()) out.formFactors.hemicubeResolution = value.get<int>();
    } else if (key == "ffTolerance") {
      problem = numberProblem(value, key, 0, 0.5);
      if (problem.empty()) out.formFactors.tolerance = value.get<double>();
    } else if (key == "tolerance") {
      problem = numberProblem(value, key, 1e-15, 1);
      if (problem.empty()) out.solverOptions.tolerance = value.get<double>();
    } else if (key == "iterations") {
      problem = numberProblem(value, key, 0, 1e7);
      if (problem.empty()) out.solverOptions.maxIterations = value.get<int>();
    } else if (key == "seed") {
      problem = numberProblem(value, key, 0, 4294967295.0);
      if (problem.empty()) out.solverOptions.seed = out.formFactors.seed = value.get<std::uint64_t>();
    } else if (key == "lightScale") {
      problem = numberProblem(value, key, 0, 1e6);
      if (problem.empty()) out.lightScale = value.get<double>();
    } else if (key == "reflectance") {
      problem = readReflectance(value, scene, out);
    } else {
      problem = "settings: unknown key \"" + key + "\"";
    }
    if (!problem.empty()) return problem;
  }
  if (!meshGiven)
    out.mesh = defaultMeshOptions(scene);
  else
    out.mesh.splitAtContacts = splitAtContacts && out.mesh.mode != MeshOptions::Mode::None;
  settings = out;
  return "";
}

std::string settingsJson(const PipelineSettings& settings) {
  Json out = Json::object();
  const MeshOptions& mesh = settings.mesh;
  if (mesh.mode == MeshOptions::Mode::Count) out["subdivide"] = mesh.count;
  if (mesh.mode == MeshOptions::Mode::MaxEdge) out["maxEdge"] = mesh.maxEdge;
  if (mesh.mode == MeshOptions::Mode::None) out["noSubdivide"] = true;
  out["splitAtContacts"] = mesh.splitAtContacts;
  out["method"] = settings.method;
  out["samples"] = settings.formFactors.samples;
  out["resolution"] = settings.formFactors.hemicubeResolution;
  out["ffTolerance"] = settings.formFactors.tolerance;
  if (!settings.solver.empty()) out["solver"] = settings.solver;
  out["tolerance"] = settings.solverOptions.tolerance;
  out["iterations"] = settings.solverOptions.maxIterations;
  out["seed"] = settings.solverOptions.seed;
  out["lightScale"] = settings.lightScale;
  if (!settings.reflectance.empty()) {
    Json reflectance = Json::object();
    for (const auto& [surface, rho] : settings.reflectance) reflectance[surface] = {rho[0], rho[1], rho[2]};
    out["reflectance"] = reflectance;
  }
  return out.dump();
}

}  // namespace rt::web
