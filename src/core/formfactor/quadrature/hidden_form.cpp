// ShadowClipper's hidden forms (shadow_clipper.h): the outline of a hidden part as what its corners are,
// found once per cell by a clip that tags them, and placed at each point of the cell from those tags.
#include <algorithm>
#include <array>
#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/formfactor/lambert_four.h"
#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/solid_silhouette.h"
#include "core/geometry/plane_clip.h"

namespace rt {
namespace {

// A corner of the outline being clipped, with what it is and the line its next edge runs along: receiver
// edge `line`, or (line >= the receiver's corner count n) the side plane of silhouette edge line - n.
struct TaggedCorner {
  Vec3 p;
  ShadowClipper::HiddenForm::Corner tag;
  int line = 0;
};

// The corner two silhouette edges share, or -1.
int sharedCorner(const SilhouetteEdge& e, const SilhouetteEdge& f) {
  if (e.a == f.a || e.a == f.b) return e.a;
  if (e.b == f.a || e.b == f.b) return e.b;
  return -1;
}

}  // namespace

bool ShadowClipper::formOf(const Vec3& x, const std::vector<int>& occluders, HiddenForm& form,
                           double* hidden) const {
  using Form = HiddenForm;
  form.count = 0;
  form.wholly = false;
  form.solid = -1;
  if (occluders.empty() || !shapes_) return false;
  const int solid = prepared_[static_cast<std::size_t>(occluders[0])].solid;
  if (solid < 0 || whole_[static_cast<std::size_t>(solid)] != 1) return false;
  for (int k : occluders)
    if (prepared_[static_cast<std::size_t>(k)].solid != solid) return false;
  const SolidShape& shape = (*shapes_)[static_cast<std::size_t>(solid)];
  constexpr int kInline = ConvexPolygon::kInline;
  SmallBuffer<SilhouetteEdge, kInline> edges;
  edges.reserve(static_cast<int>(shape.edges.size()));  // room for every edge: never -1 for want of it
  const int m = silhouetteEdges(shape, x, eps_, edges.data(), edges.capacity());
  if (m < 3) return false;
  const int n = receiver_.count;
  SmallBuffer<TaggedCorner, kInline> first, second;
  SmallBuffer<TaggedCorner, kInline>*in = &first, *out = &second;  // swapped after each plane
  in->reserve(n);
  SmallBuffer<double, kInline> side;
  for (int k = 0; k < n; ++k)
    (*in)[k] = {receiver_.v[static_cast<std::size_t>(k)], {Form::ReceiverCorner, k}, k};
  int count = n;
  bool cut = false;
  for (int p = 0; p < m; ++p) {
    const SilhouetteEdge& edge = edges[static_cast<std::size_t>(p)];
    const double margin2 = eps_ * eps_ * edge.normal.squaredNorm();
    side.reserve(count);
    bool anyBehind = false, anyFront = false;
    for (int k = 0; k < count; ++k) {
      const double d = edge.normal.dot((*in)[k].p - x);
      if (d * d <= margin2) return false;  // a corner on the side plane: x on an event, the form ambiguous
      side[static_cast<std::size_t>(k)] = d;
      anyBehind |= d < 0;
      anyFront |= d > 0;
    }
    if (!anyBehind) continue;
    form.solid = solid;
    if (!anyFront) return true;  // nothing hidden
    cut = true;
    int made = 0;
    bool ambiguous = false;   // two side planes of no common corner (an end-on edge between)
    out->reserve(2 * count);  // each corner adds itself and a cut at most
    // No corner lies on the plane (see above): the part in front is the corners of height > 0 and the cuts.
    walkHeights(
        side.data(), count,
        [&](int k) {
          if (side[static_cast<std::size_t>(k)] > 0) (*out)[made++] = (*in)[k];
        },
        [&](int k, int next, double t) {
          // The edge from `from` leaves the cone (height > 0) or enters it here: the new corner is where its
          // line meets the side plane, and the outline goes on along the plane, or along the old line.
          const TaggedCorner& from = (*in)[k];
          TaggedCorner corner{from.p + ((*in)[next].p - from.p) * t, {}, 0};
          if (from.line < n) {
            corner.tag = {Form::EdgeCut, from.line, edge.a, edge.b};
          } else {
            const int shared = sharedCorner(edges[static_cast<std::size_t>(from.line - n)], edge);
            ambiguous |= shared < 0;
            corner.tag = {Form::SolidCorner, shared};
          }
          corner.line = side[static_cast<std::size_t>(k)] > 0 ? n + p : from.line;
          (*out)[made++] = corner;
        });
    if (ambiguous) return false;
    std::swap(in, out);
    count = made;
    if (count < 3) return true;
  }
  form.solid = solid;
  form.count = count;
  form.wholly = !cut;
  form.corners.reserve(count);
  for (int k = 0; k < count; ++k) form.corners[static_cast<std::size_t>(k)] = (*in)[k].tag;
  if (hidden && cut) {  // the clipped outline itself, as hidden(x, form) would place it
    SmallBuffer<Vec3, kInline> corners;
    corners.reserve(count);
    for (int k = 0; k < count; ++k) corners[static_cast<std::size_t>(k)] = (*in)[k].p;
    *hidden = std::max(0.0, lambertContourSum(x, sourceNormal_, corners.data(), count));
  }
  return true;
}

bool ShadowClipper::place(const Vec3& x, const HiddenForm& form, Vec3* v) const {
  const SolidShape& shape = (*shapes_)[static_cast<std::size_t>(form.solid)];
  for (int k = 0; k < form.count; ++k) {
    const HiddenForm::Corner& c = form.corners[static_cast<std::size_t>(k)];
    Vec3& corner = v[static_cast<std::size_t>(k)];
    if (c.kind == HiddenForm::ReceiverCorner) {
      corner = receiver_.v[static_cast<std::size_t>(c.a)];
    } else if (c.kind == HiddenForm::SolidCorner) {
      corner =
          shape.corners[static_cast<std::size_t>(c.a)];  // on the ray from x: Lambert's terms need no more
    } else {
      const Vec3& r = receiver_.v[static_cast<std::size_t>(c.a)];
      const Vec3 along = receiver_.v[static_cast<std::size_t>(c.a + 1 == receiver_.count ? 0 : c.a + 1)] - r;
      const Vec3 normal = (shape.corners[static_cast<std::size_t>(c.b)] - x)
                              .cross(shape.corners[static_cast<std::size_t>(c.c)] - x);
      const double t = normal.dot(x - r) / normal.dot(along);
      if (!(t >= -1e-9 && t <= 1 + 1e-9)) return false;
      corner = r + along * std::clamp(t, 0.0, 1.0);
    }
  }
  // Seen from x the outline must stay convex, turning the same way at every corner (to rounding, where a
  // corner nears the next); a form taken beyond its cell (across an event the cut missed) folds over.
  double low = 0, high = 0;
  const int n = form.count;
  double local[ConvexPolygon::kInline];
  double* turn = n <= ConvexPolygon::kInline ? local : plane_clip_detail::spilledHeights<2>(n);
  for (int k = 0; k < n; ++k) {
    const int k1 = k + 1 == n ? 0 : k + 1, k2 = k1 + 1 == n ? 0 : k1 + 1;  // (no modulo: a division each)
    const Vec3 a = v[k] - x, b = v[k1] - x, c = v[k2] - x;
    const double t = a.cross(b).dot(c);
    turn[k] = t;
    low = std::min(low, t), high = std::max(high, t);
  }
  if (low < 0 && high > 0) {  // both ways: only by rounding, against the corners' distances
    const double sign = high > -low ? 1 : -1;
    for (int k = 0; k < n; ++k) {
      const double t = turn[k] * sign;
      if (t >= 0) continue;
      const double scale2 =
          (v[k] - x).squaredNorm() * (v[(k + 1) % n] - x).squaredNorm() * (v[(k + 2) % n] - x).squaredNorm();
      if (t * t > 1e-18 * scale2) return false;
    }
  }
  return true;
}

bool ShadowClipper::hidden(const Vec3& x, const HiddenForm& form, double& value) const {
  if (form.count < 3) {
    value = 0;
    return true;
  }
  SmallBuffer<Vec3, 4 * ConvexPolygon::kInline>& v = placed_;
  v.reserve(form.count);
  if (!place(x, form, v.data())) return false;
  value = std::max(0.0, lambertContourSum(x, sourceNormal_, v.data(), form.count));
  return true;
}

bool ShadowClipper::hidden4(const Vec3* x, const HiddenForm& form, double* values) const {
  if (form.count < 3) {
    std::fill(values, values + 4, 0.0);
    return true;
  }
  const int stride = form.count;
  SmallBuffer<Vec3, 4 * ConvexPolygon::kInline>& v = placed_;
  v.reserve(4 * stride);
  for (int p = 0; p < 4; ++p)
    if (!place(x[p], form, v.data() + p * stride)) return false;
  lambertContourSum4(x, sourceNormal_, v.data(), stride, form.count, values);
  for (int p = 0; p < 4; ++p) values[p] = std::max(0.0, values[p]);
  return true;
}

}  // namespace rt
