// The part of a receiver that occluders hide from one point, in double precision, and the form factor of it.
//
// From a point x on the source, an occluder O hides the part of the receiver R inside the cone from x over O.
// Cutting R into convex pieces by the cone's side planes (planes through x and each edge of O) and dropping
// the piece inside all of them removes that shadow exactly, up to rounding of the cut lines (~1e-16 of the
// scene's size); one occluder after another, the pieces left are the visible part of R, and the dropped
// pieces, which do not overlap, the hidden part. Lambert's formula on the dropped pieces gives the hidden
// form factor F(dA_x -> hidden part of R). This is the exact reference's split path (src/exact) without its
// exact predicates.
//
// Occluders are first clipped to what can cast a shadow (in front of the source's plane and of the
// receiver's plane) and then culled against the convex hull of the source and the receiver: a convex
// occluder that lies outside one face plane of that hull cannot cut any segment from source to receiver.
// The same test on a part of the source (a panel) tells where visibility cannot change, so adaptive
// quadrature splits only where it can.
#pragma once

#include <array>
#include <vector>

#include "core/formfactor/quadrature/penumbra_region.h"
#include "core/formfactor/quadrature/segment_proofs.h"
#include "core/formfactor/quadrature/source_panels.h"
#include "core/geometry/convex_polygon.h"
#include "core/geometry/small_buffer.h"
#include "core/vec.h"

namespace rt {

// The margin (a length) the shadow clipper's tests use between a source and a receiver: 1e-10 of the pair's
// size.
double shadowEps(const ConvexPolygon& source, const ConvexPolygon& receiver);

// An occluder: a convex polygon, counter-clockwise seen from its front, and the closed convex solid it
// bounds (or -1). A segment from a point outside such a solid that crosses it enters through a face the
// point is in front of, so from there the faces it sees from behind need not be clipped.
struct SolidShape;  // solid_silhouette.h
struct EventPlane;  // visibility_events.h

struct OccluderPolygon {
  const std::vector<Vec3>* polygon;
  int solid = -1;
  bool shades = false;  // known to shade part of the pair (block_shadow_regions.h): not tested again
};

class ShadowClipper {
 public:
  // source and receiver already horizon-clipped against each other. Keeps the occluders that may cut a
  // segment from the source to the receiver. `solids` outlives the clipper.
  // `solidCentres`, a point inside each solid, lets hidesAll() use the solids' cross-sections. `shapes`, the
  // solids' faces and edges, lets hidden() cut a solid wholly in front of both planes by the one cone of its
  // silhouette instead of face by face.
  ShadowClipper(const ConvexPolygon& source, const Vec3& sourceNormal, const ConvexPolygon& receiver,
                const Vec3& receiverNormal, const std::vector<OccluderPolygon>& occluders,
                const std::vector<SolidPlanes>& solids, const std::vector<Vec3>* solidCentres = nullptr,
                const std::vector<SolidShape>* shapes = nullptr);
  // One to prepare() for pair after pair (its buffers kept: a method computing millions of pairs would
  // otherwise spend as long in the heap as in the clipping).
  explicit ShadowClipper(const std::vector<SolidPlanes>& solids,
                         const std::vector<Vec3>* solidCentres = nullptr,
                         const std::vector<SolidShape>* shapes = nullptr);
  // What the first constructor does, for a new pair.
  void prepare(const ConvexPolygon& source, const Vec3& sourceNormal, const ConvexPolygon& receiver,
               const Vec3& receiverNormal, const std::vector<OccluderPolygon>& occluders);

