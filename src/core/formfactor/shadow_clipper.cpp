#include "core/formfactor/shadow_clipper.h"

#include <algorithm>
#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/formfactor/solid_silhouette.h"

namespace rt {
namespace {

Vec3 centreOf(const SmallPolygon& p) {
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < p.count; ++k) c += p.v[static_cast<std::size_t>(k)];
  return c / std::max(1, p.count);
}

// Only the corners in use: a SmallPolygon holds room for 32, and whole copies cost more than the clipping.
void copyPolygon(const SmallPolygon& from, SmallPolygon& to) {
  to.count = from.count;
  std::copy_n(from.v.begin(), from.count, to.v.begin());
}

// Splits `in` by the plane through `origin` with normal `normal`, corners within `margin` of it (a length
// times the normal's length) counting as on it. Returns 1 when no corner lies behind (nothing written), -1
// when none lies in front (nothing written), 0 when both do: then the part in front goes to `front` and,
// where `back` is given, the part behind to it. In one pass, as the shadow cut of each piece by each side
// plane of a cone needs both parts.
int splitAt(const SmallPolygon& in, const Vec3& origin, const Vec3& normal, double margin,
            SmallPolygon& front, SmallPolygon* back) {
  double side[SmallPolygon::kCapacity];
  bool anyBehind = false, anyFront = false;
  for (int k = 0; k < in.count; ++k) {
    double d = normal.dot(in.v[static_cast<std::size_t>(k)] - origin);
    if (std::abs(d) <= margin) d = 0;
    side[k] = d;
    anyBehind |= d < 0;
    anyFront |= d > 0;
  }
  if (!anyBehind) return 1;  // (a piece wholly on the plane, or a plane of no direction, cuts nothing)
  if (!anyFront) return -1;
  front.count = 0;
  if (back) back->count = 0;
  for (int k = 0; k < in.count && front.count + 2 <= SmallPolygon::kCapacity; ++k) {
    const int next = (k + 1) % in.count;
    const double dp = side[k], dq = side[next];
    const Vec3& p = in.v[static_cast<std::size_t>(k)];
    if (dp >= 0) front.v[static_cast<std::size_t>(front.count++)] = p;
    if (back && dp <= 0 && back->count < SmallPolygon::kCapacity)
      back->v[static_cast<std::size_t>(back->count++)] = p;
    if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0)) {
      const Vec3 cut = p + (in.v[static_cast<std::size_t>(next)] - p) * (dp / (dp - dq));
      front.v[static_cast<std::size_t>(front.count++)] = cut;
      if (back && back->count < SmallPolygon::kCapacity)
        back->v[static_cast<std::size_t>(back->count++)] = cut;
    }
  }
  if (front.count < 3) front.count = 0;
  if (back && back->count < 3) back->count = 0;
  return 0;
}

}  // namespace

void clipToFront(const Vec3* in, int count, const Vec3& origin, const Vec3& normal, double eps,
                 SmallPolygon& out) {
  out.count = 0;
  const double length = normal.norm();
  if (count < 3 || !(length > 0)) return;
  double side[SmallPolygon::kCapacity];
  bool anyBehind = false, anyFront = false;
  for (int k = 0; k < count; ++k) {
    double d = normal.dot(in[k] - origin) / length;
    if (std::abs(d) <= eps) d = 0;
    side[k] = d;
    anyBehind |= d < 0;
    anyFront |= d > 0;
  }
  if (!anyFront) return;
  if (!anyBehind) {
    for (int k = 0; k < count; ++k) out.v[static_cast<std::size_t>(k)] = in[k];
    out.count = count;
    return;
  }
  for (int k = 0; k < count && out.count + 2 <= SmallPolygon::kCapacity; ++k) {
    const int next = (k + 1) % count;
    const double dp = side[k], dq = side[next];
    if (dp >= 0) out.v[static_cast<std::size_t>(out.count++)] = in[k];
    if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0))
      out.v[static_cast<std::size_t>(out.count++)] = in[k] + (in[next] - in[k]) * (dp / (dp - dq));
  }
  if (out.count < 3) out.count = 0;
}

