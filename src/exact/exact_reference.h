// The exact reference (CGAL), behind a header that includes no CGAL: exact visibility from a point, exact
// point-to-area and element-to-element form factors, exact segment visibility. See docs/exact.md.
//
// Pipeline for one entry F_ij:
//   1. visibility from a point x on element i: receiver j clipped to the half-space in front of i (horizon
//   clipping),
//      occluders culled by a shaft test, clipped to the pyramid from x over j, projected centrally from x
//      into j's plane and subtracted from j by exact 2D Boolean set operations -> polygons with holes;
//   2. F(x -> visible part of j) by Lambert's contour formula (holes contribute with their opposite
//   orientation);
//   3. F_ij = (1/A_i) integral over i of (2), by adaptive high-order cubature refined where a coarse and a
//   refined
//      estimate differ (shadow boundaries), to a requested relative tolerance, with an error estimate per
//      entry.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/formfactor/formfactor_matrix.h"
#include "core/formfactor/formfactor_method.h"
#include "core/mesh.h"
#include "core/progress.h"
#include "core/vec.h"
#include "exact/polygon_with_holes.h"
#include "exact/segment_visibility.h"

namespace rt::exact {

// Adds the "exact" form-factor method to the core registry.
void registerExactMethod();

// ---- Lambert's formula (plain double precision)
// ----------------------------------------------------------------

// Differential area at x with unit normal n to a polygon that is CCW seen from its front side:
// F = (1/2pi) sum_k beta_k (n . gamma_k). Parts of the polygon behind x's plane must be clipped away first
// (pointToPolygonFormFactorClipped does that). Returns 0 when x sees the polygon's back.
double pointToPolygonFormFactor(const Vec3& x, const Vec3& n, const Polygon& polygon);
// Same after clipping the polygon to the half-space in front of x's plane (horizon clipping).
double pointToPolygonFormFactorClipped(const Vec3& x, const Vec3& n, const Polygon& polygon);
// Sum over the regions, holes included (they subtract).
double pointToRegionFormFactor(const Vec3& x, const Vec3& n, const std::vector<PolygonWithHoles>& regions);

// ---- Visibility from a point
// ----------------------------------------------------------------------------------

// What element `receiver` looks like from `point` on element `source`: the lessons draw these.
struct VisibleRegion {
  int source = -1, receiver = -1;
  Vec3 point = Vec3::Zero();
  bool facing = false;         // point in front of the receiver and receiver partly in front of point
  Polygon clippedReceiver;     // receiver after horizon clipping against the source plane at point
  std::vector<int> occluders;  // candidate occluders that survived the shaft culling
  std::vector<Polygon> occluderProjections;  // their central projections into the receiver's plane (clipped)
  std::vector<int> projectionOwners;         // element index of each projection
  std::vector<PolygonWithHoles> visible;     // clipped receiver minus the projections (exact 2D Booleans)
  double formFactor = 0;                     // F(dA at point -> visible part)
  double unoccludedFormFactor = 0;           // F(dA at point -> clipped receiver)
};

VisibleRegion visibleRegion(const Mesh& mesh, int source, const Vec3& point, int receiver);

// Elements that may block some ray between the two elements (shaft culling, conservative).
std::vector<int> shaftCandidates(const Mesh& mesh, int source, int receiver);

// ---- Element-to-element form factors
// --------------------------------------------------------------------------

// How the occluders that the double-precision filter cannot decide are cut out of the receiver at one point.
enum class Booleans {
  Exact,  // CGAL: exact projection and 2D Boolean set operations (Epeck), converted to double at the end
  Split,  // double: the receiver split into convex pieces by the planes of the shadow volumes; error =
          // rounding
};

struct ExactOptions {
  double tolerance = 1e-9;          // relative, pairs with no occluder in the shaft
  double occludedTolerance = 1e-7;  // relative, pairs with occluders (shadow boundaries make F(x) non-smooth)
  // Entries F_ij smaller than this are computed to tolerance * floor absolutely (a relative target on ~0 is
  // meaningless). A form factor, so independent of the scene's unit of length.
  double absoluteFloor = 1e-6;
  long maxEvaluations = 400000;  // per entry; the error estimate tells when it was not enough
  int ruleOrder = 5;          // Gauss-Legendre points per direction of the cubature rule (unoccluded pairs)
  int occludedRuleOrder = 3;  // lower order wins where shadow boundaries put kinks into F(x)
  Booleans booleans = Booleans::Exact;
  // Occluded pairs: split the source along the lines where F(x) has kinks (visibility events) before
  // adapting.
  bool splitAlongEvents = true;
  // Unoccluded entries from the analytic contour integral; occluded ones as that minus the cubature of what
  // the occluders take away. Off: the cubature of F_visible(x) for every entry (the lessons' cubature
  // points).
  bool analyticUnoccluded = true;
  // Called from an entry's cubature with each batch of kMeterBatch point evaluations (and the rest when the
  // entry ends), so that a whole matrix can report progress within long entries and stop on a budget or a
  // cancel by throwing. Empty: no calls.
  std::function<void(long)> meter;
};

inline constexpr long kMeterBatch = 4096;

// Thrown by exactFormFactors when the point evaluations reach the work budget: what() names the budget, the
// pairs finished and what to change.
class WorkBudgetExceeded : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Options for a requested relative tolerance t as the form-factor method reads it: t for unoccluded pairs,
// max(t, 1e-7) for occluded ones, Booleans::Split (the whole-matrix speed needs it; tests hold it to the
// exact path).
ExactOptions exactOptionsFor(double tolerance);

struct CubaturePoint {
  Vec3 position;
  double weight = 0;  // area weight (sums to the integrated part of the source's area)
  double value = 0;   // F(dA at position -> visible part of the receiver)
};

struct EntryResult {
  double value = 0;           // F_ij
  double errorEstimate = 0;   // absolute, |fine - coarse| summed over the final cubature cells
  bool occluded = false;      // the shaft held candidate occluders
  bool facing = true;         // false: one element entirely behind the other's plane, F = 0 without work
  long evaluations = 0;       // point-to-area evaluations
  long exactEvaluations = 0;  // of which went through CGAL's exact Booleans
  long splitEvaluations = 0;  // of which went through the double-precision convex split
  bool converged = true;
  long eventCells = 1;    // cells of the source after splitting along visibility events
  bool analytic = false;  // unoccluded, from the analytic contour integral: no cubature, no estimate (0)
};

class ElementIndex;  // exact/shaft.h: the mesh's polygons and a box tree over them, for whole matrices
EntryResult elementFormFactor(const Mesh& mesh, int source, int receiver, const ExactOptions& options = {},
                              std::vector<CubaturePoint>* points = nullptr,
                              const ElementIndex* index = nullptr);
// The integrand of F_ij at one point x of the source: F(dA at x -> visible part of the receiver), with the
// given way of cutting out the occluders the filter cannot decide (both ways must agree to rounding; the
// tests check it).
double pointFormFactor(const Mesh& mesh, int source, const Vec3& x, int receiver, Booleans booleans);
// The cubature points (final cells' refined rule) used for the entry F_ij.
std::vector<CubaturePoint> cubaturePoints(const Mesh& mesh, int source, int receiver,
                                          const ExactOptions& options = {});

struct ExactMatrix {
  FormFactorMatrix F;
  Eigen::MatrixXd errorEstimate;  // absolute error estimate per entry (derived entries scaled by A_i / A_j)
};

// Full matrix: rows in parallel (TBB), i < j computed and j > i derived by reciprocity. Progress moves with
// the point evaluations done (an occluded entry can take a hundred thousand of them), against an estimate of
// the whole that the finished entries refine. Throws Cancelled, and WorkBudgetExceeded when `workBudget`
// (point evaluations, 0: none) runs out. stats may be null.
ExactMatrix exactFormFactors(const Mesh& mesh, const ExactOptions& options, Progress& progress,
                             FormFactorStats* stats = nullptr, int threads = 0, long workBudget = 0);

// |F_method - F_exact| per entry, for error maps.
Eigen::MatrixXd errorMap(const FormFactorMatrix& method, const FormFactorMatrix& exact);

}  // namespace rt::exact
