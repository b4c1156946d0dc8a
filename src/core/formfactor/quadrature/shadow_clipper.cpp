#include "core/formfactor/quadrature/shadow_clipper.h"

#include <algorithm>
#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/formfactor/lambert_four.h"
#include "core/formfactor/quadrature/penumbra_region.h"
#include "core/formfactor/quadrature/shadow_clipper_detail.h"
#include "core/formfactor/quadrature/solid_silhouette.h"
#include "core/geometry/plane_clip.h"

namespace rt {

ShadowClipper::ShadowClipper(const std::vector<SolidPlanes>& solids, const std::vector<Vec3>* solidCentres,
                             const std::vector<SolidShape>* shapes)
    : solids_(solids), solidCentres_(solidCentres), shapes_(shapes) {}

ShadowClipper::ShadowClipper(const ConvexPolygon& source, const Vec3& sourceNormal,
                             const ConvexPolygon& receiver, const Vec3& receiverNormal,
                             const std::vector<OccluderPolygon>& occluders,
                             const std::vector<SolidPlanes>& solids, const std::vector<Vec3>* solidCentres,
                             const std::vector<SolidShape>* shapes)
    : ShadowClipper(solids, solidCentres, shapes) {
  prepare(source, sourceNormal, receiver, receiverNormal, occluders);
}

void ShadowClipper::prepare(const ConvexPolygon& source, const Vec3& sourceNormal,
                            const ConvexPolygon& receiver, const Vec3& receiverNormal,
                            const std::vector<OccluderPolygon>& occluders) {
  receiver_.assign(receiver);
  sourceOrigin_ = source.v[0];
  sourceNormal_ = sourceNormal;
  prepared_.clear();
  all_.clear();
  whole_.clear();
  penumbraMade_.clear();
  eps_ = shadowEps(source, receiver);
  const double size = 1e10 * eps_;
  // A solid reaching behind either plane has faces clipped there (and a cap missing): it is cut face by
  // face. One wholly in front needs no clipping, and hidden() cuts it by its silhouette.
  if (shapes_) whole_.assign(shapes_->size(), -1);
  auto wholeSolid = [&](int solid) {
    if (solid < 0 || !shapes_ || static_cast<std::size_t>(solid) >= shapes_->size()) return false;
    signed char& whole = whole_[static_cast<std::size_t>(solid)];
    if (whole < 0) {
      whole = 1;
      for (const Vec3& c : (*shapes_)[static_cast<std::size_t>(solid)].corners)
        if (sourceNormal.dot(c - source.v[0]) < -eps_ || receiverNormal.dot(c - receiver.v[0]) < -eps_) {
          whole = 0;
          break;
        }
    }
    return whole == 1;
  };
  ConvexPolygon front;
  bool planesMade = false;
  int lastSolid = -1;  // the solid whose region was tested last, and what it said
  bool lastOutside = false;
  for (const OccluderPolygon& occluder : occluders) {
    const std::vector<Vec3>* polygon = occluder.polygon;
    const int count = static_cast<int>(polygon->size());
    if (count < 3) continue;
    Occluder& o = prepared_.emplace_back();
    if (wholeSolid(occluder.solid)) {
      o.polygon.assign(polygon->data(), count);
    } else {
      clipToFront(polygon->data(), count, source.v[0], sourceNormal, eps_, front);
      clipToFront(front.v.data(), front.count, receiver.v[0], receiverNormal, eps_, o.polygon);
    }
    const Vec3 twice = twiceAreaVector(o.polygon.data(), o.polygon.count);
    const double twiceArea = twice.norm();
    if (o.polygon.count < 3 || 0.5 * twiceArea <= 1e-20 * size * size) {
      prepared_.pop_back();
      continue;
    }
    o.normal = twice / twiceArea;
    o.centre = o.polygon.centre();
    o.solid = occluder.solid;
    // As cull() has it: a whole solid by the region it can shade (once for all its faces), the rest by the
    // hull of the two; nothing when the caller knows it shades the pair.
    bool outside;
    if (occluder.shades) {
      outside = false;
    } else if (o.solid >= 0 && o.solid == lastSolid) {
      outside = lastOutside;
    } else if (const PenumbraRegion* region = penumbra(o.solid)) {
      outside = !region->meets(source.v.data(), source.count);
      lastSolid = o.solid;
      lastOutside = outside;
    } else {
      if (!planesMade) {
        hullPlanes(source.v.data(), source.count, receiver.v.data(), receiver.count);
        planesMade = true;
      }
      outside = outsideHull(o);
    }
    if (outside) {
      prepared_.pop_back();
      continue;
    }
    all_.push_back(static_cast<int>(prepared_.size()) - 1);
  }
}

void ShadowClipper::hullPlanes(const Vec3* a, int na, const Vec3* b, int nb) const {
  planes_.clear();
  // Planes through an edge of one polygon and a corner of the other (forEachEdgeCornerPlane): a face of the
  // hull when no corner of the other polygon lies strictly on the far side from the edge's own polygon. The
  // sides are decided on the unnormalised normal and only a face kept is normalised: most candidates have
  // corners on both sides, found within two or three.
  auto tryEdges = [&](const Vec3* edges, int ne, const Vec3& edgesCentre, const Vec3* others, int no) {
    shadow_detail::forEachEdgeCornerPlane(
        edges, ne, others, no, eps_, [&](const Vec3& p, const Vec3& n, double margin2) {
          const double c = n.dot(edgesCentre - p);
          bool above = c > 0 && c * c > margin2, below = c < 0 && c * c > margin2;
          for (int j = 0; j < no && !(above && below); ++j) {
            const double d = n.dot(others[j] - p);
            above |= d > 0 && d * d > margin2;
            below |= d < 0 && d * d > margin2;
          }
          if (above && below) return false;
          const Vec3 unit = (above ? -n : n) / n.norm();  // outward: every hull point on or below
          planes_.push_back({unit, unit.dot(p)});
          return false;
        });
  };
  tryEdges(a, na, cornerMean(a, na), b, nb);
  tryEdges(b, nb, cornerMean(b, nb), a, na);
}

bool ShadowClipper::outsideHull(const Occluder& o) const {
  for (const auto& [n, offset] : planes_) {
    bool inside = false;
    for (int k = 0; k < o.polygon.count && !inside; ++k)
      inside = n.dot(o.polygon.v[static_cast<std::size_t>(k)]) - offset < -eps_;
    if (!inside) return true;
  }
  return false;
}

const PenumbraRegion* ShadowClipper::penumbra(int solid) const {
  if (solid < 0 || whole_.empty() || whole_[static_cast<std::size_t>(solid)] != 1) return nullptr;
  if (penumbraMade_.empty()) {
    if (penumbrae_.size() < whole_.size()) penumbrae_.resize(whole_.size());
    penumbraMade_.assign(whole_.size(), -1);
  }
  signed char& made = penumbraMade_[static_cast<std::size_t>(solid)];
  if (made < 0) {
    const SolidShape& shape = (*shapes_)[static_cast<std::size_t>(solid)];
    made = penumbrae_[static_cast<std::size_t>(solid)].build(
        shape.corners.data(), static_cast<int>(shape.corners.size()), receiver_.v.data(), receiver_.count,
        sourceOrigin_, sourceNormal_, eps_);
  }
  return made == 1 ? &penumbrae_[static_cast<std::size_t>(solid)] : nullptr;
}

void ShadowClipper::cull(const SourcePanel& panel, const std::vector<int>& in, std::vector<int>& out) const {
  out.clear();
  if (in.empty()) return;
  // A whole solid's faces go together, kept where the panel meets the region the solid can shade and
  // dropped where it does not (kept faces the solid's silhouette covers cost a few more probes, far less
  // than the hull); the rest are tested one by one against the hull of the panel and the receiver, made
  // only when needed.
  bool planesMade = false;
  int lastSolid = -1;
  bool lastMeets = false;
  for (int k : in) {
    const Occluder& o = prepared_[static_cast<std::size_t>(k)];
    if (const PenumbraRegion* region = penumbra(o.solid)) {
      if (o.solid != lastSolid) {
        lastSolid = o.solid;
        lastMeets = region->meets(panel.v.data(), panel.count);
      }
      if (lastMeets) out.push_back(k);
      continue;
    }
    if (!planesMade) {
      hullPlanes(panel.v.data(), panel.count, receiver_.v.data(), receiver_.count);
      planesMade = true;
    }
    if (!outsideHull(o)) out.push_back(k);
  }
}

double ShadowClipper::unoccluded(const Vec3& x) const {
  return std::max(0.0, lambertContourSum(x, sourceNormal_, receiver_.v.data(), receiver_.count));
}

bool ShadowClipper::cutCone(const Vec3& x, const Vec3* cone, int m, bool last, double& sum) const {
  // (eps |n|)^2: splitByPlane's margin, with no square root. On the stack for a cone of up to kInline planes.
  double local[ConvexPolygon::kInline];
  double* margin2 = local;
  if (m > ConvexPolygon::kInline) {
    margin2_.reserve(m);
    margin2 = margin2_.data();
  }
  for (int k = 0; k < m; ++k) margin2[k] = eps_ * eps_ * cone[k].squaredNorm();
  // next_ is a pool: its first nextCount slots are the pieces kept. Slots are added only when it grows, as
  // a new ConvexPolygon is zeroed whole (768 bytes).
  int nextCount = 0;
  auto slot = [&]() -> ConvexPolygon& {
    if (nextCount == static_cast<int>(next_.size())) next_.emplace_back();
    return next_[static_cast<std::size_t>(nextCount)];
  };
  ConvexPolygon* buffers = split_;
  bool anyLeft = false;  // of the receiver, some part outside this cone and every one before
  for (int p = 0; p < pieceCount_; ++p) {
    const ConvexPolygon& piece = pieces_[static_cast<std::size_t>(p)];
    // Wholly outside one side plane: untouched by this shadow (checked first so that it is not cut into
    // pieces by the planes before it, which the occluders after this one would each have to cut again).
    bool clear = false;
    for (int k = 0; k < m && !clear && !last; ++k) {
      bool anyInside = false;
      for (int v = 0; v < piece.count && !anyInside; ++v) {
        const double d = cone[k].dot(piece.v[static_cast<std::size_t>(v)] - x);
        anyInside = d > 0 && d * d > margin2[k];
      }
      clear = !anyInside;
    }
    if (clear) {
      slot().assign(piece);
      ++nextCount;
      anyLeft = true;
      continue;
    }
    const ConvexPolygon* inside = &piece;
    int which = 0;  // the buffer the next split writes: never the one `inside` is in
    for (int k = 0; k < m && inside; ++k) {
      ConvexPolygon& part = buffers[which];
      ConvexPolygon* outside = last ? nullptr : &slot();
      const int side = splitByPlane(*inside, x, cone[k], margin2[k], part, outside);
      if (side > 0) continue;
      anyLeft = true;
      if (side < 0) {
        if (outside) {
          outside->assign(*inside);
          ++nextCount;
        }
        inside = nullptr;
        break;
      }
      if (outside && outside->count > 0) ++nextCount;
      inside = part.count > 0 ? &part : nullptr;
      which ^= 1;
    }
    if (inside) addHidden(x, *inside, sum);
  }
  // The last cone needs no pieces left over, only whether any would be.
  if (last) return anyLeft;
  pieces_.swap(next_);
  pieceCount_ = nextCount;
  return pieceCount_ > 0;
}

void ShadowClipper::addHidden(const Vec3& x, const ConvexPolygon& piece, double& sum) const {
  Pending& pending = pending_[static_cast<std::size_t>(pendingCount_++)];
  pending.piece.assign(piece);
  pending.x = x;
  pending.sum = &sum;
  if (pendingCount_ == static_cast<int>(pending_.size())) flushHidden();
}

void ShadowClipper::flushHidden() const {
  if (pendingCount_ == 1) {
    const Pending& only = pending_[0];
    *only.sum += lambertContourSum(only.x, sourceNormal_, only.piece.v.data(), only.piece.count);
  } else if (pendingCount_ > 1) {
    Vec3 points[4];
    const Vec3* polygons[4];
    int counts[4];
    double values[4];
    for (std::size_t p = 0; p < 4; ++p) {
      const bool used = static_cast<int>(p) < pendingCount_;
      points[p] = pending_[used ? p : 0].x;
      polygons[p] = pending_[p].piece.v.data();
      counts[p] = used ? pending_[p].piece.count : 0;
    }
    lambertContourSum4(points, sourceNormal_, polygons, counts, values);
    for (int p = 0; p < pendingCount_; ++p) *pending_[static_cast<std::size_t>(p)].sum += values[p];
  }
  pendingCount_ = 0;
}

double ShadowClipper::hidden(const Vec3& x, const std::vector<int>& occluders, bool* whollyHidden) const {
  double sum = 0;
  clipHidden(x, occluders, sum, whollyHidden);
  flushHidden();
  return std::max(0.0, sum);
}

void ShadowClipper::hidden4(const Vec3* x, const std::vector<int>& occluders, double* values,
                            bool* whollyHidden) const {
  for (int p = 0; p < 4; ++p) {
    values[p] = 0;
    clipHidden(x[p], occluders, values[p], whollyHidden ? whollyHidden + p : nullptr);
  }
  flushHidden();
  for (int p = 0; p < 4; ++p) values[p] = std::max(0.0, values[p]);
}

void ShadowClipper::clipHidden(const Vec3& x, const std::vector<int>& occluders, double& sum,
                               bool* whollyHidden) const {
  if (whollyHidden) *whollyHidden = false;
  if (pieces_.empty()) pieces_.emplace_back();
  pieces_[0].assign(receiver_);
  pieceCount_ = 1;
  SmallBuffer<Vec3, ConvexPolygon::kInline>& cone = cone_;
  outside_.assign(solids_.size(), -1);
  if (shapes_) cut_.assign(whole_.size(), 0);
  // From `tail` on, every occluder bounds one solid wholly in front: cut by its silhouette there, it is the
  // last shadow, and the parts of the receiver it leaves need not be kept for another.
  const int count = static_cast<int>(occluders.size());
  int tail = count;
  auto wholeSolid = [&](int position) {
    const int solid =
        prepared_[static_cast<std::size_t>(occluders[static_cast<std::size_t>(position)])].solid;
    return solid >= 0 && shapes_ && whole_[static_cast<std::size_t>(solid)] == 1 ? solid : -1;
  };
  if (count > 0 && wholeSolid(count - 1) >= 0)
    for (tail = count - 1; tail > 0 && wholeSolid(tail - 1) == wholeSolid(count - 1);) --tail;
  bool anyLeft = true;
  for (int position = 0; position < count && anyLeft; ++position) {
    const Occluder& o = prepared_[static_cast<std::size_t>(occluders[static_cast<std::size_t>(position)])];
    if (o.solid >= 0 && shapes_ && whole_[static_cast<std::size_t>(o.solid)] == 1) {
      signed char& cut = cut_[static_cast<std::size_t>(o.solid)];
      if (cut == 1) continue;  // the solid's silhouette is cut already
      if (cut == 0) {
        const SolidShape& shape = (*shapes_)[static_cast<std::size_t>(o.solid)];
        cone.reserve(static_cast<int>(shape.edges.size()));  // room for every edge: never -1 for want of it
        const int m = silhouetteCone(shape, x, eps_, cone.data(), cone.capacity());
        cut = m >= 3 ? 1 : 2;  // x not outside (or a degenerate silhouette): face by face
        if (cut == 1) {
          anyLeft = cutCone(x, cone.data(), m, position >= tail, sum);
          continue;
        }
      }
    }
    const double height = o.normal.dot(x - o.centre);
    if (std::abs(height) <= eps_) continue;  // seen edge-on: hides no area
    if (o.solid >= 0 && height < 0) {
      signed char& outside = outside_[static_cast<std::size_t>(o.solid)];
      if (outside < 0) {
        outside = 0;
        for (const auto& [n, offset] : solids_[static_cast<std::size_t>(o.solid)])
          if (n.dot(x) - offset > eps_) outside = 1;
      }
      if (outside == 1) continue;  // a back face of a solid x is outside of: its front faces cover it
    }
    const int m = o.polygon.count;
    cone.reserve(m);
    for (int k = 0; k < m; ++k) {
      const Vec3 a = o.polygon.v[static_cast<std::size_t>(k)] - x,
                 b = o.polygon.v[static_cast<std::size_t>((k + 1) % m)] - x;
      Vec3 n = a.cross(b);
      if (n.dot(o.centre - x) < 0) n = -n;  // inward: the cone's inside in front
      cone[static_cast<std::size_t>(k)] = n;
    }
    anyLeft = cutCone(x, cone.data(), m, position == count - 1, sum);
  }
  if (whollyHidden) *whollyHidden = !anyLeft;
}

}  // namespace rt
