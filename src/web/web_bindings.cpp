// The web module's JavaScript interface (embind): `new Module.Session()` with the methods of WebSession;
// the arrays come back as typed arrays of their own (Float32Array, Int32Array, Float64Array), copied out of
// the WebAssembly memory so that they outlive the next call.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "web/web_session.h"

namespace {

using emscripten::val;

template <class T>
val copied(const std::vector<T>& values) {
  return val(emscripten::typed_memory_view(values.size(), values.data())).call<val>("slice");
}

}  // namespace

EMSCRIPTEN_BINDINGS(radiosity_core) {
  using rt::web::WebSession;
  emscripten::class_<WebSession>("Session")
      .constructor<>()
      .function("putFile", &WebSession::putFile)
      .function("load", &WebSession::load)
      .function("configure", &WebSession::configure)
      .function("run", &WebSession::run)
      .function("elements", &WebSession::elements)
      .function("iterations", &WebSession::iterations)
      .function("csv", &WebSession::csv)
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
