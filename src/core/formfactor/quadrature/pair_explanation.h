// One pair of the quadrature method, explained: the route it took through the stages (README.md), what each
// stage found and the value, so that a student or a maintainer can see why F_ij is what it is. `radiosity
// formfactors SCENE --explain I,J` prints it.
#pragma once

#include <memory>
#include <string>

#include "core/formfactor/quadrature/quadrature_pair.h"
#include "core/mesh.h"

namespace rt {

struct PairExplanation {
  int i = 0, j = 0;
  int from = 0, to = 0;  // the direction computed: from the smaller element, the other by reciprocity
  PairTrace trace;       // of from -> to
  double value = 0;      // F_ij
  double tolerance = 0;
  // A few lines: the route and its meaning, the occluders found and kept, the source's pieces, U, H, F.
  std::string text() const;
};

// Builds what the method knows of the mesh once (the shaft test, the blocks), then explains any pair of it.
class QuadratureExplainer {
 public:
  // `tolerance` 0: the method's own default.
  QuadratureExplainer(const Mesh& mesh, double tolerance);
  ~QuadratureExplainer();
  // F_ij as the method computes it in the matrix (to its tolerance: the matrix may compute the pair along
  // another row, whose shadow regions differ), with the trace. i and j must be elements of the mesh.
  PairExplanation operator()(int i, int j);

 private:
  struct State;
  const Mesh& mesh_;
  double tolerance_;
  std::unique_ptr<State> state_;
};

}  // namespace rt
