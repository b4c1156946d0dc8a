// One pair of the quadrature method (quadrature_method.cpp), on one thread: F_ij = U_ij - H_ij, from the
// smaller element i. The stages, in order, each cheaper than the next and ending the pair where it can, and
// the route each ends on, are outlined in README.md in this folder:
//  - an element inside a block, or one behind the other's plane: 0;
//  - nothing in the shaft and far apart: U on one panel (unoccluded_integral.h);
//  - each block among the shaft test's candidates judged from its penumbra and umbra regions
//    (block_shadow_regions.h), then from its cross-sections (shadow_clipper.h): dropped, or the pair hidden;
//  - U: the exact contour integral for near pairs, Gauss quadrature of Lambert's formula elsewhere;
//  - H, where occluders remain after the clipper's own tests: block by block where their shadows never
//    overlap (shadow_overlap.h), over cells cut along the visibility events (visibility_events.h), or by the
//    guarded adaptive rules (hidden_integral.h).
// Keeps its working vectors from pair to pair: millions of pairs would otherwise spend as long in the heap as
// in the arithmetic.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/quadrature/block_shadow_regions.h"
#include "core/formfactor/quadrature/hidden_integral.h"
#include "core/formfactor/quadrature/quadrature_scene.h"
#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/visibility_events.h"
#include "core/formfactor/visibility.h"

namespace rt {

// Where a pair's value was found, in the order the stages try them (README.md in this folder).
enum class QuadratureRoute {
  Enclosed,       // one element inside a closed block: 0
  Behind,         // one wholly behind the other's plane: 0
  FarUnoccluded,  // nothing between, far apart: U on one panel
  BlockVerdict,   // a block's shadow regions prove it hides all: 0
  BlockSections,  // a block's cross-section cuts every segment: 0
  Unoccluded,     // no occluder left after clipping: U
  FaceHidesAll,   // the clipped occluders hide all from every point: 0
  SolidBySolid,   // U - H, H block by block over each one's cells
  Cells,          // U - H, H over cells cut along the visibility events
  Adaptive,       // U - H, H by the guarded adaptive rules
};
inline constexpr int kQuadratureRoutes = 10;
const char* routeName(QuadratureRoute route);     // "far-unoccluded", ...
const char* routeMeaning(QuadratureRoute route);  // the comment above, in words

// What one pair went through, recorded where asked (QuadraturePair::trace()).
struct PairTrace {
  QuadratureRoute route = QuadratureRoute::Behind;
  std::vector<int> shaft;             // the patches the shaft test found between the two
  std::vector<int> afterBlocks;       // of them, those the blocks' verdicts left
  int clippedOccluders = 0;           // occluder polygons the clipper kept
  int sourcePieces = 0;               // the source outside the blocks it reaches under
  int panels = 0, cells = 0;          // the source's panels, and its cells where H was cut into cells
  bool near = false;                  // U by the exact contour integral
  double unoccluded = 0, hidden = 0;  // U and H of the pair as computed (from i to j)
  long points = 0, contours = 0;      // Lambert evaluations and exact contour integrals the pair took
  bool budgetReached = false;         // the rules stopped at their work bound before the tolerance
};

class QuadraturePair {
 public:
  // What the notes report, summed over threads at the end.
  struct Counts {
    long points = 0, clipped = 0, placed = 0, contours = 0, budgetPairs = 0, occludedPairs = 0,
         hiddenPairs = 0, eventPairs = 0, apartPairs = 0;
    std::array<long, kQuadratureRoutes> routes{};
    Counts& operator+=(const Counts& o) {
      for (std::size_t r = 0; r < routes.size(); ++r) routes[r] += o.routes[r];
      points += o.points;
      clipped += o.clipped;
      placed += o.placed;
      contours += o.contours;
      budgetPairs += o.budgetPairs;
      occludedPairs += o.occludedPairs;
      hiddenPairs += o.hiddenPairs;
      eventPairs += o.eventPairs;
      apartPairs += o.apartPairs;
      return *this;
    }
  };

  QuadraturePair(const QuadratureScene& scene, double tolerance);

  // F_ij to the tolerance; `row` is the element the matrix's current row is fixed at (i or j), whose
  // shadow regions are kept from pair to pair.
  PairResult operator()(int i, int j, int row);

  const Counts& counts() const { return counts_; }
  // Record what each following pair goes through in `trace` (nullptr: stop).
  void trace(PairTrace* trace) { trace_ = trace; }

 private:
  // The stages of operator(), in order; the route says which one ended the pair.
  QuadratureRoute integrate(int i, int j, int row, PairResult& result);

  // Drops the blocks that miss the pair from candidates_; true when one hides all of it. `sourceCentre` and
  // `receiverCentre` are the clipped polygons' centres.
  bool judgeBlocks(int i, int j, int row, const ConvexPolygon& a, const ConvexPolygon& b,
                   const ConvexPolygon& source, const ConvexPolygon& receiver, const Vec3& sourceCentre,
                   const Vec3& receiverCentre);

  // H solid by solid, where every occluder left bounds a convex solid, there are several, and no segment
  // from i to j passes through two of them (QuadratureScene::shadowsApart): then H is the sum of what each
  // hides alone, and each of those is integrated over cells cut along its own events (visibility_events.h
  // leaves several occluders out: their shadows' crossings are events that are not planes, but apart they
  // never cross). False (`sum` unset) where that does not hold or the cells would be too many; the adaptive
  // rules take the pair then. `eps`: shadowEps() of the pair.
  bool hiddenSolidBySolid(int i, int j, const ConvexPolygon& source, double eps, HiddenIntegral& hidden,
                          double tolerance, double& sum);

  // The gap between element i, whole (`source` its corners), and the receiver: the distance between their
  // bounding spheres, or the source's height over the receiver's plane where that is more.
  double gapOf(int i, const ConvexPolygon& source, const ReceiverBound& receiver) const;
  // Whether a region said `solid` shades part of the pair, and so does not hide all of it (judgeBlocks()).
  bool shades(int solid) const {
    return std::find(shading_.begin(), shading_.end(), solid) != shading_.end();
  }

  const QuadratureScene& scene_;
  double tolerance_;
  ShadowClipper clipper_;
  RowShadowRegions rowRegions_;
  Counts counts_;
  std::vector<int> candidates_;
  std::vector<int> shading_;  // solids a region says shade the pair
  std::vector<ConvexPolygon> pieces_, next_;
  std::vector<SourcePanel> panels_;
  std::vector<OccluderPolygon> occluders_;
  std::vector<EventPlane> events_;
  std::vector<ConvexPolygon> cells_;
  std::vector<SourcePanel> cellPanels_;
  std::vector<ShadowClipper::HiddenForm> forms_;
  std::vector<int> solidsHere_, solidOccluders_;
  PairTrace* trace_ = nullptr;
};

}  // namespace rt