bool polygonCutsEverySegment(const Vec3* from, int fromCount, const Vec3* to, int toCount,
                             const Vec3* polygon, int count, const Vec3& normal, double offset, double eps) {
  if (fromCount < 1 || toCount < 1 || count < 3) return false;
  auto height = [&](const Vec3& p) { return normal.dot(p) - offset; };
  const double side = height(to[0]);
  for (int k = 0; k < toCount; ++k)
    if (!(height(to[k]) * side > 0 && std::abs(height(to[k])) > eps)) return false;
  for (int k = 0; k < fromCount; ++k)
    if (!(height(from[k]) * side < 0 && std::abs(height(from[k])) > eps)) return false;
  for (int f = 0; f < fromCount; ++f)
    for (int t = 0; t < toCount; ++t) {
      const double hf = height(from[f]), ht = height(to[t]);
      const Vec3 crossing = from[f] + (to[t] - from[f]) * (hf / (hf - ht));
      for (int k = 0; k < count; ++k) {
        const Vec3 edge = polygon[(k + 1) % count] - polygon[k];
        if (!(edge.cross(crossing - polygon[k]).dot(normal) > eps * edge.norm())) return false;
      }
    }
  return true;
}

ShadowClipper::ShadowClipper(const SmallPolygon& source, const Vec3& sourceNormal,
                             const SmallPolygon& receiver, const Vec3& receiverNormal,
                             const std::vector<OccluderPolygon>& occluders,
                             const std::vector<SolidPlanes>& solids, const std::vector<Vec3>* solidCentres,
                             const std::vector<SolidShape>* shapes)
    : receiver_(receiver),
      sourceNormal_(sourceNormal),
      solids_(solids),
      solidCentres_(solidCentres),
      shapes_(shapes) {
  const Vec3 cs = centreOf(source), cr = centreOf(receiver);
  double size = (cs - cr).norm();
  for (int k = 0; k < source.count; ++k)
    size = std::max(size, (source.v[static_cast<std::size_t>(k)] - cr).norm());
  eps_ = 1e-10 * size;
  hullPlanes(source.v.data(), source.count, receiver.v.data(), receiver.count);
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
  SmallPolygon front;
  for (const OccluderPolygon& occluder : occluders) {
    const std::vector<Vec3>* polygon = occluder.polygon;
    const int count = static_cast<int>(polygon->size());
    if (count < 3 || count > SmallPolygon::kCapacity - 4) continue;
    Occluder& o = prepared_.emplace_back();
    if (wholeSolid(occluder.solid)) {
      o.polygon.count = count;
      std::copy(polygon->begin(), polygon->end(), o.polygon.v.begin());
    } else {
      clipToFront(polygon->data(), count, source.v[0], sourceNormal, eps_, front);
      clipToFront(front.v.data(), front.count, receiver.v[0], receiverNormal, eps_, o.polygon);
    }
    Vec3 twice = Vec3::Zero();
    for (int k = 0; k < o.polygon.count; ++k)
      twice += o.polygon.v[static_cast<std::size_t>(k)].cross(
          o.polygon.v[static_cast<std::size_t>((k + 1) % o.polygon.count)]);
    const double twiceArea = twice.norm();
    if (o.polygon.count < 3 || 0.5 * twiceArea <= 1e-20 * size * size) {
      prepared_.pop_back();
      continue;
    }
    o.normal = twice / twiceArea;
    o.centre = centreOf(o.polygon);
    o.solid = occluder.solid;
    if (outsideHull(o)) {
      prepared_.pop_back();
      continue;
    }
    all_.push_back(static_cast<int>(prepared_.size()) - 1);
  }
}

