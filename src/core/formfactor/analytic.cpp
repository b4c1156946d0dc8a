#include "core/formfactor/analytic.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/formfactor/gauss_legendre.h"
#include "core/geometry/plane_clip.h"
#include "core/polygon.h"

namespace rt {
namespace {

constexpr double kInvTwoPi = 0.5 / std::numbers::pi;

// Antiderivative in u of ln sqrt(u^2 + h^2): the inner integral along a line at distance h.
double logLineIntegral(double u, double h) {
  const double rr = u * u + h * h;
  if (rr == 0) return 0;
  double value = 0.5 * u * std::log(rr) - u;
  if (h > 0) value += h * std::atan(u / h);
  return value;
}

// Second antiderivative: the double integral of ln r over two parallel lines at distance h.
double logLineIntegral2(double u, double h) {
  const double rr = u * u + h * h;
  if (rr == 0) return 0;
  double value = 0.25 * (u * u - h * h) * std::log(rr) - 0.75 * u * u;
  if (h > 0) value += h * u * std::atan(u / h);
  return value;
}

struct Segment {
  Vec3 start;
  Vec3 direction;  // unit
  double length;
};

Segment segmentOf(const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double length = d.norm();
  return {a, length > 0 ? Vec3(d / length) : Vec3::Zero(), length};
}

// int_0^L ln |p - (start + t direction)| dt, in closed form.
double innerIntegral(const Vec3& p, const Segment& b) {
  const Vec3 w = p - b.start;
  const double foot = w.dot(b.direction);
  const double h = (w - foot * b.direction).norm();
  return logLineIntegral(b.length - foot, h) - logLineIntegral(-foot, h);
}

// Distance from the point q to the part [s0, s1] of segment a.
double pointPanelDistance(const Segment& a, double s0, double s1, const Vec3& q) {
  const double s = std::clamp((q - a.start).dot(a.direction), s0, s1);
  return (a.start + s * a.direction - q).norm();
}

// Where the inner integral I(s) = int_b ln |a(s) - q| dq stops being analytic. In closed form (innerIntegral)
// it depends on s through |a(s) - end|^2 for the two ends of b, and through the distance h(s) of a(s) from
// b's line, whose square is a quadratic in s. So its complex singularities are (1) at s_e +- i d_e for each
// end e of b, s_e the foot of e on a and d_e its distance from a's line, and (2) at s* +- i h_min / sine,
// with s* the closest approach of the two lines. The distance from a real panel to the points of (1) is the
// 3D distance from the panel to e; for (2) it is hypot(distance from s* to the panel, h_min / sine). These
// are isolated points, so bisecting towards them ends after a logarithmic number of panels, for every
// configuration. (Grading towards the whole of b instead never ends for edges that are almost collinear
// over a long stretch: every panel stays closer to b than its own length.)
struct Singularities {
  Vec3 end0, end1;
  double closest = 0;    // s*
  double imaginary = 0;  // h_min / sine
};

Singularities singularitiesOf(const Segment& a, const Segment& b, double sine) {
  Singularities out{b.start, b.start + b.length * b.direction, 0, 0};
  const Vec3 w = a.start - b.start;
  const double cosine = a.direction.dot(b.direction), d = a.direction.dot(w), e = b.direction.dot(w);
  const double denominator = sine * sine;
  out.closest = (cosine * e - d) / denominator;
  const double t = (e - cosine * d) / denominator;
  const double hMin = (w + out.closest * a.direction - t * b.direction).norm();
  out.imaginary = hMin / sine;
  return out;
}

double singularityDistance(const Segment& a, double s0, double s1, const Singularities& z) {
  const double real = std::max({0.0, s0 - z.closest, z.closest - s1});
  return std::min({pointPanelDistance(a, s0, s1, z.end0), pointPanelDistance(a, s0, s1, z.end1),
                   std::hypot(real, z.imaginary)});
}

// Number of Gauss-Legendre points for a panel whose nearest singularity is `ratio` panel lengths away: the
// error of the n-point rule decays like rho^-2n with rho the Bernstein ellipse through that singularity
// (worst case: above the panel's middle). Aim at 1e-16.
// A panel on a singularity (ratio 0) comes only from the recursion's floor, 1e-15 of the edge long: its share
// is below rounding, and the lowest order does.
int pointsForRatio(double ratio) {
  if (!(ratio > 0)) return 4;
  const double rho = 2 * ratio + std::sqrt(1 + 4 * ratio * ratio);
  return static_cast<int>(std::clamp(std::ceil(18.5 / std::log(rho)), 4.0, 24.0));
}

double integratePanel(const Segment& a, const Segment& b, double s0, double s1, double distance) {
  const double length = s1 - s0;
  if (length <= 0) return 0;
  const QuadratureRule& rule = gaussLegendre(pointsForRatio(distance / length));
  double sum = 0;
  for (std::size_t k = 0; k < rule.nodes.size(); ++k)
    sum += rule.weights[k] * innerIntegral(a.start + (s0 + length * rule.nodes[k]) * a.direction, b);
  return sum * length;
}

// int over [s0, s1] of the inner integral. A panel at least its own length away from every singularity of
// the integrand gets one Gauss rule (order from that ratio); closer panels are bisected, which grades them
// geometrically towards each singularity and keeps every rule converged. The depth bound is a safety net:
// with isolated singularities the floor ends the recursion first.
double integrateAdaptive(const Segment& a, const Segment& b, const Singularities& z, double s0, double s1,
                         double floor, int depth = 0) {
  constexpr int kMaxDepth = 64;
  const double length = s1 - s0;
  if (length <= 0) return 0;
  const double distance = singularityDistance(a, s0, s1, z);
  if (distance >= length || length <= floor || depth >= kMaxDepth)
    return integratePanel(a, b, s0, s1, distance);
  const double middle = 0.5 * (s0 + s1);
  return integrateAdaptive(a, b, z, s0, middle, floor, depth + 1) +
         integrateAdaptive(a, b, z, middle, s1, floor, depth + 1);
}

// int_a int_b ln r ds dt over two segments (arc length).
double edgePairIntegral(const Segment& a, const Segment& b) {
  if (a.length == 0 || b.length == 0) return 0;
  const double sine = a.direction.cross(b.direction).norm();
  if (sine < 1e-13) {
    // Parallel or collinear: closed form of the double integral along the common direction.
    const Vec3 w0 = b.start - a.start;
    const Vec3 w1 = w0 + b.length * b.direction;
    const double beta0 = w0.dot(a.direction), beta1 = w1.dot(a.direction);
    const double lo = std::min(beta0, beta1), hi = std::max(beta0, beta1);
    const double h = 0.5 * ((w0 - beta0 * a.direction).norm() + (w1 - beta1 * a.direction).norm());
    return logLineIntegral2(a.length - lo, h) - logLineIntegral2(-lo, h) -
           logLineIntegral2(a.length - hi, h) + logLineIntegral2(-hi, h);
  }
  return integrateAdaptive(a, b, singularitiesOf(a, b, sine), 0, a.length,
                           1e-15 * std::max(a.length, b.length));
}

Vec3 unitNormal(const Vec3* v, int n) {
  const Vec3 sum = twiceAreaVector(v, n);
  const double length = sum.norm();
  return length > 0 ? Vec3(sum / length) : Vec3::Zero();
}

double areaOf(const Vec3* v, int n) {
  return 0.5 * twiceAreaVector(v, n).norm();
}

// Sutherland-Hodgman against one plane into `out` (capacity n + 1). Returns the vertex count, 0 when nothing
// is in front (entirely behind, or lying in the plane).
int clipInto(const Vec3* v, int n, const Vec3& origin, const Vec3& normal, Vec3* out) {
  if (n <= 0) return 0;
  double scale = 0;
  for (int k = 0; k < n; ++k) scale = std::max(scale, (v[k] - origin).norm());
  const double eps = 1e-12 * scale * normal.norm();
  constexpr int kStack = 64;
  double stackSide[kStack];
  std::vector<double> heapSide;
  double* side = stackSide;
  if (n > kStack) {
    heapSide.resize(n);
    side = heapSide.data();
  }
  bool anyBehind = false, anyFront = false;
  for (int k = 0; k < n; ++k) {
    double d = normal.dot(v[k] - origin);
    if (std::abs(d) <= eps) d = 0;
    side[k] = d;
    anyBehind |= d < 0;
    anyFront |= d > 0;
  }
  if (!anyFront) return 0;
  int count = 0;
  if (!anyBehind) {
    for (int k = 0; k < n; ++k) out[count++] = v[k];
    return count;
  }
  cutByHeights(
      v, side, n, [&](const Vec3& p) { out[count++] = p; }, [](const Vec3&) {});
  return count >= 3 ? count : 0;
}

double contourArea(const Vec3* from, int m, const Vec3* to, int n) {
  double sum = 0;
  for (int p = 0; p < m; ++p) {
    const Segment a = segmentOf(from[p], from[(p + 1) % m]);
    for (int q = 0; q < n; ++q) {
      const Segment b = segmentOf(to[q], to[(q + 1) % n]);
      const double alignment = a.direction.dot(b.direction);
      if (alignment == 0) continue;  // perpendicular edges exchange nothing in the contour integral
      sum += alignment * edgePairIntegral(a, b);
    }
  }
  return kInvTwoPi * sum;
}

double lambertSum(const Vec3& point, const Vec3& normal, const Vec3* v, int n) {
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const Vec3 a = v[k] - point, b = v[k + 1 == n ? 0 : k + 1] - point;  // (no modulo: a division each)
    const Vec3 c = a.cross(b);
    const double sine = c.norm();  // |a||b| sin(theta)
    if (sine == 0) continue;       // edge seen edge-on (or through the point): no solid angle
    const double theta = std::atan2(sine, a.dot(b));
    sum += theta * normal.dot(c) / sine;
  }
  // A polygon facing the point runs clockwise as seen from it: the raw sum is negative.
  return -kInvTwoPi * sum;
}

// Scratch space for clipped copies without touching the heap for mesh-sized polygons.
struct ClipBuffer {
  static constexpr int kInline = 15;
  Vec3 inlineStorage[kInline + 1];
  std::vector<Vec3> heap;
  Vec3* reserve(int n) {
    if (n <= kInline) return inlineStorage;
    heap.resize(n + 1);
    return heap.data();
  }
};

// Far apart, the double contour integral of ln r loses about (distance / size)^2 of its digits to
// cancellation (0.3 % at 1000 sizes apart); Lambert's formula integrated over the source does not: its
// integrand is analytic over the source, with the nearest singularity on the receiver, so a Gauss rule whose
// order follows that distance converges fast. Collapsed product rule on a fan of triangles.
double farFieldArea(const Vec3* from, int m, const Vec3* to, int n, const Vec3& normal, int points) {
  const QuadratureRule& rule = gaussLegendre(points);
  double sum = 0;
  for (int t = 1; t + 1 < m; ++t) {
    const Vec3 e1 = from[t] - from[0], e2 = from[t + 1] - from[t];
    const double scale = e1.cross(e2).norm();
    for (std::size_t i = 0; i < rule.nodes.size(); ++i)
      for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
        const double u = rule.nodes[i], v = rule.nodes[j];
        const Vec3 x = from[0] + u * e1 + (u * v) * e2;
        sum += rule.weights[i] * rule.weights[j] * u * scale * std::max(0.0, lambertSum(x, normal, to, n));
      }
  }
  return sum;
}

