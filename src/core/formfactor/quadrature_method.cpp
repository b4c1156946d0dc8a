// "quadrature": every entry to an absolute tolerance, one knob (`tolerance`) setting the cost.
//
//   F_ij = U_ij - H_ij,  U_ij = (1/A_i) int_i F(dA_x -> j) dA_x,  H_ij = (1/A_i) int_i F(dA_x -> hidden j)
//   dA_x
//
// U, the unoccluded form factor: pairs closer than one source size are given the exact contour integral (its
// cost does not depend on the tolerance, and quadrature would need many points there). All others get
// Gauss-Legendre quadrature of Lambert's formula over the source, the order read off an a-priori bound for
// each panel (source_panels.h), panels split where the order would exceed 8. A far pair at a loose
// tolerance gets one point (the centroid rule) only when the bound allows it.
//
// H, the hidden part, only where occluders survive the shaft test and the hull test (shadow_clipper.h): the
// hidden part of the receiver from each point, clipped in double precision, integrated by adaptive
// quadrature over the source. A panel is compared with its four children; where the two disagree by more
// than the panel's share of the tolerance, the children are split again. Children that no occluder can
// touch contribute exactly 0 and are never split, so the work concentrates along the penumbrae. Depth and
// points per pair are bounded; pairs that reach the bound are counted in the notes.
//
// Both halves are computed from the smaller element of a pair (pair_matrix.h), so the tolerance holds for
// F_ij and F_ji alike. Rows are spread over the cores by TBB's work stealing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "core/formfactor/analytic.h"
#include "core/formfactor/analytic_method.h"
#include "core/formfactor/block_shadow_regions.h"
#include "core/formfactor/closed_solids.h"
#include "core/formfactor/hidden_integral.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/shadow_clipper.h"
#include "core/formfactor/shaft_culling.h"
#include "core/formfactor/solid_silhouette.h"
#include "core/formfactor/source_panels.h"
#include "core/formfactor/visibility.h"
#include "core/formfactor/visibility_events.h"