void ShadowClipper::hullPlanes(const Vec3* a, int na, const Vec3* b, int nb) const {
  planes_.clear();
  // Faces of the hull of two convex polygons other than their own planes hold an edge of one and a vertex
  // of the other. A plane through an edge of a convex polygon has all of that polygon on one side, the side
  // of its centre, so only the other polygon's corners are tested one by one. The sides are decided on the
  // unnormalised normal (scaling eps by its length) and only a face kept is normalised: most candidates have
  // corners on both sides, found within two or three.
  auto centre = [](const Vec3* p, int n) {
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < n; ++k) c += p[k];
    return Vec3(c / n);
  };
  auto tryEdges = [&](const Vec3* edges, int ne, const Vec3& edgesCentre, const Vec3* others, int no) {
    for (int e = 0; e < ne; ++e) {
      const Vec3& p = edges[e];
      const Vec3 edge = edges[(e + 1) % ne] - p;
      for (int k = 0; k < no; ++k) {
        const Vec3 n = edge.cross(others[k] - p);
        const double length2 = n.squaredNorm();
        if (!(length2 > 0)) continue;
        // |d| > eps |n|, squared: no square root for the many candidates rejected.
        const double margin2 = eps_ * eps_ * length2;
        const double c = n.dot(edgesCentre - p);
        bool above = c > 0 && c * c > margin2, below = c < 0 && c * c > margin2;
        for (int j = 0; j < no && !(above && below); ++j) {
          const double d = n.dot(others[j] - p);
          above |= d > 0 && d * d > margin2;
          below |= d < 0 && d * d > margin2;
        }
        if (above && below) continue;
        const Vec3 unit = (above ? -n : n) / std::sqrt(length2);  // outward: every hull point on or below
        planes_.push_back({unit, unit.dot(p)});
      }
    }
  };
  tryEdges(a, na, centre(a, na), b, nb);
  tryEdges(b, nb, centre(b, nb), a, na);
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

void ShadowClipper::cull(const SourcePanel& panel, const std::vector<int>& in, std::vector<int>& out) const {
  out.clear();
  if (in.empty()) return;
  hullPlanes(panel.v.data(), panel.count, receiver_.v.data(), receiver_.count);
  for (int k : in)
    if (!outsideHull(prepared_[static_cast<std::size_t>(k)])) out.push_back(k);
}

bool ShadowClipper::crossings(const Vec3* panel, int count, const Vec3& normal, double offset) const {
  crossings_.clear();
  double sign = 0;
  double heights[SmallPolygon::kCapacity];
  for (int k = 0; k < receiver_.count; ++k) {
    heights[k] = normal.dot(receiver_.v[static_cast<std::size_t>(k)]) - offset;
    if (std::abs(heights[k]) <= eps_ || (sign != 0 && heights[k] * sign < 0)) return false;
    sign = heights[k];
  }
  for (int p = 0; p < count; ++p) {
    const double h = normal.dot(panel[p]) - offset;
    if (!(h * sign < 0) || std::abs(h) <= eps_) return false;
    for (int k = 0; k < receiver_.count; ++k) {
      const Vec3& r = receiver_.v[static_cast<std::size_t>(k)];
      crossings_.push_back(panel[p] + (r - panel[p]) * (h / (h - heights[k])));
    }
  }
  return true;
}

bool ShadowClipper::hidesAll(const Vec3* panel, int count, const std::vector<int>& occluders) const {
  int lastSolid = -1;
  for (int index : occluders) {
    const Occluder& o = prepared_[static_cast<std::size_t>(index)];
    if (polygonCutsEverySegment(panel, count, receiver_.v.data(), receiver_.count, o.polygon.v.data(),
                                o.polygon.count, o.normal, o.normal.dot(o.centre), eps_))
      return true;
    // A block's faces may share the segments between them; its cross-sections through its centre, across
    // the line of sight and parallel to each face, hold them all.
    if (o.solid < 0 || o.solid == lastSolid || !solidCentres_) continue;
    lastSolid = o.solid;
    const SolidPlanes& solid = solids_[static_cast<std::size_t>(o.solid)];
    const Vec3& centre = (*solidCentres_)[static_cast<std::size_t>(o.solid)];
    Vec3 panelCentre = Vec3::Zero();
    for (int p = 0; p < count; ++p) panelCentre += panel[p];
    const Vec3 sight = (centreOf(receiver_) - panelCentre / count).normalized();
    for (std::size_t plane = 0; plane <= solid.size(); ++plane) {
      const Vec3 normal = plane == 0 ? sight : solid[plane - 1].first;
      if (!crossings(panel, count, normal, normal.dot(centre))) continue;
      bool inside = true;
      for (std::size_t c = 0; c < crossings_.size() && inside; ++c)
        for (const auto& [n, offset] : solid)
          if (!(n.dot(crossings_[c]) - offset < -eps_)) {
            inside = false;
            break;
          }
      if (inside) return true;
    }
  }
  return false;
}

