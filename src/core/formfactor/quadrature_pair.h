// One pair of the quadrature method (quadrature_method.cpp), on one thread: F_ij = U_ij - H_ij, from the
// smaller element i.
//
// In order, each step cheaper than the next and ending the pair where it can:
//  1. the shaft test's candidate occluders; each block among them judged from its penumbra and umbra
//     regions (block_shadow_regions.h): dropped where it misses the pair, the pair done where it hides all;
//  2. a block's cross-sections tried as a proof that it hides all (shadow_clipper.h), unless its regions said
//     it shades only part;
//  3. U: the exact contour integral for near pairs, Gauss quadrature of Lambert's formula with an a-priori
//     order (source_panels.h) elsewhere;
//  4. H, where occluders remain after the clipper's own tests: over cells cut along the visibility events
//     where there is one occluder or two whole blocks (visibility_events.h), each block over its own cells
//     where their shadows never overlap (shadow_overlap.h), by the guarded adaptive rules otherwise
//     (hidden_integral.h).
// Keeps its working vectors from pair to pair: millions of pairs would otherwise spend as long in the heap as
// in the arithmetic.
#pragma once

#include <algorithm>
#include <vector>

#include "core/formfactor/block_shadow_regions.h"
#include "core/formfactor/hidden_integral.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/quadrature_scene.h"
#include "core/formfactor/shadow_clipper.h"
#include "core/formfactor/visibility.h"
#include "core/formfactor/visibility_events.h"

namespace rt {

class QuadraturePair {
 public:
  // What the notes report, summed over threads at the end.
  struct Counts {
    long points = 0, clipped = 0, placed = 0, contours = 0, budgetPairs = 0, occludedPairs = 0,
         hiddenPairs = 0, eventPairs = 0, apartPairs = 0;
    Counts& operator+=(const Counts& o) {
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

 private:
  // Drops the blocks that miss the pair from candidates_; true when one hides all of it. `sourceCentre` and
  // `receiverCentre` are the clipped polygons' centres.
  bool judgeBlocks(int i, int j, int row, const ElementPolygon& a, const ElementPolygon& b,
                   const SmallPolygon& source, const SmallPolygon& receiver, const Vec3& sourceCentre,
                   const Vec3& receiverCentre);

  // H solid by solid, where every occluder left bounds a convex solid, there are several, and no segment
  // from i to j passes through two of them (QuadratureScene::shadowsApart): then H is the sum of what each
  // hides alone, and each of those is integrated over cells cut along its own events (visibility_events.h
  // leaves several occluders out: their shadows' crossings are events that are not planes, but apart they
  // never cross). False (`sum` unset) where that does not hold or the cells would be too many; the adaptive
  // rules take the pair then. `eps`: shadowEps() of the pair.
  bool hiddenSolidBySolid(int i, int j, const SmallPolygon& source, double eps, HiddenIntegral& hidden,
                          double tolerance, double& sum);

  // The gap between element i, whole (`source` its corners), and the receiver: the distance between their
  // bounding spheres, or the source's height over the receiver's plane where that is more.
  double gapOf(int i, const SmallPolygon& source, const ReceiverBound& receiver) const;
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
  std::vector<SmallPolygon> pieces_, next_;
  std::vector<SourcePanel> panels_;
  std::vector<OccluderPolygon> occluders_;
  std::vector<EventPlane> events_;
  std::vector<SmallPolygon> cells_;
  std::vector<SourcePanel> cellPanels_;
  std::vector<ShadowClipper::HiddenForm> forms_;
  std::vector<int> solidsHere_, solidOccluders_;
};

}  // namespace rt