namespace rt {
namespace {

constexpr double kNearSizes = 1.0;  // closer than this many source sizes: exact contour integral
constexpr int kMaxUnoccludedDepth = 6;
constexpr int kMaxEventCells = 64;  // more, and the adaptive rules cost less than the cells
// `gap` and `edge`, where known (>= 0), are panelGap() and the longest edge of the panel.
double integrateUnoccluded(const SourcePanel& panel, const ReceiverBound& bound, const SmallPolygon& receiver,
                           const Vec3& normal, double tolerance, int depth, PairWork& work, double gap = -1,
                           double edge = -1) {
  int n = gap >= 0 ? gaussOrderFor(gap, edge, panel.count, bound.area, tolerance)
                   : gaussOrderFor(panel, bound, tolerance);
  if (n == 0 && depth < kMaxUnoccludedDepth) {
    double sum = 0;
    for (const SourcePanel& child : panel.split())
      sum += integrateUnoccluded(child, bound, receiver, normal, tolerance, depth + 1, work);
    return sum;
  }
  if (n == 0) n = kMaxOrder;
  double sum = 0;
  forEachGaussPoint(panel, n, [&](const Vec3& x, double w) {
    sum += w * std::max(0.0, lambertContourSum(x, normal, receiver.v.data(), receiver.count));
  });
  work.points += n * n;
  return sum;
}

// The receiver as the a-priori order sees it.
ReceiverBound boundOf(const SmallPolygon& receiver, const Vec3& normal) {
  ReceiverBound bound{receiver.v[0], normal, Vec3::Zero(), 0, 0};
  Vec3 twice = Vec3::Zero();
  for (int k = 0; k < receiver.count; ++k) {
    bound.centre += receiver.v[static_cast<std::size_t>(k)];
    twice += receiver.v[static_cast<std::size_t>(k)].cross(
        receiver.v[static_cast<std::size_t>((k + 1) % receiver.count)]);
  }
  bound.centre /= receiver.count;
  for (int k = 0; k < receiver.count; ++k)
    bound.radius = std::max(bound.radius, (receiver.v[static_cast<std::size_t>(k)] - bound.centre).norm());
  bound.area = 0.5 * twice.norm();
  return bound;
}

class QuadratureMethod : public FormFactorMethod {
 public:
  std::string name() const override { return "quadrature"; }
  AccuracyKnob knob() const override {
    return {AccuracyKnob::Field::Tolerance,
            "ff-tolerance",
            "absolute error allowed in each form factor",
            1e-9,
            0.1,
            1e-5};
  }
  std::string description() const override {
    return "every entry to an absolute --tolerance: exact contour integral for near pairs, Gauss quadrature "
           "of Lambert's formula with an a-priori order elsewhere, the hidden part clipped per point in "
           "double precision and integrated adaptively along the penumbrae";
  }

  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                                 FormFactorStats& stats) const override {
    const ShaftCulling shafts(mesh);
    const double tolerance = std::clamp(options.tolerance, 1e-12, 0.5);
    const int hiddenOrder = 2;  // low: the hidden part has kinks and jumps
    // Occluders are whole patches where a patch is convex (its outline covers exactly its elements), the
    // elements otherwise.
    std::vector<double> patchArea(shafts.patchCount(), 0.0);
    std::vector<std::vector<int>> patchElements(shafts.patchCount());
    for (std::size_t e = 0; e < mesh.size(); ++e) {
      patchArea[static_cast<std::size_t>(mesh.elements[e].patch)] += mesh.elements[e].area;
      patchElements[static_cast<std::size_t>(mesh.elements[e].patch)].push_back(static_cast<int>(e));
    }
    std::vector<bool> convex(shafts.patchCount(), false);
    std::vector<std::vector<Vec3>> elementPolygons(mesh.size());
    for (std::size_t k = 0; k < shafts.patchCount(); ++k) {
      const std::vector<Vec3>& outline = shafts.outline(static_cast<int>(k));
      Vec3 sum = Vec3::Zero();
      for (std::size_t v = 0; v < outline.size(); ++v)
        sum += outline[v].cross(outline[(v + 1) % outline.size()]);
      convex[k] = std::abs(0.5 * sum.norm() - patchArea[k]) <= 1e-9 * patchArea[k];
      if (!convex[k])
        for (int e : patchElements[k]) elementPolygons[static_cast<std::size_t>(e)] = mesh.polygon(e);
    }
    const std::vector<Vec3> none;
    std::vector<const std::vector<Vec3>*> outlines;
    for (std::size_t k = 0; k < shafts.patchCount(); ++k)
      outlines.push_back(convex[k] ? &shafts.outline(static_cast<int>(k)) : &none);
    std::vector<SolidPlanes> solids;
    const std::vector<int> solidOf = closedConvexSolids(outlines, solids);
    const std::vector<SolidShape> shapes = solidShapes(outlines, solidOf, static_cast<int>(solids.size()));
    // A point inside each solid, for the proofs by cross-sections: its shape's centre.
    std::vector<Vec3> solidCentres;
    for (const SolidShape& shape : shapes) solidCentres.push_back(shape.centre);
    // The solids each element reaches into (a floor element partly under a block): that part sees nothing,
    // and the jump at the block's edge is cut out of the source instead of left to the quadrature.
    std::vector<std::vector<int>> elementSolids(mesh.size());
    for (std::size_t e = 0; e < mesh.size() && !solids.empty(); ++e) {
      const ElementPolygon polygon(mesh, static_cast<int>(e));
      SmallPolygon small;
      small.count = polygon.count;
      std::copy(polygon.v.begin(), polygon.v.begin() + polygon.count, small.v.begin());
      const double eps = 1e-9 * std::sqrt(mesh.elements[e].area);
      const int own = solidOf[static_cast<std::size_t>(mesh.elements[e].patch)];
      for (std::size_t s = 0; s < solids.size(); ++s)
        if (static_cast<int>(s) != own && areaInside(small, solids[s], eps) > 1e-9 * mesh.elements[e].area)
          elementSolids[e].push_back(static_cast<int>(s));
    }
    // What the notes report, counted per thread: shared atomics cost a fifth of an unoccluded room's time
    // (two cores taking turns at one cache line for every pair).
    struct Counts {
      long points = 0, clipped = 0, contours = 0, budgetPairs = 0, occludedPairs = 0, hiddenPairs = 0,
           eventPairs = 0;
    };

    // Per thread: the pair's working vectors, kept from pair to pair.
    struct PairScratch {
      std::vector<int> candidates;
      std::vector<SmallPolygon> pieces, next;
      std::vector<SourcePanel> panels;
      std::vector<OccluderPolygon> occluders;
      std::vector<EventPlane> events;
      std::vector<SmallPolygon> cells;
      std::vector<SourcePanel> cellPanels;
      std::vector<int> shading;  // solids a region says shade the pair
      Counts counts;
    };
    tbb::enumerable_thread_specific<PairScratch> scratches;
    double sceneSize = 0;
    for (const Vec3& v : mesh.vertices) sceneSize = std::max(sceneSize, v.cwiseAbs().maxCoeff());
    const double regionEps = 1e-10 * sceneSize;
    tbb::enumerable_thread_specific<RowShadowRegions> rowRegions(std::cref(shapes), regionEps);
    std::vector<std::vector<Vec3>> polygons;
    std::vector<Vec3> normals;
    if (!solids.empty())
      for (std::size_t e = 0; e < mesh.size(); ++e) {
        polygons.push_back(mesh.polygon(static_cast<int>(e)));
        normals.push_back(mesh.elements[e].normal);
      }
    const ContactShadowRegions contactRegions(shapes, static_cast<int>(polygons.size()), polygons, normals,
                                              regionEps);
    static thread_local int rowElement = -1;  // the element the current row of the matrix is fixed at
    tbb::enumerable_thread_specific<ShadowClipper> clippers(std::cref(solids), &solidCentres, &shapes);

    // Per element, what the a-priori order needs of it whole (most pairs clip neither element): its bound as
    // a receiver, and its centre, radius and longest edge as a source panel.
    struct ElementMeasure {
      ReceiverBound bound;
      double longest = 0;
    };
    std::vector<ElementMeasure> measures(mesh.size());
    for (std::size_t e = 0; e < mesh.size(); ++e) {
      const ElementPolygon polygon(mesh, static_cast<int>(e));
      SmallPolygon small;
      small.count = polygon.count;
      std::copy(polygon.v.begin(), polygon.v.begin() + polygon.count, small.v.begin());
      measures[e].bound = boundOf(small, mesh.elements[e].normal);
      for (int k = 0; k < polygon.count; ++k)
        measures[e].longest =
            std::max(measures[e].longest, (polygon.v[static_cast<std::size_t>((k + 1) % polygon.count)] -
                                           polygon.v[static_cast<std::size_t>(k)])
                                              .norm());
    }

    auto integrate = [&](int i, int j) {
      PairResult result;
      PairWork work;
      const ElementPolygon a(mesh, i), b(mesh, j);
      const Vec3 &ni = mesh.elements[static_cast<std::size_t>(i)].normal,
                 &nj = mesh.elements[static_cast<std::size_t>(j)].normal;
      const double areaI = mesh.elements[static_cast<std::size_t>(i)].area;
      const double scale = (mesh.elements[static_cast<std::size_t>(i)].centroid -
                            mesh.elements[static_cast<std::size_t>(j)].centroid)
                               .norm();
      SmallPolygon source, receiver;
      const bool receiverWhole = clipToFront(b.v.data(), b.count, a.v[0], ni, 1e-12 * scale, receiver);
      const bool sourceWhole = clipToFront(a.v.data(), a.count, b.v[0], nj, 1e-12 * scale, source);
      if (source.count < 3 || receiver.count < 3) return result;
      PairScratch& scratch = scratches.local();
      std::vector<int>& candidates = scratch.candidates;
      candidates.clear();
      shafts.candidates(i, j, candidates);
      // What each block does to the pair, read off regions made once per row or per element on the floor a
      // block stands on (block_shadow_regions.h): more than half of the blocks the shaft test lets through
      // miss the pair, and most pairs they hide wholly are found so.
      scratch.shading.clear();
      if (!candidates.empty() && !solids.empty() && (rowElement == i || rowElement == j)) {
        const bool rowIsSource = rowElement == i;
        const ElementPolygon &row = rowIsSource ? a : b, &otherFull = rowIsSource ? b : a;
        const SmallPolygon& other = rowIsSource ? receiver : source;
        const int otherElement = rowIsSource ? j : i;
        RowShadowRegions& regions = rowRegions.local();
        int last = -1;
        BlockVerdict verdict = BlockVerdict::Unknown;
        for (int& k : candidates) {
          const int solid = solidOf[static_cast<std::size_t>(k)];
          if (solid < 0) continue;
          if (solid != last) {
            verdict = contactRegions.judge(solid, rowElement, row.v.data(), row.count, otherElement);
            if (verdict == BlockVerdict::Unknown)
              verdict =
                  contactRegions.judge(solid, otherElement, otherFull.v.data(), otherFull.count, rowElement);
            if (verdict == BlockVerdict::Unknown)
              verdict =
                  regions.judge(rowElement, row.v.data(), row.count, solid, other.v.data(), other.count,
                                other.v[0], mesh.elements[static_cast<std::size_t>(otherElement)].normal);
            if (verdict == BlockVerdict::HidesAll) {
              result.needsVisibility = true;
              ++scratch.counts.occludedPairs;
              ++scratch.counts.hiddenPairs;
              return result;
            }
          }
          if (solid != last && verdict == BlockVerdict::Shades) scratch.shading.push_back(solid);
          last = solid;
          if (verdict == BlockVerdict::Misses) k = -1;
        }
        std::erase(candidates, -1);
      }
      // A block between them that cuts every segment from one to the other (most occluded pairs of a room
      // with blocks in it): proven from its cross-sections alone, before anything else is prepared.
      if (!candidates.empty() && !solids.empty()) {
        const double eps = shadowEps(source, receiver);
        int last = -1;
        for (int k : candidates) {
          const int solid = solidOf[static_cast<std::size_t>(k)];
          if (solid < 0 || solid == last) continue;
          last = solid;
          if (solidCutsEverySegment(source.v.data(), source.count, receiver.v.data(), receiver.count,
                                    solids[static_cast<std::size_t>(solid)],
                                    solidCentres[static_cast<std::size_t>(solid)], eps)) {
            result.needsVisibility = true;
            ++scratch.counts.occludedPairs;
            ++scratch.counts.hiddenPairs;
            return result;
          }
        }
      }
      const ReceiverBound bound =
          receiverWhole ? measures[static_cast<std::size_t>(j)].bound : boundOf(receiver, nj);

      std::vector<SmallPolygon>&pieces = scratch.pieces, &next = scratch.next;
      pieces.assign(1, source);
      for (int s : elementSolids[static_cast<std::size_t>(i)]) {
        next.clear();
        for (const SmallPolygon& piece : pieces)
          piecesOutside(piece, solids[static_cast<std::size_t>(s)], 1e-12 * scale, next);
        pieces.swap(next);
      }
      std::vector<SourcePanel>& panels = scratch.panels;
      panels.clear();
      for (const SmallPolygon& piece : pieces) {
        std::array<SourcePanel, SmallPolygon::kCapacity> fan;
        const int made = panelsOf(piece.v.data(), piece.count, fan.data(), SmallPolygon::kCapacity);
        panels.insert(panels.end(), fan.begin(), fan.begin() + made);
      }
      const int panelCount = static_cast<int>(panels.size());
      bool near = false;
      // The source whole (nothing cut off by the receiver's plane or a block it reaches under) and one panel:
      // its gap from what is known of the element.
      double topGap = -1, topEdge = -1;
      if (sourceWhole && panelCount == 1 && elementSolids[static_cast<std::size_t>(i)].empty()) {
        const ReceiverBound& own = measures[static_cast<std::size_t>(i)].bound;
        double height = INFINITY;
        for (int k = 0; k < source.count; ++k)
          height = std::min(height, std::abs(nj.dot(source.v[static_cast<std::size_t>(k)] - bound.point)));
        topGap = std::max((own.centre - bound.centre).norm() - own.radius - bound.radius, height);
        topEdge = measures[static_cast<std::size_t>(i)].longest;
        near = topGap < kNearSizes * topEdge;
      }
      for (int p = 0; p < panelCount && !near && topGap < 0; ++p)
        near = panelGap(panels[static_cast<std::size_t>(p)], bound) <
               kNearSizes * panels[static_cast<std::size_t>(p)].longestEdge();
      ShadowClipper* clipper = nullptr;
      if (!candidates.empty()) {
        std::vector<OccluderPolygon>& occluders = scratch.occluders;
        occluders.clear();
        for (int k : candidates) {
          if (convex[static_cast<std::size_t>(k)])
            occluders.push_back({&shafts.outline(k), solidOf[static_cast<std::size_t>(k)],
                                 std::find(scratch.shading.begin(), scratch.shading.end(),
                                           solidOf[static_cast<std::size_t>(k)]) != scratch.shading.end()});
          else
            for (int e : patchElements[static_cast<std::size_t>(k)])
              occluders.push_back({&elementPolygons[static_cast<std::size_t>(e)], -1});
        }
        clipper = &clippers.local();
        clipper->prepare(source, ni, receiver, nj, occluders);
        if (clipper->occluders().empty()) clipper = nullptr;
      }
      if (clipper) {
        result.needsVisibility = true;
        ++scratch.counts.occludedPairs;
        // Wholly hidden by one face (the blocks' cross-sections were tried above): nothing to integrate.
        if (clipper->hidesAll(source.v.data(), source.count, clipper->occluders(), false)) {
          ++scratch.counts.hiddenPairs;
          return result;
        }
      }
      const double unoccludedTolerance = clipper ? 0.5 * tolerance : tolerance;
      double unoccluded = 0;
      if (near) {
        if (elementSolids[static_cast<std::size_t>(i)].empty()) {
          unoccluded = polygonToPolygonFormFactor(a.v.data(), a.count, b.v.data(), b.count);
        } else {
          for (const SmallPolygon& piece : pieces) {
            Vec3 twicePiece = Vec3::Zero();
            for (int k = 0; k < piece.count; ++k)
              twicePiece += piece.v[static_cast<std::size_t>(k)].cross(
                  piece.v[static_cast<std::size_t>((k + 1) % piece.count)]);
            unoccluded += polygonToPolygonFormFactor(piece.v.data(), piece.count, b.v.data(), b.count) * 0.5 *
                          twicePiece.norm() / areaI;
          }
        }
        ++work.contours;
      } else {
        for (int p = 0; p < panelCount; ++p)
          unoccluded += integrateUnoccluded(panels[static_cast<std::size_t>(p)], bound, receiver, ni,
                                            unoccludedTolerance, 0, work, topGap, topEdge);
        unoccluded /= areaI;
      }
      result.value = unoccluded;
      if (clipper && unoccluded > 0) {
        auto unoccludedOn = [&](const SourcePanel& panel, double pointTolerance) {
          return integrateUnoccluded(panel, bound, receiver, ni, pointTolerance, 0, work);
        };
        HiddenIntegral hidden(*clipper, hiddenOrder, unoccludedOn, areaI, work);
        // One occluder: the source cut into cells along its visibility events, where the hidden part is
        // analytic. Otherwise (or where the cells would be too many) the adaptive rules with their guards.
        bool byCells = clipper->eventPlanes(source, clipper->occluders(), scratch.events);
        std::vector<SmallPolygon>& cells = scratch.cells;
        cells.clear();
        const double eps = shadowEps(source, receiver);
        for (int p = 0; p < panelCount && byCells; ++p)
          byCells = cutAlongEvents(panels[static_cast<std::size_t>(p)], scratch.events, eps,
                                   kMaxEventCells - static_cast<int>(cells.size()), cells);
        double sum;
        if (byCells) {
          std::vector<SourcePanel>& cellPanels = scratch.cellPanels;
          cellPanels.clear();
          for (const SmallPolygon& cell : cells) {
            std::array<SourcePanel, SmallPolygon::kCapacity> fan;
            const int made = panelsOf(cell.v.data(), cell.count, fan.data(), SmallPolygon::kCapacity);
            cellPanels.insert(cellPanels.end(), fan.begin(), fan.begin() + made);
          }
          sum = hidden.overCells(cellPanels.data(), static_cast<int>(cellPanels.size()),
                                 0.5 * tolerance * areaI);
          ++scratch.counts.eventPairs;
        } else {
          sum = hidden(panels.data(), panelCount, 0.5 * tolerance * areaI);
        }
        result.value = std::max(0.0, unoccluded - sum / areaI);
      }
      Counts& counts = scratch.counts;
      counts.points += work.points;
      counts.clipped += work.clipped;
      counts.contours += work.contours;
      if (work.budgetReached) ++counts.budgetPairs;
      result.kernelEvaluations = static_cast<std::size_t>(work.points);
      result.contourIntegrals = static_cast<std::size_t>(work.contours);
      return result;
    };

    FormFactorMatrix F = computeReciprocalMatrix(mesh, options, progress, stats, "form factors (quadrature)",
                                                 [&](int i, int j) {
                                                   rowElement = i;
                                                   return fromSmallerElement(mesh, i, j, integrate);
                                                 });
    Counts total;
    for (const PairScratch& scratch : scratches) {
      total.points += scratch.counts.points;
      total.clipped += scratch.counts.clipped;
      total.contours += scratch.counts.contours;
      total.budgetPairs += scratch.counts.budgetPairs;
      total.occludedPairs += scratch.counts.occludedPairs;
      total.hiddenPairs += scratch.counts.hiddenPairs;
      total.eventPairs += scratch.counts.eventPairs;
    }
    char line[256];
    std::snprintf(
        line, sizeof line,
        "absolute tolerance %.3g: %ld point evaluations (%ld with the receiver clipped), %ld exact contour "
        "integrals, %ld pairs with "
        "occluders clipped per point (%ld of them wholly hidden)",
        tolerance, total.points, total.clipped, total.contours, total.occludedPairs, total.hiddenPairs);
    stats.notes = line;
    stats.notes += ", " + std::to_string(solids.size()) + " closed convex solids, " +
                   std::to_string(total.eventPairs) +
                   " pairs integrated over cells cut along visibility events";
    if (total.budgetPairs > 0)
      stats.notes += ", " + std::to_string(total.budgetPairs) + " pairs reached the work bound (depth " +
                     std::to_string(HiddenIntegral::kMaxDepth) + ", " +
                     std::to_string(HiddenIntegral::kMaxPoints) + " points) before the tolerance";
    return F;
  }
};

}  // namespace

std::unique_ptr<FormFactorMethod> makeQuadratureMethod() {
  return std::make_unique<QuadratureMethod>();
}

}  // namespace rt