// Centre (vertex average) and radius of a polygon's bounding sphere around it.
void boundingSphere(const Vec3* v, int n, Vec3& centre, double& radius) {
  centre = Vec3::Zero();
  for (int k = 0; k < n; ++k) centre += v[k];
  centre /= n;
  radius = 0;
  for (int k = 0; k < n; ++k) radius = std::max(radius, (v[k] - centre).norm());
}

}  // namespace

Polygon clipPolygonToPlane(const Polygon& polygon, const Vec3& origin, const Vec3& normal) {
  Polygon out(polygon.size() + 1);
  const int count = clipInto(polygon.data(), static_cast<int>(polygon.size()), origin, normal, out.data());
  out.resize(count);
  return out;
}

double lambertContourSum(const Vec3& point, const Vec3& normal, const Polygon& polygon) {
  return lambertSum(point, normal, polygon.data(), static_cast<int>(polygon.size()));
}

double lambertContourSum(const Vec3& point, const Vec3& normal, const Vec3* polygon, int count) {
  return lambertSum(point, normal, polygon, count);
}

double pointToPolygonFormFactor(const Vec3& point, const Vec3& normal, const Vec3* polygon, int count) {
  if (count < 3) return 0;
  const Vec3 polygonNormal = twiceAreaVector(polygon, count);
  if (polygonNormal.dot(point - polygon[0]) <= 0) return 0;  // behind the polygon: one-sided
  ClipBuffer buffer;
  Vec3* visible = buffer.reserve(count);
  const int n = clipInto(polygon, count, point, normal, visible);
  if (n < 3) return 0;
  return std::max(0.0, lambertSum(point, normal, visible, n));
}