double ShadowClipper::probeShadow(const SourcePanel& panel, const std::vector<int>& occluders,
                                  long& points) const {
  const Vec3& origin = panel.v[0];
  double best = 0;
  SmallPolygon projected, clipped;
  // Clips `projected` to the panel (the planes through its edges along the source's normal) and probes
  // the centre of what is left.
  // The panel's edge planes, found once for all probes.
  Vec3 edgeNormals[4];
  for (int k = 0; k < panel.count; ++k)
    edgeNormals[k] = sourceNormal_.cross(panel.v[static_cast<std::size_t>((k + 1) % panel.count)] -
                                         panel.v[static_cast<std::size_t>(k)]);
  // Projections that cover the whole panel (or the same part of it) give the same probe: evaluated once.
  Vec3 probed[64];
  int probedCount = 0;
  auto probe = [&]() {
    for (int k = 0; k < panel.count && projected.count >= 3; ++k) {
      clipToFront(projected.v.data(), projected.count, panel.v[static_cast<std::size_t>(k)], edgeNormals[k],
                  eps_, clipped);
      copyPolygon(clipped, projected);
    }
    if (projected.count < 3) return;
    const Vec3 x = centreOf(projected);
    for (int k = 0; k < probedCount; ++k)
      if ((probed[k] - x).cwiseAbs().maxCoeff() <= eps_) return;
    if (probedCount < 64) probed[probedCount++] = x;
    best = std::max(best, hidden(x, occluders));
    ++points;
  };
  double receiverHeight[SmallPolygon::kCapacity];
  for (int r = 0; r < receiver_.count; ++r)
    receiverHeight[r] = sourceNormal_.dot(receiver_.v[static_cast<std::size_t>(r)] - origin);
  // The point of the source plane on the line from r through o, when o lies between the plane and r (o
  // itself when it stands on the plane).
  auto through = [&](int r, const Vec3& o, double oHeight) {
    const double rHeight = receiverHeight[r];
    if (!(oHeight >= -eps_ && rHeight - oHeight > eps_)) return;
    const Vec3& rv = receiver_.v[static_cast<std::size_t>(r)];
    projected.v[static_cast<std::size_t>(projected.count++)] =
        rv + (o - rv) * (rHeight / (rHeight - oHeight));
  };
  // A solid's corner is a corner of three faces or more: each is probed once. (Its faces seen from behind,
  // though covered by those seen from the front, are probed too: their projections' centres found the
  // shadows that the front faces' missed on the 612-wall grid room, 1.2e-5 off without them.)
  std::vector<Vec3>& probedCorners = probed_;
  probedCorners.clear();
  for (int index : occluders) {
    const Occluder& occluder = prepared_[static_cast<std::size_t>(index)];
    const SmallPolygon& o = occluder.polygon;
    double oHeight[SmallPolygon::kCapacity];
    for (int k = 0; k < o.count; ++k)
      oHeight[k] = sourceNormal_.dot(o.v[static_cast<std::size_t>(k)] - origin);
    for (int r = 0; r < receiver_.count; ++r) {
      projected.count = 0;
      for (int k = 0; k < o.count; ++k) through(r, o.v[static_cast<std::size_t>(k)], oHeight[k]);
      probe();
    }
    for (int k = 0; k < o.count; ++k) {
      const Vec3& corner = o.v[static_cast<std::size_t>(k)];
      if (occluder.solid >= 0) {
        if (std::find(probedCorners.begin(), probedCorners.end(), corner) != probedCorners.end()) continue;
        probedCorners.push_back(corner);
      }
      projected.count = 0;
      for (int r = 0; r < receiver_.count; ++r) through(r, corner, oHeight[k]);
      probe();
    }
  }
  return best;
}

double ShadowClipper::unoccluded(const Vec3& x) const {
  return std::max(0.0, lambertContourSum(x, sourceNormal_, receiver_.v.data(), receiver_.count));
}

