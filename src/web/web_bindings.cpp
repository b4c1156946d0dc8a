// The web module's JavaScript interface (embind): `new Module.Session()` with the methods of WebSession;
// the arrays come back as typed arrays of their own (Float32Array, Int32Array, Float64Array, Uint8Array),
// copied out of the WebAssembly memory so that they outlive the next call. `Module.controlRows(keys)` gives
// the step-key table's rows a page builds its widgets from (web_step.h).
#include <span>

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <nlohmann/json.hpp>

#include "viz/display_pipeline.h"
#include "viz/hemicube_view.h"
#include "web/web_session.h"
#include "web/web_step.h"

namespace {

using emscripten::val;

template <class T>
val copied(std::span<const T> values) {
  return val(emscripten::typed_memory_view(values.size(), values.data())).call<val>("slice");
}
template <class T>
val copied(const std::vector<T>& values) {
  return copied(std::span<const T>(values));
}

// Reports to a JavaScript function(fraction, stage), at most once per percent and stage, so that a worker
// posting them does not flood the page.
class ScriptProgress : public rt::Progress {
 public:
  explicit ScriptProgress(val callback) : callback_(std::move(callback)) {}
  void report(double fraction, const std::string& stage) override {
    const int percent = static_cast<int>(fraction * 100);
    if (percent == percent_ && stage == stage_) return;
    percent_ = percent;
    stage_ = stage;
    if (callback_.typeOf().as<std::string>() == "function") callback_(fraction, stage);
  }

 private:
  val callback_;
  int percent_ = -1;
  std::string stage_;
};

val bytes(const std::string& text) {
  const std::vector<unsigned char> b(text.begin(), text.end());
  return copied(b);
}

rt::MatrixFormat formatOf(const std::string& extension) {
  return extension == "npy" ? rt::MatrixFormat::Npy : rt::MatrixFormat::Csv;
}

rt::RgbField field(const std::vector<double>& values) {
  rt::RgbField out(Eigen::Index(values.size() / 3), 3);
  for (Eigen::Index i = 0; i < out.rows(); ++i)
    for (int c = 0; c < 3; ++c) out(i, c) = values[std::size_t(3 * i + c)];
  return out;
}

// The display pipeline of the app's views and the book's figures (viz/display_pipeline.h, VTK-free, compiled
// into the module): the exposure of the session's final B (`exposure` when > 0, else automatic, the emitters
// left out), and B after iteration k (k < 0: the final B) as 8-bit colours through it.
double displayExposure(const rt::web::WebSession& s, double exposure, const std::string& toneMap) {
  rt::viz::ImageOptions options;
  options.exposure = exposure;
  options.toneMap = rt::viz::toneMapFromName(toneMap);
  const rt::RgbField emission = field(s.emission());
  return rt::viz::displaySettingsFor(options, field(s.radiosity(-1)), &emission).exposure;
}

val displayColours(const rt::web::WebSession& s, int k, double exposure, const std::string& toneMap,
                   bool gamma) {
  const rt::viz::DisplaySettings settings{exposure, rt::viz::toneMapFromName(toneMap), gamma};
  const std::vector<double> B = s.radiosity(k);
  std::vector<unsigned char> out(B.size());
  for (std::size_t i = 0; i + 2 < B.size(); i += 3) {
    const rt::viz::Rgb8 c = rt::viz::displayColour(rt::Rgb(B[i], B[i + 1], B[i + 2]), settings);
    for (std::size_t j = 0; j < 3; ++j) out[i + j] = c[j];
  }
  return copied(out);
}

// A 2D figure of the viz layer (viz/drawing.h: polygons, lines and text in pixels, origin bottom-left) as
// JSON, which live_view.js paints on a canvas: the book's figure, drawn by the same code, live.
std::string drawingJson(const rt::viz::Drawing& d) {
  using Json = nlohmann::json;
  auto colour = [](const rt::viz::Rgb8& c) { return Json::array({c[0], c[1], c[2]}); };
  Json shapes = Json::array();
  for (const auto& shape : d.shapes) {
    if (shape.kind == rt::viz::Drawing::Kind::Image) continue;  // no figure drawn live has one
    Json points = Json::array();
    for (const rt::Vec2& p : shape.points) points.push_back(Json::array({p.x(), p.y()}));
    Json out{{"kind", shape.kind == rt::viz::Drawing::Kind::Text       ? "text"
                      : shape.kind == rt::viz::Drawing::Kind::Polyline ? "polyline"
                                                                       : "polygon"},
             {"points", points},
             {"filled", shape.filled},
             {"fill", colour(shape.fill)},
             {"stroke", colour(shape.stroke)},
             {"strokeWidth", shape.strokeWidth}};
    if (shape.kind == rt::viz::Drawing::Kind::Text) {
      out["text"] = shape.text;
      out["fontSize"] = shape.fontSize;
      out["hAlign"] = static_cast<int>(shape.hAlign);
      out["vAlign"] = static_cast<int>(shape.vAlign);
      out["bold"] = shape.bold;
      out["angle"] = shape.angleDegrees;
    }
    shapes.push_back(std::move(out));
  }
  return Json{
      {"width", d.width}, {"height", d.height}, {"background", colour(d.background)}, {"shapes", shapes}}
      .dump();
}

// The hemicube lesson's figure of one element's faces (viz/hemicube_view.h), "" when there is none.
std::string hemicubeFigure(const rt::web::WebSession& s, int element, int resolution, int width, int height) {
  const rt::HemicubeFaces faces = s.hemicube(element, resolution);
  if (faces.resolution < 2) return "";
  rt::viz::HemicubeViewOptions options;
  options.size = {width, height, 96.0};
  return drawingJson(rt::viz::hemicubeFacesDrawing(faces, static_cast<std::size_t>(s.elements()), options));
}

}  // namespace

