#include "core/formfactor/quadrature/hidden_integral.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/formfactor/quadrature/near_edges.h"
#include "core/portable_heap.h"

namespace rt {
namespace {

// Panels probed for grazing shadows (ShadowClipper::probeShadow): the top ones and their children. Once a
// probe has started the refinement, the rules' comparison carries it on. Measured on the 612-wall grid
// room at 1e-5: largest floor-row error against the exact method 1.19e-5 unprobed, 8.0e-6 at depth 0,
// 5.9e-6 at depth 1 and at every depth, which costs 1.25 x the work of depth 1.
constexpr int kMaxProbedDepth = 1;
// A top panel's hidden part up to this many times the tolerance is trusted on one comparison of rules: a
// chance agreement of about 1 % of it then costs at most a tenth of the tolerance (HiddenIntegral::push).
constexpr double kTrustedShare = 10;

}  // namespace

double HiddenIntegral::operator()(const SourcePanel* panels, int count, double tolerance) {
  tolerance_ = tolerance;
  thread_local NearEdges near;
  thread_local std::vector<SourcePanel> strips;
  double reach = 0;
  for (int p = 0; p < count; ++p) reach = std::max(reach, 2 * panels[p].radius());
  near.find(clipper_, clipper_.occluders(), reach, tolerance);
  near_ = &near;
  std::vector<Item> heap;
  double done = 0;  // panels that no occluder can touch or that are wholly hidden, or at the depth bound
  for (int p = 0; p < count; ++p) done += enter(panels[p], clipper_.occluders(), 0, heap, -1);
  done += refine(heap, tolerance, [&](Item& worst, std::vector<Item>& into) {
    double finished = 0;    // children that no occluder touches or that are wholly hidden
    if (worst.near >= 0) {  // strips along the near edge instead of the four children
      strips.clear();
      near.strips(worst.panel, worst.near, strips);
      for (const SourcePanel& part : strips)
        finished += enter(part, worst.occluders, worst.depth + 1, into, worst.near);
      return finished;
    }
    for (std::size_t c = 0; c < 4; ++c) {
      Child& child = worst.children[c];
      if (child.state != Child::Mixed) {
        finished += child.value;
        continue;
      }
      Item next{child.panel, std::move(child.occluders), 0, 0, worst.depth + 1};
      push(into, std::move(next), child.value, child.allHidden);
    }
    return finished;
  });
  near_ = nullptr;
  return done;
}

double HiddenIntegral::enter(const SourcePanel& panel, const std::vector<int>& from, int depth,
                             std::vector<Item>& heap, int cutAlong) {
  Item top{panel, {}, 0, 0, depth};
  clipper_.cull(panel, from, top.occluders);
  if (top.occluders.empty()) return 0;
  bool allHidden = true;
  const double estimate = evaluate(top.panel, top.occluders, allHidden);
  // Only a panel whose every point saw nothing of the receiver can be wholly hidden.
  if (allHidden && clipper_.hidesAll(panel.v.data(), panel.count, top.occluders))
    return unoccluded_(panel, pointTolerance());
  push(heap, std::move(top), estimate, allHidden, cutAlong);
  return 0;
}

template <class T, class Split>
double HiddenIntegral::refine(std::vector<T>& heap, double tolerance, Split&& split) {
  auto byError = [](const T& a, const T& b) { return a.error < b.error; };
  // The same cells in the same order with every standard library (portable_heap.h).
  portable_heap::make(heap, byError);
  double error = 0, done = 0;
  for (const T& item : heap) error += item.error;
  while (!heap.empty() && error > tolerance) {
    if (work_.points >= kMaxPoints) {
      work_.budgetReached = true;
      break;
    }
    portable_heap::pop(heap, byError);
    T worst = std::move(heap.back());
    heap.pop_back();
    error -= worst.error;
    if (worst.depth + 1 >= kMaxDepth) {
      done += worst.value;
      work_.budgetReached = true;
      continue;
    }
    const std::size_t before = heap.size();
    done += split(worst, heap);
    for (std::size_t k = before; k < heap.size(); ++k) {
      error += heap[k].error;
      portable_heap::push(heap, k + 1, byError);
    }
  }
  for (const T& item : heap) done += item.value;
  return done;
}

double HiddenIntegral::overCells(const SourcePanel* cells, int count, double tolerance,
                                 const std::vector<int>& occluders) {
  tolerance_ = tolerance;
  // The cells waiting to be split: kept from call to call on this thread (a vector made per pair cost as much
  // as a cell's rule). overCells() does not nest.
  thread_local std::vector<Smooth> heap;
  heap.clear();
  // Occluder edges low over the source's plane, and a split cell's strips along one: kept like the heap.
  thread_local NearEdges near;
  thread_local std::vector<SourcePanel> strips;
  double reach = 0;
  for (int c = 0; c < count; ++c) reach = std::max(reach, 2 * cells[c].radius());
  near.find(clipper_, occluders, reach, tolerance);
  double done = 0;
  std::size_t formCount = 0;
  // Two whole solids: each one's faces, for its own form at a cell's centre.
  const bool twoSolids = clipper_.ofSeveralSolids(occluders);
  std::array<std::vector<int>, 2> own;
  if (twoSolids)
    for (int k : occluders)
      own[clipper_.solidOf(k) == clipper_.solidOf(occluders.front()) ? 0 : 1].push_back(k);
  for (int c = 0; c < count; ++c) {
    // Not culled: the centre tells as well whether anything is hidden there, for about the cost of the test.
    // Its form, where there is one, tells it without Lambert's sum, and places the cell's other points.
    Smooth cell{cells[c], 0, 0, 0};
    bool wholly = false;
    double centre = 0;
    const Vec3 x = cells[c].centre();
    if (forms_.size() < formCount + 2) forms_.resize(formCount + 2);
    const int alone = twoSolids ? oneSolidAlone(x, own, formCount, wholly, centre) : -1;
    ShadowClipper::HiddenForm& form = forms_[formCount];
    if (twoSolids && alone == kNoneHides) {
      ++work_.points;
      continue;
    } else if (twoSolids && (wholly || alone >= 0)) {
      if (alone >= 0) cell.form = static_cast<int>(formCount++);
    } else if (!twoSolids && clipper_.formOf(x, occluders, form, &centre)) {
      wholly = form.wholly;
      if (!wholly && form.count >= 3) cell.form = static_cast<int>(formCount++);
    } else {
      centre = clipper_.hidden(x, occluders, &wholly);
      // Both solids' shadows on the receiver: between them a gap can open inside a cell
      // (visibility_events.h), so a cell they hide all of it from at the centre is taken as wholly hidden
      // only where one of them is proven to hide it from the whole cell; otherwise it is rated like any
      // other.
      if (wholly && twoSolids && !clipper_.hidesAll(cells[c].v.data(), cells[c].count, occluders))
        wholly = false;
    }
    ++work_.points;
    ++work_.clipped;
    if (wholly) {
      done += unoccluded_(cells[c], pointTolerance());
      continue;
    }
    if (centre <= 0) continue;
    cell.value = centre * cells[c].area();
    rate(cell, occluders);
    if (!near.empty()) probeNear(cell, near, occluders);
    heap.push_back(std::move(cell));
  }
  return done + refine(heap, tolerance, [&](Smooth& worst, std::vector<Smooth>& into) {
           // Too wide for a near edge: strips along it, each rated on its own (the parent's rules missed
           // what lies beside the edge, so their difference says nothing of the strips').
           if (worst.near >= 0) {
             strips.clear();
             near.strips(worst.panel, worst.near, strips);
             for (const SourcePanel& part : strips) {
               Smooth child{part, 0, 0, worst.depth + 1, worst.form};
               child.value = hiddenIn(part.centre(), child.form, occluders) * part.area();
               ++work_.points;
               ++work_.clipped;
               rate(child, occluders);
               probeNear(child, near, occluders, worst.near);
               into.push_back(std::move(child));
             }
             return 0.0;
           }
           // The children's 2 x 2 rules against the parent's: for an analytic integrand that difference is
           // about the parent's error, and the children's together about a sixteenth of it. It replaces their
           // own one-point estimates (which fall only four times per split), shared out in their proportions.
           std::array<Smooth, 4> children;
           const std::array<SourcePanel, 4> parts = splitPanel(worst.panel);
           double sum = 0, own = 0;
           for (std::size_t c = 0; c < 4; ++c) {
             Smooth& child = children[c];
             child = {parts[c], 0, 0, worst.depth + 1, worst.form};
             child.value = hiddenIn(parts[c].centre(), child.form, occluders) * parts[c].area();
             ++work_.points;
             ++work_.clipped;
             rate(child, occluders);
             sum += child.value;
             own += child.error;
           }
           const double difference = std::abs(sum - worst.value);
           for (Smooth& child : children) {
             child.error =
                 own > 0 ? std::min(child.error, difference * child.error / own) : 0.25 * difference;
             into.push_back(std::move(child));
           }
           return 0.0;
         });
}

int HiddenIntegral::oneSolidAlone(const Vec3& x, const std::array<std::vector<int>, 2>& own, std::size_t slot,
                                  bool& wholly, double& hidden) {
  std::array<bool, 2> none{};
  std::array<double, 2> value{};
  for (std::size_t s = 0; s < 2; ++s) {
    ShadowClipper::HiddenForm& form = forms_[slot + s];
    if (!clipper_.formOf(x, own[s], form, &value[s])) return kBothHide;
    if (form.wholly) {
      wholly = true;
      return kBothHide;
    }
    none[s] = form.count < 3;
  }
  if (none[0] && none[1]) return kNoneHides;
  if (none[0] == none[1]) return kBothHide;
  if (none[0]) std::swap(forms_[slot], forms_[slot + 1]);
  hidden = value[none[0] ? 1 : 0];
  return none[0] ? 1 : 0;
}

void HiddenIntegral::rate(Smooth& cell, const std::vector<int>& occluders) {
  double fine = 0;
  std::array<Vec3, 4> x;
  std::array<double, 4> weight, value;
  int n = 0;
  forEachGaussPoint(cell.panel, 2, [&](const Vec3& point, double w) {
    x[static_cast<std::size_t>(n)] = point;
    weight[static_cast<std::size_t>(n++)] = w;
  });
  if (cell.form >= 0 &&
      clipper_.hidden4(x.data(), forms_[static_cast<std::size_t>(cell.form)], value.data())) {
    work_.placed += 4;
  } else {
    for (std::size_t p = 0; p < 4; ++p) value[p] = hiddenIn(x[p], cell.form, occluders);
  }
  for (std::size_t p = 0; p < 4; ++p) fine += weight[p] * value[p];
  work_.points += 4;
  work_.clipped += 4;
  cell.error = std::abs(fine - cell.value);
  cell.value = fine;
}

void HiddenIntegral::probeNear(Smooth& cell, const NearEdges& near, const std::vector<int>& occluders,
                               int cutAlong) {
  cell.near = near.tooWide(cell.panel, cutAlong);
  if (cell.near < 0) return;
  const double probe = hiddenIn(near.nearestPoint(cell.panel, cell.near), cell.form, occluders);
  ++work_.points;
  ++work_.clipped;
  cell.error = std::max(cell.error, std::abs(probe * cell.panel.area() - cell.value));
}

double HiddenIntegral::hiddenIn(const Vec3& x, int form, const std::vector<int>& occluders) {
  double value = 0;
  if (form >= 0 && clipper_.hidden(x, forms_[static_cast<std::size_t>(form)], value)) {
    ++work_.placed;
    return value;
  }
  return clipper_.hidden(x, occluders);
}

double HiddenIntegral::evaluate(const SourcePanel& panel, const std::vector<int>& occluders,
                                bool& allHidden) {
  PanelPoints points;
  gaussPoints(panel, order_, points);
  double sum = 0;
  int p = 0;
  for (; p + 4 <= points.count; p += 4) {  // four points' pieces summed at once
    std::array<double, 4> value;
    std::array<bool, 4> hiddenHere;
    clipper_.hidden4(&points.x[static_cast<std::size_t>(p)], occluders, value.data(), hiddenHere.data());
    for (std::size_t k = 0; k < 4; ++k) {
      sum += points.weight[static_cast<std::size_t>(p) + k] * value[k];
      allHidden &= hiddenHere[k];
    }
  }
  for (; p < points.count; ++p) {
    bool hiddenHere = false;
    sum += points.weight[static_cast<std::size_t>(p)] *
           clipper_.hidden(points.x[static_cast<std::size_t>(p)], occluders, &hiddenHere);
    allHidden &= hiddenHere;
  }
  work_.points += points.count;
  work_.clipped += points.count;
  return sum;
}

void HiddenIntegral::push(std::vector<Item>& heap, Item item, double estimate, bool estimateAllHidden,
                          int cutAlong) {
  const std::array<SourcePanel, 4> split = splitPanel(item.panel);
  item.value = 0;
  bool mixed = false, allHidden = estimateAllHidden;
  for (std::size_t c = 0; c < 4; ++c) {
    Child& child = item.children[c];
    child.panel = split[c];
    clipper_.cull(split[c], item.occluders, child.occluders);
    if (child.occluders.empty()) {
      child.state = Child::Visible;
      child.value = 0;
    } else {
      child.allHidden = true;
      child.value = evaluate(split[c], child.occluders, child.allHidden);
      if (child.allHidden && clipper_.hidesAll(split[c].v.data(), split[c].count, child.occluders)) {
        child.state = Child::Hidden;
        child.value = unoccluded_(split[c], pointTolerance());
      } else {
        child.state = Child::Mixed;
        allHidden &= child.allHidden;
        mixed = true;
      }
    }
    item.value += child.value;
  }
  item.error = std::abs(item.value - estimate);
  // A 2 x 2 rule and its children's can agree by chance where a shadow's edge or a visibility event crosses
  // the panel: there the integrand has a kink, each rule errs by an amount that depends on where the kink
  // falls between its points, and the two errors can be equal. The error that goes unseen is then about 1 %
  // of the panel's hidden part at the size of a top panel, and it falls like the panel's size (a rule's
  // error along a kink is O(h^3) against a hidden part O(h^2)): halved at each split. A panel whose hidden
  // part could hide more than a tenth of the tolerance that way is therefore never trusted on one
  // comparison, at any depth: it is split, and its children compared in turn (their own chance agreements
  // are independent of the parent's). The threshold doubles per level while the hidden part of a child is
  // about a quarter of its parent's, so this ends after a few levels. (A 3 x 3 rule against the children's
  // is fooled the same way: a higher order does not replace the forced split.)
  double trusted = kTrustedShare * tolerance_;
  for (int d = 0; d < item.depth; ++d) trusted *= 2;
  const bool forced = mixed && item.value > trusted;
  if (forced) item.error = std::max(item.error, item.value);
  // No Gauss point saw a shadow, but one may fall on the panel's rim only (the shadow of a block's corner
  // reaching the last few percent of a wall element): the corners are looked at too, and a shadow seen
  // there counts as an error of its size.
  if (mixed && item.value == 0 && estimate == 0) {
    double corners = 0;
    for (int k = 0; k < item.panel.count; ++k)
      corners += clipper_.hidden(item.panel.v[static_cast<std::size_t>(k)], item.occluders);
    work_.points += item.panel.count;
    work_.clipped += item.panel.count;
    item.error = std::max(item.error, corners / item.panel.count * item.panel.area());
  }
  // A shadow that grazes the receiver from a sliver of the panel only (a block's top corner cutting a
  // floor-to-ceiling pair) is seen by few sample points or none, by the panel's rule and its children's
  // alike. Probed where the occluders and the receiver line up: a probe that sees more than twice what
  // the samples give the panel on average means the samples missed it.
  // (A panel split anyway needs no probe where its children are probed.)
  if (mixed && item.depth <= kMaxProbedDepth && !(forced && item.depth < kMaxProbedDepth)) {
    long probes = 0;
    const double probed = clipper_.probeShadow(item.panel, item.occluders, probes);
    work_.points += probes;
    work_.clipped += probes;
    item.error = std::max(item.error, 0.5 * probed * item.panel.area() - item.value);
  }
  // The converse: every point saw the receiver wholly hidden, but a corner may look past the occluder's
  // edge (a sliver of a wall seen past a block's corner from the end of a wall element only).
  if (mixed && allHidden) {
    double corners = 0;
    for (int k = 0; k < item.panel.count; ++k) {
      const Vec3& corner = item.panel.v[static_cast<std::size_t>(k)];
      corners += std::max(0.0, clipper_.unoccluded(corner) - clipper_.hidden(corner, item.occluders));
    }
    work_.points += 2 * item.panel.count;
    work_.clipped += item.panel.count;
    item.error = std::max(item.error, corners / item.panel.count * item.panel.area());
  }
  // Wider than its distance from a near edge: a probe beside the edge, as overCells() has it.
  if (mixed && near_ && !near_->empty()) {
    item.near = near_->tooWide(item.panel, cutAlong);
    if (item.near >= 0) {
      const double probe = clipper_.hidden(near_->nearestPoint(item.panel, item.near), item.occluders);
      ++work_.points;
      ++work_.clipped;
      item.error = std::max(item.error, std::abs(probe * item.panel.area() - item.value));
    }
  }
  heap.push_back(std::move(item));
}

}  // namespace rt
