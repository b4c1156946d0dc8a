// The hidden part of a pair's form factor: the integral over the source of F(dA_x -> the part of the receiver
// that occluders hide from x), clipped per point by ShadowClipper and integrated adaptively along the
// penumbrae (docs/formfactor-methods.md, "Quadrature").
#pragma once

#include <array>
#include <vector>

#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/source_panels.h"

namespace rt {

class NearEdges;  // near_edges.h

// Per pair, on one thread.
struct PairWork {
  long points = 0;    // Lambert evaluations
  long clipped = 0;   // of them, at points where the receiver was clipped by occluders
  long placed = 0;    // of those, placed from their cell's hidden form without clipping
  long contours = 0;  // exact contour integrals
  bool budgetReached = false;
};

// Globally adaptive: panels wait in a heap ordered by their error estimate (a panel's rule against the sum
// of its four children's), and the worst is split until the estimates add up to less than the tolerance or
// the work bound is reached. Local criteria (each panel its share of the tolerance) never end along a jump
// of the integrand: the floor next to a block sees half the room just outside its footprint and nothing
// under it, and a panel straddling that line errs in proportion to its own area however small it is. The
// total error along such a line falls like the panels' size, so the global criterion ends.
class HiddenIntegral {
 public:
  // `unoccluded(panel, tolerance)`: int over the panel of F(dA_x -> receiver), for panels from which the
  // whole receiver is hidden (there the hidden part is all of it).
  // A reference to the caller's callable, which outlives this object (a std::function of the caller's lambda
  // allocated on the heap for every occluded pair).
  class Unoccluded {
   public:
    template <class F>
    Unoccluded(const F& f)  // implicit: a lambda converts as it did to std::function
        : object_(&f), call_([](const void* o, const SourcePanel& p, double t) {
            return (*static_cast<const F*>(o))(p, t);
          }) {}
    double operator()(const SourcePanel& panel, double tolerance) const {
      return call_(object_, panel, tolerance);
    }

   private:
    const void* object_;
    double (*call_)(const void*, const SourcePanel&, double);
  };
  // `sourceArea` turns the tolerance of the integral into one of F(dA -> receiver) at each point.
  // `forms`: scratch for overCells(), kept by the caller from pair to pair.
  HiddenIntegral(const ShadowClipper& clipper, int order, Unoccluded unoccluded, double sourceArea,
                 PairWork& work, std::vector<ShadowClipper::HiddenForm>& forms)
      : clipper_(clipper),
        order_(order),
        unoccluded_(unoccluded),
        sourceArea_(sourceArea),
        work_(work),
        forms_(forms) {}

  // Work bounds per pair: panel depth and points.
  static constexpr int kMaxDepth = 10;
  static constexpr long kMaxPoints = 60000;

  // int over the panels of F(dA_x -> hidden part), to `tolerance` (absolute, in the same units).
  double operator()(const SourcePanel* panels, int count, double tolerance);

  // The same over the cells of the source cut along the visibility events (visibility_events.h). In each
  // the hidden part is analytic, and nothing, part or all of the receiver is hidden throughout: the centre
  // tells which. Only cells hiding part of it are integrated: the 2 x 2 rule, its difference from the
  // centre's one-point rule as the error estimate (which for an analytic integrand overstates the 2 x 2
  // rule's error by far), split where the estimates add up to more than the tolerance. A cell wider than its
  // distance from an occluder edge low over the source's plane is rated by a probe beside that edge too,
  // and split into strips along it (near_edges.h). None of the guards
  // against shadows the points miss is needed. Where the occluder is one convex solid, the hidden part's
  // form is found at each cell's centre and its other points are placed from it (ShadowClipper::formOf).
  // `occluders`: those the cells were cut for (one solid or polygon).
  double overCells(const SourcePanel* cells, int count, double tolerance, const std::vector<int>& occluders);