EMSCRIPTEN_BINDINGS(radiosity_core) {
  using rt::web::WebSession;
  emscripten::function("controlRows", emscripten::optional_override([](const std::string& keysJson) {
                         std::vector<std::string> keys;
                         const val list = val::global("JSON").call<val>("parse", keysJson);
                         for (int i = 0; i < list["length"].as<int>(); ++i)
                           keys.push_back(list[i].as<std::string>());
                         return rt::web::controlRowsJson(keys);
                       }));
  emscripten::class_<WebSession>("Session")
      .constructor<>()
      .function("putFile", &WebSession::putFile)
      .function("load", &WebSession::load)
      .function("configure", &WebSession::configure)
      .function("configureStep", &WebSession::configureStep)
      .function("run", emscripten::optional_override([](WebSession& s) { return s.run(); }))
      .function("runWithProgress", emscripten::optional_override([](WebSession& s, val callback) {
                  ScriptProgress progress(std::move(callback));
                  return s.run(progress);
                }))
      .function("rowPlan", &WebSession::rowPlan)
      .function("formFactorRows", emscripten::optional_override([](WebSession& s, int begin, int end) {
                  return copied(s.formFactorRows(begin, end));
                }))
      // Rows computed by another worker (a Float64Array of formFactorRows) into this session's F: false
      // when they are not rows of the planned mesh.
      .function("putFormFactorRows",
                emscripten::optional_override([](WebSession& s, int begin, int end, val rows) {
                  const std::span<double> target = s.rowsToFill(begin, end);
                  if (target.empty() || rows["length"].as<std::size_t>() != target.size()) return false;
                  val(emscripten::typed_memory_view(target.size(), target.data())).call<void>("set", rows);
                  return true;
                }))
      .function("fillFormFactorRows", &WebSession::fillFormFactorRows)
      .function("displayExposure", &displayExposure)
      .function("displayColours", &displayColours)
      .function("hemicubeFigure", &hemicubeFigure)
      .function("elements", &WebSession::elements)
      .function("iterations", &WebSession::iterations)
      .function("csv", &WebSession::csv)
      .function("formFactorFile", emscripten::optional_override([](const WebSession& s, std::string ext) {
                  return bytes(s.formFactorFile(formatOf(ext)));
                }))
      .function("trianglePositions", emscripten::optional_override(
                                         [](const WebSession& s) { return copied(s.trianglePositions()); }))
      .function("triangleElements", emscripten::optional_override(
                                        [](const WebSession& s) { return copied(s.triangleElements()); }))
      .function("radiosity", emscripten::optional_override(
                                 [](const WebSession& s, int k) { return copied(s.radiosity(k)); }))
      .function("formFactorRow", emscripten::optional_override(
                                     [](const WebSession& s, int i) { return copied(s.formFactorRow(i)); }))
      .function("residuals",
                emscripten::optional_override([](const WebSession& s) { return copied(s.residuals()); }));
}