  // Indices of the occluders kept (all of them may block).
  const std::vector<int>& occluders() const { return all_; }
  // The solid occluder `k` bounds, or -1.
  int solidOf(int k) const { return prepared_[static_cast<std::size_t>(k)].solid; }
  // Whether `occluders` bound more than one solid (or mix a solid with polygons of none).
  bool ofSeveralSolids(const std::vector<int>& occluders) const {
    for (int k : occluders)
      if (solidOf(k) != solidOf(occluders.front())) return true;
    return false;
  }
  // Occluder `k` as kept (clipped to the front of both planes, or a whole solid's face), and the source's
  // plane.
  const ConvexPolygon& polygonOf(int k) const { return prepared_[static_cast<std::size_t>(k)].polygon; }
  const Vec3& sourceOrigin() const { return sourceOrigin_; }
  const Vec3& sourceNormal() const { return sourceNormal_; }
  // Of `in`, those that may cut a segment from `panel` to the receiver, into `out`.
  void cull(const SourcePanel& panel, const std::vector<int>& in, std::vector<int>& out) const;
  // True when one of `occluders`, or the solid one of them bounds, cuts every segment from the panel
  // (`count` corners) to the receiver, with a margin: then the whole receiver is hidden from all of it.
  // Every such segment crosses a plane that separates the two at a point in the convex hull of the
  // crossings of the corner-to-corner segments, so those crossings lying inside a convex face (or a convex
  // solid's cross-section) is enough. `bySolids` false leaves the solids' cross-sections out (a caller that
  // has tried them already with solidCutsEverySegment).
  bool hidesAll(const Vec3* panel, int count, const std::vector<int>& occluders, bool bySolids = true) const;
  // F(dA_x -> the part of the receiver hidden by `occluders`) for x on the source; `whollyHidden`, where
  // given, tells whether nothing of the receiver is left in view.
  double hidden(const Vec3& x, const std::vector<int>& occluders, bool* whollyHidden = nullptr) const;
  // The same at four points, their hidden pieces' Lambert sums taken four at a time (lambert_four.h).
  void hidden4(const Vec3* x, const std::vector<int>& occluders, double* values,
               bool* whollyHidden = nullptr) const;
  // Where sample points of a panel saw no shadow although an occluder passed the hull test: the largest
  // hidden(x) over probe points x that aim at a shadow. From a point of the panel inside the projection of
  // an occluder from a receiver corner, that corner is hidden; from one inside the projection of the
  // receiver through an occluder corner, that corner's shadow falls on the receiver. Each projection is
  // clipped to the panel and probed at its centre, so a shadow that grazes the receiver from a sliver of the
  // source only (a block's top corner cutting a floor-to-ceiling pair) is found however thin it is. `points`
  // counts the evaluations.
  double probeShadow(const SourcePanel& panel, const std::vector<int>& occluders, long& points) const;
  // F(dA_x -> the whole receiver).
  double unoccluded(const Vec3& x) const;

  // The form of the part of the receiver one convex solid hides from x: its outline's corners, each a corner
  // of the receiver, a corner of the solid's silhouette (the hidden part's corner lies behind it from x), or
  // where the plane through x and a silhouette edge cuts an edge of the receiver. Over a cell of the source
  // cut along the visibility events (visibility_events.h) the form stays the same and only the corners move,
  // so hidden(x, form) places them without clipping: a fifth of the cost of a point
  // (docs/formfactor-methods.md).
  struct HiddenForm {
    enum Kind : signed char { ReceiverCorner, SolidCorner, EdgeCut };
    struct Corner {
      Kind kind = ReceiverCorner;
      int a = 0;         // the receiver's or the solid's corner; for EdgeCut, the receiver edge from corner a
      int b = 0, c = 0;  // EdgeCut: the silhouette edge's corners
    };
    SmallBuffer<Corner, ConvexPolygon::kInline> corners;
    int count = 0;        // 0: nothing hidden
    bool wholly = false;  // the whole receiver hidden
    int solid = -1;
  };
  // The form at x, for `occluders` that are faces of one solid wholly in front of both planes. False where
  // there is none to tell: other occluders, or x within eps of an event (a corner on a side plane).
  // `hidden`, where given, receives F(dA_x -> hidden part) from the clipped outline, where part of the
  // receiver is hidden (the form then has three corners or more).
  bool formOf(const Vec3& x, const std::vector<int>& occluders, HiddenForm& form,
              double* hidden = nullptr) const;
  // F(dA_x -> hidden part) from a form found at another point of the same cell. False (`value` unset) where
  // the form does not fit x: a cut outside its receiver edge, or an outline that no longer turns one way.
  bool hidden(const Vec3& x, const HiddenForm& form, double& value) const;
  // The same at four points at once (a 2 x 2 rule, lambert_four.h); false where the form fits none or only
  // some of them.
  bool hidden4(const Vec3* x, const HiddenForm& form, double* values) const;
  // The planes along which the hidden part's form changes over the source (visibility_events.h), into
  // `out`. False when `occluders` are not one solid or one polygon: then the events are not all planes.
  bool eventPlanes(const ConvexPolygon& source, const std::vector<int>& occluders,
                   std::vector<EventPlane>& out) const;

