#include "core/formfactor/quadrature/pair_explanation.h"

#include <algorithm>
#include <cstdio>

#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/quadrature/quadrature_scene.h"
#include "core/formfactor/shaft_culling.h"

namespace rt {
namespace {

std::string listOf(const std::vector<int>& patches) {
  if (patches.empty()) return "none";
  std::string s = std::to_string(patches.size()) + " (patch";
  s += patches.size() == 1 ? " " : "es ";
  for (std::size_t k = 0; k < patches.size(); ++k) s += (k ? ", " : "") + std::to_string(patches[k]);
  return s + ")";
}

// The stages a route went through (the later ones never ran).
bool reachedClipping(QuadratureRoute r) {
  return r != QuadratureRoute::Enclosed && r != QuadratureRoute::Behind &&
         r != QuadratureRoute::FarUnoccluded && r != QuadratureRoute::BlockVerdict &&
         r != QuadratureRoute::BlockSections;
}

bool withHidden(QuadratureRoute r) {
  return r == QuadratureRoute::SolidBySolid || r == QuadratureRoute::Cells || r == QuadratureRoute::Adaptive;
}

}  // namespace

struct QuadratureExplainer::State {
  State(const Mesh& mesh, double tolerance) : shafts(mesh), scene(mesh, shafts), pair(scene, tolerance) {}
  ShaftCulling shafts;
  QuadratureScene scene;
  QuadraturePair pair;
};

QuadratureExplainer::QuadratureExplainer(const Mesh& mesh, double tolerance)
    : mesh_(mesh),
      tolerance_(tolerance > 0 ? tolerance : accuracyKnobOf("quadrature").defaultValue),
      state_(std::make_unique<State>(mesh, tolerance_)) {}

QuadratureExplainer::~QuadratureExplainer() = default;

PairExplanation QuadratureExplainer::operator()(int i, int j) {
  PairExplanation e;
  e.i = i, e.j = j, e.tolerance = tolerance_;
  e.from = i, e.to = j;
  if (i == j || !elementsFaceEachOther(mesh_, i, j)) return e;  // behind (a flat element sees none of itself)
  state_->pair.trace(&e.trace);
  const PairResult result = fromSmallerElement(mesh_, i, j, [&](int a, int b) {
    e.from = a, e.to = b;
    return state_->pair(a, b, std::min(i, j));  // the row the matrix computes the pair along
  });
  state_->pair.trace(nullptr);
  e.value = result.value;
  return e;
}

std::string PairExplanation::text() const {
  const PairTrace& t = trace;
  char line[256];
  std::string s;
  std::snprintf(line, sizeof line, "pair %d -> %d", i, j);
  s += line;
  if (from != i) {
    std::snprintf(line, sizeof line, " (computed from %d, the smaller; F_%d,%d = A_%d F_%d,%d / A_%d)", from,
                  i, j, j, j, i, i);
    s += line;
  }
  s += "\nroute: " + std::string(routeName(t.route)) + ": " + routeMeaning(t.route) + "\n";
  if (t.route != QuadratureRoute::Enclosed && t.route != QuadratureRoute::Behind) {
    s += "shaft: occluders found " + listOf(t.shaft);
    if (t.route != QuadratureRoute::FarUnoccluded && t.route != QuadratureRoute::BlockVerdict)
      s += "; left by the blocks' verdicts " + listOf(t.afterBlocks);
    s += "\n";
  }
  if (reachedClipping(t.route)) {
    std::snprintf(
        line, sizeof line,
        "clipped: %d occluder polygons kept; source: %d piece(s) outside the blocks, %d panel(s)%s\n",
        t.clippedOccluders, t.sourcePieces, t.panels, t.near ? ", near: U by the contour integral" : "");
    s += line;
    if (t.cells > 0) s += "cells: " + std::to_string(t.cells) + " cut along the visibility events\n";
  }
  const bool withU = t.route == QuadratureRoute::FarUnoccluded || t.route == QuadratureRoute::Unoccluded ||
                     withHidden(t.route);
  if (withU) {
    std::snprintf(line, sizeof line, "U_%d,%d = %.9g", from, to, t.unoccluded);
    s += line;
    if (withHidden(t.route)) {
      std::snprintf(line, sizeof line, ", H_%d,%d = %.9g", from, to, t.hidden);
      s += line;
    }
    s += "\n";
  }
  if (withU) {
    std::snprintf(
        line, sizeof line, "work: %ld point evaluations, %ld contour integrals%s\n", t.points, t.contours,
        t.budgetReached ? "; the work bound was reached before the tolerance (counted in the notes)" : "");
    s += line;
  }
  std::snprintf(line, sizeof line, "F_%d,%d = %.9g (to %.3g)\n", i, j, value, tolerance);
  return s + line;
}

}  // namespace rt
