// The web edition's computing session: what a page asks of the core, in plain C++ types so that the same
// class runs natively (tests compare it with the programs) and in WebAssembly (web_bindings.cpp hands it to
// JavaScript). A page gives it the text of its files, its settings as JSON, and reads back the mesh's
// triangles, B after every iteration and the convergence curve; one Pipeline keeps F cached across runs,
// so that a reflectance or light change only solves again.
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/formfactor/hemicube.h"
#include "core/io/matrix_export.h"
#include "core/pipeline/pipeline.h"
#include "core/progress.h"
#include "core/scene.h"
#include "core/solvers/shooting_solvers.h"

namespace rt::web {

class WebSession {
 public:
  WebSession();

  // A file the scene loader may read: the scene (.json or .obj) and the material libraries its OBJ names.
  void putFile(const std::string& name, const std::string& text);
  // Loads the scene `name` from the files given. Returns "" or the loader's message (file, line, field).
  std::string load(const std::string& name);
  // The settings as a JSON object (web_settings.h). Returns "" or what is wrong, naming the key.
  std::string configure(const std::string& settingsJson);
  // A lesson step's parameters instead (web_step.h: {"stage", "parameters": {key: text}}), read through the
  // table of step keys as the app reads its panel. Returns "" or the refusal, naming the key.
  std::string configureStep(const std::string& stepJson);
  // Mesh, form factors (cached by geometry and method), solve with every iteration recorded. Returns a JSON
  // object: the counts, the solver and its status, the surfaces with their reflectance and emission, or
  // {"error": message}. `progress` hears how far the computation is (the page's progress bar).
  std::string run(Progress& progress = noProgress());

  // F's rows spread over workers that share no memory (the pages' Web Workers, live_worker.js). rowPlan()
  // meshes the configured step and returns how many rows F has to be computed apart, 0 when there is nothing
  // to spread (F is cached, the method's rows are not independent, the run needs no F or only rescales the
  // light). formFactorRows(begin, end) computes rows [begin, end) of that mesh's F (row-major), bit for bit
  // the rows of the whole matrix, into storage of the session's that the next call reuses (empty for a
  // range that is not F's). rowsToFill(begin, end) is where such rows go (empty for a range that is not
  // F's); fillFormFactorRows(begin, end) computes them there, in this session (false for such a range). Once
  // every row is in, run() solves with that F as if it had computed it.
  int rowPlan();
  std::span<const double> formFactorRows(int begin, int end);
  std::span<double> rowsToFill(int begin, int end);
  bool fillFormFactorRows(int begin, int end);

  int elements() const;
  int iterations() const;  // recorded iterations (0 before a run)
  // The mesh as triangles, three float xyz vertices each, unshared, so that a view colours each flat; and
  // for each triangle its element.
  std::vector<float> trianglePositions() const;
  std::vector<int> triangleElements() const;
  // B (n x 3, row-major) after iteration `k` (0-based), or the final B for k < 0 or past the last.
  std::vector<double> radiosity(int k) const;
  // Each element's emission (n x 3, row-major; an emitter's light is not what an exposure is set by).
  std::vector<double> emission() const;
  // Row i of F (empty without F: a solver that traces its own rays stores none).
  std::vector<double> formFactorRow(int i) const;
  // The hemicube of `element` at `resolution` on the mesh of the last run, what the hemicube lesson's figure
  // unfolds (resolution 0: no run, or an element or resolution out of range).
  HemicubeFaces hemicube(int element, int resolution) const;
  // The relative residual after each recorded iteration.
  std::vector<double> residuals() const;
  // B per element as `radiosity solve --output` writes it.
  std::string csv() const;
  // F as a file of `format` (matrix_export.h: the CSV or NumPy .npy that `radiosity formfactors --output`
  // writes); empty without F.
  std::string formFactorFile(MatrixFormat format) const;

 private:
  bool onlyTheLightChanged() const;
  void scaleTheLight();
  const Mesh& plannedMesh();
  // Rows [begin, end) of the planned mesh's F into `out` (row-major); the provider is kept across blocks.
  void computeRows(int begin, int end, double* out);
  void keepGatheredRows();
  void forgetPlan();

  std::map<std::string, std::string> files_;
  std::shared_ptr<const Scene> scene_;
  std::string sceneName_;
  PipelineSettings settings_;
  Pipeline pipeline_;
  PipelineOutput output_;
  bool solved_ = false;
  // The step configured and the one last run, without their light (configureStep only), and that light.
  std::string stepButLight_, ranStep_;
  double ranLight_ = 0;
  // The mesh of the configured step for rows computed apart, and the rows gathered so far.
  MeshedScene planned_;
  FormFactorRowProvider plannedRows_;
  std::unique_ptr<FormFactorMatrix> gathered_;
  std::vector<bool> rowIn_;
  std::vector<double> rowsOut_;  // formFactorRows' answer: kept, so that no call zero-fills a new block
  Eigen::Index rowsGathered_ = 0;
  std::chrono::steady_clock::time_point plannedAt_;
};

}  // namespace rt::web