double pointToPolygonFormFactor(const Vec3& point, const Vec3& normal, const Polygon& polygon) {
  return pointToPolygonFormFactor(point, normal, polygon.data(), static_cast<int>(polygon.size()));
}

double contourFormFactorArea(const Polygon& from, const Polygon& to) {
  return contourArea(from.data(), static_cast<int>(from.size()), to.data(), static_cast<int>(to.size()));
}

double polygonToPolygonFormFactor(const Vec3* from, int m, const Vec3* to, int n) {
  if (m < 3 || n < 3) return 0;
  const double area = areaOf(from, m);
  if (!(area > 0)) return 0;
  const Vec3 ni = unitNormal(from, m), nj = unitNormal(to, n);
  ClipBuffer toBuffer, fromBuffer;
  Vec3* toVisible = toBuffer.reserve(n);
  const int nv = clipInto(to, n, from[0], ni, toVisible);
  if (nv < 3) return 0;
  Vec3* fromVisible = fromBuffer.reserve(m);
  const int mv = clipInto(from, m, to[0], nj, fromVisible);
  if (mv < 3) return 0;
  // Edge-on leftovers have no area facing the other side.
  if (areaOf(toVisible, nv) <= 1e-14 * areaOf(to, n) || areaOf(fromVisible, mv) <= 1e-14 * area) return 0;
  // Well separated (a gap of more than twice the two radii): Lambert over the source, see farFieldArea.
  Vec3 ci, cj;
  double ri, rj;
  boundingSphere(fromVisible, mv, ci, ri);
  boundingSphere(toVisible, nv, cj, rj);
  const double gap = (ci - cj).norm() - ri - rj;
  if (gap > 2 * (ri + rj))
    return std::max(0.0,
                    farFieldArea(fromVisible, mv, toVisible, nv, ni, pointsForRatio(gap / (2 * ri))) / area);
  return std::max(0.0, contourArea(fromVisible, mv, toVisible, nv) / area);
}

double polygonToPolygonFormFactor(const Polygon& from, const Polygon& to) {
  return polygonToPolygonFormFactor(from.data(), static_cast<int>(from.size()), to.data(),
                                    static_cast<int>(to.size()));
}

double pointToPointKernel(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny) {
  const Vec3 d = y - x;
  const double r2 = d.squaredNorm();
  if (r2 <= 0) return 0;
  // The cosines are d.n / r each: r^4 below, not r^2.
  return std::max(0.0, nx.dot(d)) * std::max(0.0, -ny.dot(d)) / (std::numbers::pi * r2 * r2);
}

}  // namespace rt
