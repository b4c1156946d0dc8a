#include "cli/web_edition.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/io/scene_loader.h"
#include "lesson/book_html.h"
#include "web/web_step.h"

namespace rt::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// The live views' scripts from src/web/page, in the order a page loads them (after three.js and the core):
// the worker's text, then the views that start it. Copied into the site and named by every page from here.
constexpr const char* kPageScripts[] = {"live_worker.js", "live_view.js"};

// The <script> tags of a page with live views, in the order they load: three.js, the core, `steps` (a
// lesson's live steps, if any), the live views' scripts, then `last` (the playground's, if any).
std::string liveViewScripts(const std::string& steps, const std::string& last) {
  std::vector<std::string> scripts = {"three.min.js", "OrbitControls.js", "radiosity-core.js"};
  if (!steps.empty()) scripts.push_back(steps);
  scripts.insert(scripts.end(), std::begin(kPageScripts), std::end(kPageScripts));
  if (!last.empty()) scripts.push_back(last);
  std::string tags;
  for (const std::string& script : scripts) tags += "<script src=\"web/" + script + "\"></script>\n";
  return tags;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot read");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

void copyAsset(const fs::path& from, const fs::path& to, const std::string& remedy) {
  if (!fs::exists(from)) throw std::runtime_error(from.string() + " is missing: " + remedy);
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

// The element a hemicube view is seen from, where the step names it by its index.
std::optional<int> hemicubeElement(const lesson::Step& step) {
  if (step.parameters.from.empty() || step.parameters.from.size() > 9 ||
      step.parameters.from.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  return std::stoi(step.parameters.from);
}

// The steps the web core computes as the desktop does, with a 3D view of the scene or an element's hemicube:
// solve and bounces steps (a bounces step of no bounce shows the emission alone, which has no iteration to
// scrub), and the steps that compute F by a method, whose live view solves with that F.
bool isLive(const lesson::Step& step) {
  using lesson::Stage;
  const bool solves =
      step.stage == Stage::Solve || (step.stage == Stage::Bounces && step.parameters.bounces > 0) ||
      step.stage == Stage::FormFactors || step.stage == Stage::Hemicube || step.stage == Stage::Nusselt;
  auto shows = [&](lesson::View view) {
    return std::find(step.views.begin(), step.views.end(), view) != step.views.end();
  };
  const bool shown = shows(lesson::View::Scene) || (shows(lesson::View::Hemicube) && hemicubeElement(step));
  return solves && shown && !step.scene.empty();
}

// The step for the page: its scene's files, its stage, its parameters as the lesson writes them and the
// keys it offers as controls (web_step.h), and the surface whose reflectance the reader may drag (the floor
// when there is one, else the first surface that does not emit).
Json liveStep(const lesson::Step& step, const std::string& scenesDir) {
  const fs::path scenePath = fs::path(scenesDir) / step.scene;
  Json files = Json::object();
  files[scenePath.filename().string()] = readText(scenePath);
  if (scenePath.extension() == ".obj") {
    const fs::path mtl = fs::path(scenePath).replace_extension(".mtl");
    if (fs::exists(mtl)) files[mtl.filename().string()] = readText(mtl);
  }
  const Scene scene = loadScene(scenePath.string());
  Json out{{"scene", scenePath.filename().string()},
           {"files", files},
           {"stage", lesson::toString(web::liveStage(step))},
           {"parameters", Json::parse(web::stepParametersJson(step))},
           {"controls", web::liveControls(step)}};
  const auto from = hemicubeElement(step);
  if (from && std::find(step.views.begin(), step.views.end(), lesson::View::Hemicube) != step.views.end())
    out["hemicube"] = {{"from", *from}, {"resolution", step.parameters.resolution.value_or(64)}};
  const Surface* chosen = nullptr;
  for (const Surface& s : scene.surfaces) {
    if (scene.materials[std::size_t(s.material)].isEmitter()) continue;
    if (!chosen || s.name == "floor") chosen = &s;
  }
  if (chosen) {
    Rgb rho = scene.materials[std::size_t(chosen->material)].reflectance;
    const auto over = step.parameters.reflectance.find(chosen->name);
    if (over != step.parameters.reflectance.end()) rho = over->second;
    out["surface"] = chosen->name;
    out["surfaceColour"] = {rho[0], rho[1], rho[2]};
    out["surfaceReflectance"] = rho.maxCoeff();
  }
  return out;
}

// Puts `insert` after the </figure> of the figure whose file name ends in `figureFile`; false when the page
// has no such figure.
bool insertAfterFigure(std::string& html, const std::string& figureFile, const std::string& insert) {
  const std::size_t stem = figureFile.rfind('.');
  const std::string name = "/" + figureFile.substr(0, stem) + ".";
  const std::size_t at = html.find(name);
  if (at == std::string::npos) return false;
  const std::size_t end = html.find("</figure>", at);
  if (end == std::string::npos) return false;
  html.insert(end + 9, "\n" + insert);
  return true;
}

// The scene playground (src/web/page/playground.js): the reader's own scene, dropped on the page, with the
// controls of a solve step.
std::string playgroundHtml() {
  lesson::Step solve;
  solve.stage = lesson::Stage::Solve;
  const std::string controls = Json(web::liveControls(solve)).dump();
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>Scene playground</title>\n<link rel=\"stylesheet\" href=\"" +
      std::string(lesson::kBookStyleFile) +
      "\">\n<link rel=\"stylesheet\" href=\"web/live_view.css\">\n</head>\n<body>\n"
      "<p><a href=\"index.html\">Contents</a></p>\n<h1>Scene playground</h1>\n"
      "<p>Drop a scene here (a scene JSON, or an OBJ with its MTL), or choose the files. It is checked as "
      "the "
      "desktop programs check it, meshed, solved by the same core, running in this page, and shown: drag to "
      "rotate, scrub the iterations, change the light.</p>\n"
      "<div id=\"playground-drop\" class=\"live-view\" data-controls='" +
      controls +
      "'>\n"
      "<p><input type=\"file\" id=\"playground-files\" multiple accept=\".json,.obj,.mtl\"> "
      "<label>Subdivide <input type=\"number\" id=\"playground-subdivide\" min=\"1\" max=\"12\" "
      "value=\"3\"></label> <button type=\"button\" class=\"playground-download\" data-kind=\"csv\" "
      "hidden>Download B (CSV)</button> <button type=\"button\" class=\"playground-download\" "
      "data-kind=\"F-csv\" hidden>Download F (CSV)</button> <button type=\"button\" "
      "class=\"playground-download\" data-kind=\"F-npy\" hidden>Download F (NPY)</button></p>\n<p "
      "id=\"playground-status\">No scene yet.</p>\n"
      "<div id=\"playground-view\"></div>\n</div>\n";
  return html + liveViewScripts("", "playground.js") + "</body>\n</html>\n";
}

}  // namespace

WebAssets defaultWebAssets() {
  return {RT_WASM_MODULE, RT_THREE_DIR, RT_WEB_PAGE_DIR};
}

int writeWebEdition(const std::string& output, const std::vector<lesson::RenderedLesson>& rendered,
                    const std::vector<std::string>& files, const lesson::LessonFolders& folders,
                    const WebAssets& assets) {
  const fs::path out = output;
  const fs::path web = out / "web";
  fs::create_directories(web);
  copyAsset(assets.module, web / "radiosity-core.js",
            "build the WebAssembly core first: cmake --preset wasm && cmake --build --preset wasm");
  const std::string three = "install libjs-three (./install-deps.sh)";
  copyAsset(fs::path(assets.three) / "three.min.js", web / "three.min.js", three);
  copyAsset(fs::path(assets.three) / "examples/js/controls/OrbitControls.js", web / "OrbitControls.js",
            three);
  for (const char* page : kPageScripts)
    copyAsset(fs::path(assets.pageFiles) / page, web / page, "the source tree's src/web/page");
  for (const char* page : {"live_view.css", "playground.js"})
    copyAsset(fs::path(assets.pageFiles) / page, web / page, "the source tree's src/web/page");
  writeText(out / "playground.html", playgroundHtml());
  // The contents page links to the playground.
  const fs::path index = out / lesson::kBookIndexFile;
  if (fs::exists(index)) {
    std::string html = readText(index);
    const std::size_t bodyEnd = html.rfind("</body>");
    if (bodyEnd != std::string::npos && html.find("playground.html") == std::string::npos) {
      html.insert(bodyEnd,
                  "<p><a href=\"playground.html\">Scene playground</a>: solve your own scene in the "
                  "browser.</p>\n");
      writeText(index, html);
    }
  }

  int views = 0;
  for (const std::string& file : files) {
    const lesson::Lesson l = lesson::loadLesson(file, folders.scenes);
    const auto page = std::find_if(rendered.begin(), rendered.end(),
                                   [&](const lesson::RenderedLesson& r) { return r.id == l.id; });
    if (page == rendered.end()) continue;
    const fs::path pagePath = out / lesson::lessonPageFile(*page);
    std::string html = readText(pagePath);
    Json live = Json::object();
    for (const lesson::Step& step : l.steps) {
      if (!isLive(step) || step.figureFiles().empty()) continue;
      const std::string key = l.id + "/" + std::to_string(step.index);
      if (!insertAfterFigure(html, step.figureFiles().front(),
                             "<div class=\"live-view\" data-live=\"" + key + "\"></div>"))
        continue;
      live[key] = liveStep(step, folders.scenes);
      ++views;
    }
    if (live.empty()) continue;
    const std::string data = l.id + "-live.js";
    writeText(web / data, "window.RT_LIVE = Object.assign(window.RT_LIVE || {}, " + live.dump() + ");\n");
    const std::string head = "<link rel=\"stylesheet\" href=\"web/live_view.css\">\n</head>";
    const std::size_t headEnd = html.find("</head>");
    if (headEnd != std::string::npos) html.replace(headEnd, 7, head);
    const std::size_t bodyEnd = html.rfind("</body>");
    html.insert(bodyEnd == std::string::npos ? html.size() : bodyEnd, liveViewScripts(data, ""));
    writeText(pagePath, html);
  }
  return views;
}

}  // namespace rt::cli
