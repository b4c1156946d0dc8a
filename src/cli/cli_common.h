// Pieces shared by the subcommands: mesh options, scene loading, the progress line.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <ostream>
#include <string>

#include "core/formfactor/formfactor_method.h"
#include "core/mesh.h"
#include "core/progress.h"
#include "core/scene.h"

namespace rt::cli {

// The exit status of every subcommand, one per class of error (docs/robustness.md lists the messages).
enum ExitCode : int {
  Success = 0,
  Failure = 1,      // the computation could not be done (solver failure, an output that cannot be drawn)
  Usage = 2,        // the command line: unknown option, bad value, unknown method or solver name
  Input = 3,        // a file: missing, unreadable, malformed, or an impossible scene or mesh (file:line)
  OutOfMemory = 4,  // the allocator gave up despite the size checks
  Internal = 5,     // an internal invariant check failed: a bug
};
inline constexpr const char* kExitCodeHelp =
    "Exit status: 0 success, 1 computation failed, 2 command-line error, 3 input error (file, line or "
    "value), 4 out of memory, 5 internal error (a bug).";

// --no-subdivide | --subdivide N | --max-edge L, mutually exclusive.
struct MeshArguments {
  bool noSubdivide = false;
  int subdivide = 0;
  double maxEdge = 0.0;
  bool splitAtContacts = false;                  // with subdivide or maxEdge: cut along contact lines first
  double overlapGap = MeshOptions{}.overlapGap;  // and under parallel patches this near (of the diagonal)
  void add(CLI::App& command);
  MeshOptions options() const;
  // options(), except that a scene given without any mesh option gets defaultMeshOptions, and stderr says
  // which element size was chosen and how to choose another (solve: a solution needs a mesh). Either way,
  // stderr lists the cuts the mesh makes (contacts and overlaps, meshCuts).
  MeshOptions optionsFor(const Scene& scene) const;
};

// --camera "position x y z target x y z up x y z fov_y_degrees f": the view of every picture a command makes,
// in place of the scene's own camera (or the default one looking at the whole scene).
struct CameraArgument {
  std::string text;
  void add(CLI::App& command);
  // Sets scene.camera when --camera was given; throws InputError naming --camera when the text is wrong.
  void applyTo(Scene& scene) const;
};

// Loads and validates the scene, printing its warnings to stderr.
Scene loadSceneReportingWarnings(const std::string& path);

class ProgressLine;

// Prints "METHOD: summary" to `out` and the method's warnings to stderr.
void reportFormFactorStats(std::ostream& out, const std::string& method, const FormFactorStats& stats);

// Computes F with the named method, showing progress, and prints the method's one-line summary to stderr.
FormFactorMatrix computeFormFactorsReporting(const Mesh& mesh, const std::string& method,
                                             const FormFactorOptions& options, ProgressLine& progress);

// A single progress line on stderr ("form factors  42%"), redrawn in place when stderr is a terminal and
// printed at most every 10% otherwise, so logs stay short.
class ProgressLine : public Progress {
 public:
  explicit ProgressLine(bool enabled = true);
  ~ProgressLine() override;
  void report(double fraction, const std::string& stage) override;
  void finish();

 private:
  bool enabled_;
  bool terminal_;
  int lastPercent_ = -1;
  std::string lastStage_;
  std::chrono::steady_clock::time_point stageStart_;
  bool open_ = false;
};

}  // namespace rt::cli