 private:
  struct Child {
    enum State { Visible, Hidden, Mixed };
    SourcePanel panel;
    std::vector<int> occluders;
    double value = 0;
    State state = Visible;
    bool allHidden = false;  // every point of its rule saw the receiver wholly hidden
  };
  struct Item {
    SourcePanel panel;
    std::vector<int> occluders;
    double value = 0;  // the sum over its children
    double error = 0;  // |children - own rule|
    int depth = 0;
    std::array<Child, 4> children;
    int near = -1;  // the near edge (NearEdges) it is too wide for, or -1
  };

  struct Smooth {  // a cell, or part of one, of overCells()
    SourcePanel panel;
    double value = 0, error = 0;
    int depth = 0;
    int form = -1;  // the cell's hidden form in forms_, or -1 (clipped at every point)
    int near = -1;  // the near edge (NearEdges) it is too wide for, or -1
  };
  // The global refinement both integrals share: the item with the largest error estimate is split
  // (`split(worst, heap)` appends its parts and returns the value of those finished outright) until the
  // estimates add up to less than `tolerance` or a work bound is reached. Returns the sum of every value.
  template <class T, class Split>
  double refine(std::vector<T>& heap, double tolerance, Split&& split);

  // For a cell between two whole solids (`own`: each one's faces), at its centre x: each solid's own form,
  // into forms_[slot] and forms_[slot + 1]. Cut along both solids' events, a cell keeps what each alone hides
  // (nothing, part or all of the receiver) throughout. Returns the solid that alone hides part of it while
  // the other hides nothing (its form then in forms_[slot], and what it hides from x in `hidden`),
  // kNoneHides, or kBothHide; `wholly` is set where one of them alone hides all of it (also kBothHide), and
  // kBothHide is returned as well where a form is not known (x on an event).
  static constexpr int kNoneHides = -2, kBothHide = -1;
  int oneSolidAlone(const Vec3& x, const std::array<std::vector<int>, 2>& own, std::size_t slot, bool& wholly,
                    double& hidden);
  // From `value` holding the one-point rule: the 2 x 2 rule's value and the difference as its error.
  void rate(Smooth& cell, const std::vector<int>& occluders);
  // After rate(): where the cell is too wide for a near edge, that edge, and the error raised to what a
  // probe beside the edge says is missed. `cutAlong`: the edge a strip was cut along (never too wide for it).
  void probeNear(Smooth& cell, const NearEdges& near, const std::vector<int>& occluders, int cutAlong = -1);
  // F(dA_x -> hidden part) at a point of a cell: from the cell's form where it has one that fits x.
  double hiddenIn(const Vec3& x, int form, const std::vector<int>& occluders);

  // Clears `allHidden` when some point of the rule sees part of the receiver.
  double evaluate(const SourcePanel& panel, const std::vector<int>& occluders, bool& allHidden);

  // Evaluates the item's children and appends it (not yet in heap order) with its error estimate. A child
  // that no occluder touches hides nothing, one whose receiver is wholly hidden hides all of it: both are
  // exact (to the unoccluded rule's tolerance) and never split; only mixed children carry an error.
  // `cutAlong`: the near edge a strip was cut along, as for probeNear().
  void push(std::vector<Item>& heap, Item item, double estimate, bool estimateAllHidden, int cutAlong = -1);
  // A panel of the adaptive rules as it enters them (a source panel, or a strip cut along a near edge): the
  // occluders that can touch it, of `from`; returns its value where that is known outright (nothing hidden,
  // or all of the receiver), else pushes it.
  double enter(const SourcePanel& panel, const std::vector<int>& from, int depth, std::vector<Item>& heap,
               int cutAlong);

  // Wholly hidden panels do not overlap, so this holds their sum to half the tolerance.
  double pointTolerance() const { return 0.5 * tolerance_ / sourceArea_; }

  const ShadowClipper& clipper_;
  int order_;
  Unoccluded unoccluded_;
  double sourceArea_;
  PairWork& work_;
  std::vector<ShadowClipper::HiddenForm>& forms_;
  double tolerance_ = 0;
  const NearEdges* near_ = nullptr;  // operator()'s, while it runs
};

}  // namespace rt