bool ShadowClipper::cutCone(const Vec3& x, const Vec3* cone, int m, bool last, double& sum) const {
  double margin[SmallPolygon::kCapacity];
  for (int k = 0; k < m; ++k) margin[k] = eps_ * cone[k].norm();
  next_.clear();
  SmallPolygon buffers[2];
  bool anyLeft = false;  // of the receiver, some part outside this cone and every one before
  for (const SmallPolygon& piece : pieces_) {
    // Wholly outside one side plane: untouched by this shadow (checked first so that it is not cut into
    // pieces by the planes before it, which the occluders after this one would each have to cut again).
    bool clear = false;
    for (int k = 0; k < m && !clear && !last; ++k) {
      bool anyInside = false;
      for (int v = 0; v < piece.count && !anyInside; ++v)
        anyInside = cone[k].dot(piece.v[static_cast<std::size_t>(v)] - x) > margin[k];
      clear = !anyInside;
    }
    if (clear) {
      copyPolygon(piece, next_.emplace_back());
      anyLeft = true;
      continue;
    }
    const SmallPolygon* inside = &piece;
    int which = 0;  // the buffer the next split writes: never the one `inside` is in
    for (int k = 0; k < m && inside; ++k) {
      SmallPolygon& part = buffers[which];
      SmallPolygon* outside = last ? nullptr : &next_.emplace_back();
      const int side = splitAt(*inside, x, cone[k], margin[k], part, outside);
      if (side > 0) {
        if (outside) next_.pop_back();
        continue;
      }
      anyLeft = true;
      if (side < 0) {
        if (outside) copyPolygon(*inside, *outside);
        inside = nullptr;
        break;
      }
      if (outside && outside->count == 0) next_.pop_back();
      inside = part.count > 0 ? &part : nullptr;
      which ^= 1;
    }
    if (inside) sum += lambertContourSum(x, sourceNormal_, inside->v.data(), inside->count);
  }
  // The last cone needs no pieces left over, only whether any would be.
  if (last) return anyLeft;
  pieces_.swap(next_);
  return !pieces_.empty();
}

double ShadowClipper::hidden(const Vec3& x, const std::vector<int>& occluders, bool* whollyHidden) const {
  if (whollyHidden) *whollyHidden = false;
  pieces_.resize(1);
  copyPolygon(receiver_, pieces_[0]);
  double sum = 0;
  std::array<Vec3, SmallPolygon::kCapacity> cone;
  outside_.assign(solids_.size(), -1);
  if (shapes_) cut_.assign(whole_.size(), 0);
  // From `tail` on, every occluder bounds one solid wholly in front: cut by its silhouette there, it is the
  // last shadow, and the parts of the receiver it leaves need not be kept for another.
  const int n = static_cast<int>(occluders.size());
  int tail = n;
  auto wholeSolid = [&](int position) {
    const int solid =
        prepared_[static_cast<std::size_t>(occluders[static_cast<std::size_t>(position)])].solid;
    return solid >= 0 && shapes_ && whole_[static_cast<std::size_t>(solid)] == 1 ? solid : -1;
  };
  if (n > 0 && wholeSolid(n - 1) >= 0)
    for (tail = n - 1; tail > 0 && wholeSolid(tail - 1) == wholeSolid(n - 1);) --tail;
  bool anyLeft = true;
  for (int position = 0; position < n && anyLeft; ++position) {
    const Occluder& o = prepared_[static_cast<std::size_t>(occluders[static_cast<std::size_t>(position)])];
    if (o.solid >= 0 && shapes_ && whole_[static_cast<std::size_t>(o.solid)] == 1) {
      signed char& cut = cut_[static_cast<std::size_t>(o.solid)];
      if (cut == 1) continue;  // the solid's silhouette is cut already
      if (cut == 0) {
        const int m = silhouetteCone((*shapes_)[static_cast<std::size_t>(o.solid)], x, eps_, cone.data(),
                                     SmallPolygon::kCapacity);
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
    for (int k = 0; k < m; ++k) {
      const Vec3 a = o.polygon.v[static_cast<std::size_t>(k)] - x,
                 b = o.polygon.v[static_cast<std::size_t>((k + 1) % m)] - x;
      Vec3 n = a.cross(b);
      if (n.dot(o.centre - x) < 0) n = -n;  // inward: the cone's inside in front
      cone[static_cast<std::size_t>(k)] = n;
    }
    anyLeft = cutCone(x, cone.data(), m, position == n - 1, sum);
  }
  if (whollyHidden) *whollyHidden = !anyLeft;
  return std::max(0.0, sum);
}

}  // namespace rt
