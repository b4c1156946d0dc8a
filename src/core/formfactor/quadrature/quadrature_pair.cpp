#include "core/formfactor/quadrature/quadrature_pair.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/formfactor/quadrature/closed_solids.h"
#include "core/formfactor/quadrature/hidden_integral.h"
#include "core/formfactor/quadrature/unoccluded_integral.h"
#include "core/geometry/plane_clip.h"

namespace rt {
namespace {

constexpr double kNearSizes = 1.0;  // closer than this many source sizes: exact contour integral
constexpr int kMaxEventCells = 64;  // more, and the adaptive rules cost less than the cells
constexpr int kHiddenOrder = 2;     // low: the hidden part has kinks and jumps where it is not cut into cells

}  // namespace

QuadraturePair::QuadraturePair(const QuadratureScene& scene, double tolerance)
    : scene_(scene),
      tolerance_(tolerance),
      clipper_(scene.solids, &scene.solidCentres, &scene.shapes),
      rowRegions_(scene.shapes, scene.regionEps) {}

bool QuadraturePair::judgeBlocks(int i, int j, int row, const ConvexPolygon& a, const ConvexPolygon& b,
                                 const ConvexPolygon& source, const ConvexPolygon& receiver,
                                 const Vec3& sourceCentre, const Vec3& receiverCentre) {
  const bool rowIsSource = row == i;
  const ConvexPolygon &rowPolygon = rowIsSource ? a : b, &otherFull = rowIsSource ? b : a;
  const ConvexPolygon& other = rowIsSource ? receiver : source;
  const int otherElement = rowIsSource ? j : i;
  const Vec3& otherNormal = scene_.mesh.elements[static_cast<std::size_t>(otherElement)].normal;
  int last = -1;
  BlockVerdict verdict = BlockVerdict::Unknown;
  for (int& k : candidates_) {
    const int solid = scene_.solidOf[static_cast<std::size_t>(k)];
    if (solid < 0) continue;
    if (solid != last) {
      verdict = scene_.contactRegions->judge(solid, row, rowPolygon.v.data(), rowPolygon.count, otherElement);
      if (verdict == BlockVerdict::Unknown)
        verdict = scene_.contactRegions->judge(solid, otherElement, otherFull.v.data(), otherFull.count, row);
      if (verdict == BlockVerdict::Unknown)
        verdict = rowRegions_.judge(row, rowPolygon.v.data(), rowPolygon.count, solid, other.v.data(),
                                    other.count, other.v[0], otherNormal);
      // No region from either side (the block reaches as high as one of them over the other's plane): one
      // of its faces with both elements in front of it still proves it misses.
      if (verdict == BlockVerdict::Unknown &&
          !segmentEntersSolid(sourceCentre, receiverCentre, scene_.solids[static_cast<std::size_t>(solid)],
                              scene_.regionEps)) {
        const SolidShape& shape = scene_.shapes[static_cast<std::size_t>(solid)];
        if (solidMissesEverySegment(source.v.data(), source.count, receiver.v.data(), receiver.count,
                                    scene_.solids[static_cast<std::size_t>(solid)], scene_.regionEps) ||
            solidOutsideHullOf(source.v.data(), source.count, receiver.v.data(), receiver.count,
                               shape.corners.data(), static_cast<int>(shape.corners.size()),
                               scene_.regionEps))
          verdict = BlockVerdict::Misses;
      }
      if (verdict == BlockVerdict::HidesAll) return true;
      if (verdict == BlockVerdict::Shades) shading_.push_back(solid);
    }
    last = solid;
    if (verdict == BlockVerdict::Misses) k = -1;
  }
  std::erase(candidates_, -1);
  return false;
}

bool QuadraturePair::hiddenSolidBySolid(int i, int j, const ConvexPolygon& source, double eps,
                                        HiddenIntegral& hidden, double tolerance, double& sum) {
  solidsHere_.clear();
  for (int k : clipper_.occluders()) {
    const int solid = clipper_.solidOf(k);
    if (solid < 0) return false;
    if (std::find(solidsHere_.begin(), solidsHere_.end(), solid) == solidsHere_.end())
      solidsHere_.push_back(solid);
  }
  if (solidsHere_.size() < 2) return false;
  for (std::size_t a = 0; a < solidsHere_.size(); ++a)
    for (std::size_t b = a + 1; b < solidsHere_.size(); ++b)
      if (!scene_.shadowsApart(i, j, solidsHere_[a], solidsHere_[b])) return false;
  // Each solid's share of the tolerance; its cells cut along its own events only.
  const double share = tolerance / static_cast<double>(solidsHere_.size());
  double total = 0;
  for (int solid : solidsHere_) {
    solidOccluders_.clear();
    for (int k : clipper_.occluders())
      if (clipper_.solidOf(k) == solid) solidOccluders_.push_back(k);
    if (!clipper_.eventPlanes(source, solidOccluders_, events_)) return false;
    cells_.clear();
    for (const SourcePanel& panel : panels_)
      if (!cutAlongEvents(panel, events_, eps, kMaxEventCells - static_cast<int>(cells_.size()), cells_))
        return false;
    appendPanels(cells_, cellPanels_);
    total +=
        hidden.overCells(cellPanels_.data(), static_cast<int>(cellPanels_.size()), share, solidOccluders_);
  }
  sum = total;
  return true;
}

double QuadraturePair::gapOf(int i, const ConvexPolygon& source, const ReceiverBound& receiver) const {
  const ReceiverBound& own = scene_.measures[static_cast<std::size_t>(i)].bound;
  double height = INFINITY;
  for (int k = 0; k < source.count; ++k)
    height = std::min(height,
                      std::abs(receiver.normal.dot(source.v[static_cast<std::size_t>(k)] - receiver.point)));
  return std::max((own.centre - receiver.centre).norm() - own.radius - receiver.radius, height);
}

const char* routeName(QuadratureRoute route) {
  static constexpr std::array<const char*, kQuadratureRoutes> names{
      "enclosed",   "behind",         "far-unoccluded", "block-verdict", "block-sections",
      "unoccluded", "face-hides-all", "solid-by-solid", "cells",         "adaptive"};
  return names[static_cast<std::size_t>(route)];
}

const char* routeMeaning(QuadratureRoute route) {
  static constexpr std::array<const char*, kQuadratureRoutes> meanings{
      "one element lies inside a closed block: F = 0",
      "one element lies wholly behind the other's plane: F = 0",
      "nothing between them and far apart: F = U on one panel, its Gauss order read off a bound",
      "a block's shadow regions prove that it hides all of the pair: F = 0",
      "a block's cross-section cuts every segment from one to the other: F = 0",
      "no occluder is left after clipping: F = U",
      "the clipped occluders hide the receiver from every point of the source: F = 0",
      "F = U - H, H block by block over each block's own cells (their shadows never overlap)",
      "F = U - H, H over cells of the source cut along the visibility events",
      "F = U - H, H by the globally adaptive rules with their guards"};
  return meanings[static_cast<std::size_t>(route)];
}

PairResult QuadraturePair::operator()(int i, int j, int row) {
  PairResult result;
  const QuadratureRoute route = integrate(i, j, row, result);
  ++counts_.routes[static_cast<std::size_t>(route)];
  if (trace_) trace_->route = route;
  return result;
}

QuadratureRoute QuadraturePair::integrate(int i, int j, int row, PairResult& result) {
  const Mesh& mesh = scene_.mesh;
  PairWork work;
  if (trace_) *trace_ = PairTrace{};
  if (scene_.enclosed[static_cast<std::size_t>(i)] || scene_.enclosed[static_cast<std::size_t>(j)]) {
    result.needsVisibility = true;
    ++counts_.occludedPairs;
    ++counts_.hiddenPairs;
    return QuadratureRoute::Enclosed;
  }
  const ConvexPolygon a = elementPolygon(mesh, i), b = elementPolygon(mesh, j);
  const Vec3 &ni = mesh.elements[static_cast<std::size_t>(i)].normal,
             &nj = mesh.elements[static_cast<std::size_t>(j)].normal;
  const double areaI = mesh.elements[static_cast<std::size_t>(i)].area;
  const double scale = (mesh.elements[static_cast<std::size_t>(i)].centroid -
                        mesh.elements[static_cast<std::size_t>(j)].centroid)
                           .norm();
  ConvexPolygon source, receiver;
  const bool receiverWhole = clipToFront(b.v.data(), b.count, a.v[0], ni, 1e-12 * scale, receiver);
  const bool sourceWhole = clipToFront(a.v.data(), a.count, b.v[0], nj, 1e-12 * scale, source);
  if (source.count < 3 || receiver.count < 3) return QuadratureRoute::Behind;
  candidates_.clear();
  shading_.clear();
  scene_.shafts.candidates(i, j, candidates_);
  if (trace_) trace_->shaft = candidates_;
  // The centres' segment rules the blocks' proofs in or out (judgeBlocks and the cross-sections below); only
  // pairs with candidates need it.
  Vec3 sourceCentre = Vec3::Zero(), receiverCentre = Vec3::Zero();
  if (!candidates_.empty()) {
    sourceCentre = source.centre();
    receiverCentre = receiver.centre();
  }
  // Nothing between them, both whole, a triangle or quadrilateral for source and not near: the source is one
  // panel, integrated as the general path below would (one point on each side for most such pairs), before
  // any of its machinery is set up.
  const QuadratureScene::Measure &mi = scene_.measures[static_cast<std::size_t>(i)],
                                 &mj = scene_.measures[static_cast<std::size_t>(j)];
  if (candidates_.empty() && sourceWhole && receiverWhole && mi.corners > 0 &&
      scene_.elementSolids[static_cast<std::size_t>(i)].empty()) {
    const double gap = gapOf(i, source, mj.bound);
    if (!(gap < kNearSizes * mi.longest)) {
      SourcePanel panel;
      panel.assign(source);
      const OnePoint far = onePointOf(mj), own = onePointOf(mi);
      result.value = integrateUnoccluded(panel, mj.bound, receiver, ni, tolerance_, 0, work, gap, mi.longest,
                                         &far, &own) /
                     areaI;
      counts_.points += work.points;
      result.kernelEvaluations = static_cast<std::size_t>(work.points);
      if (trace_) trace_->sourcePieces = trace_->panels = 1, trace_->unoccluded = result.value;
      if (trace_) trace_->points = work.points;  // no contour integral, no work bound on this route
      return QuadratureRoute::FarUnoccluded;
    }
  }
  const std::vector<SolidPlanes>& solids = scene_.solids;
  auto whollyHidden = [&](QuadratureRoute route) {
    result.needsVisibility = true;
    ++counts_.occludedPairs;
    ++counts_.hiddenPairs;
    return route;
  };
  if (!candidates_.empty() && !solids.empty() && (row == i || row == j) &&
      judgeBlocks(i, j, row, a, b, source, receiver, sourceCentre, receiverCentre))
    return whollyHidden(QuadratureRoute::BlockVerdict);
  if (trace_) trace_->afterBlocks = candidates_;
  // A block between them that cuts every segment from one to the other, proven from its cross-sections
  // alone, before anything else is prepared.
  if (!candidates_.empty() && !solids.empty()) {
    const double eps = shadowEps(source, receiver);
    int last = -1;
    for (int k : candidates_) {
      const int solid = scene_.solidOf[static_cast<std::size_t>(k)];
      if (solid < 0 || solid == last) continue;
      last = solid;
      // Its regions said it does not hide all (judgeBlocks(): Shades): no proof to look for.
      if (shades(solid)) continue;
      // The centres' segment passing clear of the block (not even within eps of it): one segment it does not
      // cut, so no proof that it cuts them all.
      if (!segmentEntersSolid(sourceCentre, receiverCentre, solids[static_cast<std::size_t>(solid)], -eps))
        continue;
      if (solidCutsEverySegment(source.v.data(), source.count, receiver.v.data(), receiver.count,
                                solids[static_cast<std::size_t>(solid)],
                                scene_.solidCentres[static_cast<std::size_t>(solid)], eps))
        return whollyHidden(QuadratureRoute::BlockSections);
    }
  }
  const ReceiverBound bound =
      receiverWhole ? scene_.measures[static_cast<std::size_t>(j)].bound : boundOf(receiver, nj);
  const std::vector<int>& reached = scene_.elementSolids[static_cast<std::size_t>(i)];
  if (reached.empty()) {
    panels_.clear();
    appendPanels(source, panels_);
  } else {
    pieces_.assign(1, source);
    for (int s : reached) {
      next_.clear();
      for (const ConvexPolygon& piece : pieces_)
        piecesOutside(piece, solids[static_cast<std::size_t>(s)], 1e-12 * scale, next_);
      pieces_.swap(next_);
    }
    appendPanels(pieces_, panels_);
  }
  const int panelCount = static_cast<int>(panels_.size());
  bool near = false;
  // The source whole (nothing cut off by the receiver's plane or a block it reaches under) and one panel: its
  // gap from what is known of the element.
  double topGap = -1, topEdge = -1;
  if (sourceWhole && panelCount == 1 && reached.empty()) {
    topGap = gapOf(i, source, bound);
    topEdge = scene_.measures[static_cast<std::size_t>(i)].longest;
    near = topGap < kNearSizes * topEdge;
  }
  for (int p = 0; p < panelCount && !near && topGap < 0; ++p)
    near = panelGap(panels_[static_cast<std::size_t>(p)], bound) <
           kNearSizes * panels_[static_cast<std::size_t>(p)].longestEdge();
  bool occluded = false;
  if (!candidates_.empty()) {
    occluders_.clear();
    for (int k : candidates_) {
      const int solid = scene_.solidOf[static_cast<std::size_t>(k)];
      if (scene_.convex[static_cast<std::size_t>(k)])
        occluders_.push_back({&scene_.shafts.outline(k), solid, shades(solid)});
      else
        for (int e : scene_.patchElements[static_cast<std::size_t>(k)])
          occluders_.push_back({&scene_.elementPolygons[static_cast<std::size_t>(e)], -1});
    }
    clipper_.prepare(source, ni, receiver, nj, occluders_);
    occluded = !clipper_.occluders().empty();
  }
  if (trace_) {
    trace_->clippedOccluders = occluded ? static_cast<int>(clipper_.occluders().size()) : 0;
    trace_->sourcePieces = reached.empty() ? 1 : static_cast<int>(pieces_.size());
    trace_->panels = panelCount;
    trace_->near = near;
  }
  if (occluded) {
    result.needsVisibility = true;
    ++counts_.occludedPairs;
    // Wholly hidden by one face (the blocks' cross-sections were tried above): nothing to integrate. Not
    // tried where every occluder is a face of a block whose shadow regions said it does not hide all of the
    // pair (judgeBlocks(): Shades); where that is wrong by a margin, the cells find the hidden part whole.
    const bool shadingOnly =
        std::all_of(clipper_.occluders().begin(), clipper_.occluders().end(), [&](int k) {
          const int solid = clipper_.solidOf(k);
          return solid >= 0 && shades(solid);
        });
    if (!shadingOnly && clipper_.hidesAll(source.v.data(), source.count, clipper_.occluders(), false)) {
      ++counts_.hiddenPairs;
      return QuadratureRoute::FaceHidesAll;
    }
  }
  const double unoccludedTolerance = occluded ? 0.5 * tolerance_ : tolerance_;
  double unoccluded = 0;
  if (near) {
    if (reached.empty()) {
      unoccluded = polygonToPolygonFormFactor(a.v.data(), a.count, b.v.data(), b.count);
    } else {
      for (const ConvexPolygon& piece : pieces_) {
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
    // The elements' own one-point rules where they are whole.
    const OnePoint far = receiverWhole ? onePointOf(mj) : OnePoint{};
    const OnePoint own = topGap >= 0 ? onePointOf(mi) : OnePoint{};
    for (int p = 0; p < panelCount; ++p)
      unoccluded +=
          integrateUnoccluded(panels_[static_cast<std::size_t>(p)], bound, receiver, ni, unoccludedTolerance,
                              0, work, topGap, topEdge, &far, own.corners > 0 ? &own : nullptr);
    unoccluded /= areaI;
  }
  result.value = unoccluded;
  QuadratureRoute route = QuadratureRoute::Unoccluded;
  if (occluded && unoccluded > 0) {
    auto unoccludedOn = [&](const SourcePanel& panel, double pointTolerance) {
      return integrateUnoccluded(panel, bound, receiver, ni, pointTolerance, 0, work);
    };
    HiddenIntegral hidden(clipper_, kHiddenOrder, unoccludedOn, areaI, work, forms_);
    // Two solids whose shadows never overlap: each over its own cells. One solid or polygon, or two whole
    // solids: the source cut into cells along their visibility events, where the hidden part is analytic
    // (between two solids, up to a gap opening between their shadows, which overCells() guards against).
    // Otherwise (or where the cells would be too many) the adaptive rules with their guards.
    const double eps = shadowEps(source, receiver);
    double sum = 0;
    const bool apart = clipper_.ofSeveralSolids(clipper_.occluders()) &&
                       hiddenSolidBySolid(i, j, source, eps, hidden, 0.5 * tolerance_ * areaI, sum);
    bool byCells = !apart && clipper_.eventPlanes(source, clipper_.occluders(), events_);
    cells_.clear();
    for (int p = 0; p < panelCount && byCells; ++p)
      byCells = cutAlongEvents(panels_[static_cast<std::size_t>(p)], events_, eps,
                               kMaxEventCells - static_cast<int>(cells_.size()), cells_);
    if (apart) {
      ++counts_.eventPairs;
      ++counts_.apartPairs;
      route = QuadratureRoute::SolidBySolid;
    } else if (byCells) {
      appendPanels(cells_, cellPanels_);
      sum = hidden.overCells(cellPanels_.data(), static_cast<int>(cellPanels_.size()),
                             0.5 * tolerance_ * areaI, clipper_.occluders());
      ++counts_.eventPairs;
      route = QuadratureRoute::Cells;
      if (trace_) trace_->cells = static_cast<int>(cellPanels_.size());
    } else {
      sum = hidden(panels_.data(), panelCount, 0.5 * tolerance_ * areaI);
      route = QuadratureRoute::Adaptive;
    }
    result.value = std::max(0.0, unoccluded - sum / areaI);
    if (trace_) trace_->hidden = sum / areaI;
  }
  if (trace_) {
    trace_->unoccluded = unoccluded;
    trace_->points = work.points, trace_->contours = work.contours;
    trace_->budgetReached = work.budgetReached;
  }
  counts_.points += work.points;
  counts_.clipped += work.clipped;
  counts_.placed += work.placed;
  counts_.contours += work.contours;
  if (work.budgetReached) ++counts_.budgetPairs;
  result.kernelEvaluations = static_cast<std::size_t>(work.points);
  result.contourIntegrals = static_cast<std::size_t>(work.contours);
  return route;
}

}  // namespace rt