 private:
  struct Occluder {
    ConvexPolygon polygon;  // clipped to the front of the source's and the receiver's planes
    Vec3 centre;
    Vec3 normal;  // unit
    int solid = -1;
  };
  // Outward face planes (unit normal, offset) of the convex hull of the points a and b.
  void hullPlanes(const Vec3* a, int na, const Vec3* b, int nb) const;
  bool outsideHull(const Occluder& o) const;
  // Cuts the shadow of the cone from x (`m` inward side planes) out of pieces_, adding the form factor of the
  // cut parts to `sum`, and keeps the parts left for the next cone unless this one is the `last`. Returns
  // whether any part is left.
  bool cutCone(const Vec3& x, const Vec3* cone, int m, bool last, double& sum) const;
  // hidden() without the last Lambert sums: the hidden pieces are added to `sum` by flushHidden().
  void clipHidden(const Vec3& x, const std::vector<int>& occluders, double& sum, bool* whollyHidden) const;
  // Hidden pieces wait in pending_ to have their Lambert sums taken four at a time, each added to the sum
  // of its point when four are waiting or at flushHidden().
  void addHidden(const Vec3& x, const ConvexPolygon& piece, double& sum) const;
  void flushHidden() const;
  // The corners of a hidden form's outline from x, into `v`; false where the form does not fit x.
  bool place(const Vec3& x, const HiddenForm& form, Vec3* v) const;

  // The region of the source's plane a whole solid can shade (null when unbounded or not a whole solid).
  const PenumbraRegion* penumbra(int solid) const;

  ConvexPolygon receiver_;
  Vec3 sourceOrigin_;
  Vec3 sourceNormal_;
  double eps_ = 0;  // a length: 1e-10 of the pair's size
  const std::vector<SolidPlanes>& solids_;
  const std::vector<Vec3>* solidCentres_;
  const std::vector<SolidShape>* shapes_;
  std::vector<signed char> whole_;    // per solid: wholly in front of both planes (1), cut by its silhouette
  mutable std::vector<Vec3> probed_;  // probeShadow(): the solids' corners probed already
  std::vector<Occluder> prepared_;
  std::vector<int> all_;
  mutable std::vector<std::pair<Vec3, double>> planes_;
  mutable std::vector<ConvexPolygon> pieces_, next_;  // pools: the first pieceCount_ of pieces_ are in use
  mutable int pieceCount_ = 0;
  struct Pending {
    ConvexPolygon piece;
    Vec3 x;
    double* sum = nullptr;
  };
  mutable std::array<Pending, 4> pending_;
  // clipHidden()'s cone and cutCone()'s margins: kept, so that an occluder of many corners allocates once.
  mutable SmallBuffer<Vec3, ConvexPolygon::kInline> cone_;
  mutable SmallBuffer<double, ConvexPolygon::kInline> margin2_;
  mutable ConvexPolygon split_[2];                                // cutCone()'s parts inside the cone
  mutable SmallBuffer<Vec3, 4 * ConvexPolygon::kInline> placed_;  // hidden forms' outlines, four at a time
  mutable int pendingCount_ = 0;
  mutable std::vector<signed char> outside_;       // per solid, for the current point: -1 not yet known
  mutable std::vector<PenumbraRegion> penumbrae_;  // per solid, made on first use
  mutable std::vector<signed char> penumbraMade_;  // -1 not yet, 0 unbounded, 1 made
  mutable std::vector<signed char> cut_;  // per solid, for the current point: 0 not yet, 1 cut, 2 by faces
};

}  // namespace rt
