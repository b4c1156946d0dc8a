#include "core/portable_heap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace rt {
namespace {

// Keys with many ties (an adaptive rule's equally rated cells), each with its own label, so that two
// arrangements of equal keys can be told apart.
struct Keyed {
  int key = 0, label = 0;
  bool operator==(const Keyed&) const = default;
};
const auto byKey = [](const Keyed& a, const Keyed& b) { return a.key < b.key; };

// The order in which the heap hands out its items under a mix of pushes and pops, as the adaptive rules
// use it (pop the largest, push its parts), and the arrangement left at the end.
template <class Make, class Push, class Pop>
std::vector<Keyed> run(unsigned seed, Make make, Push push, Pop pop, std::vector<Keyed>& heap) {
  std::mt19937 random(seed);
  heap.clear();
  int label = 0;
  for (int k = 0; k < 40; ++k) heap.push_back({int(random() % 5), label++});
  make(heap);
  std::vector<Keyed> out;
  for (int step = 0; step < 200 && !heap.empty(); ++step) {
    pop(heap);
    out.push_back(heap.back());
    heap.pop_back();
    for (unsigned c = 0, parts = random() % 4; c < parts; ++c) {
      heap.push_back({int(random() % 5), label++});
      push(heap);
    }
  }
  return out;
}

std::vector<Keyed> portable(unsigned seed, std::vector<Keyed>& heap) {
  return run(
      seed, [](std::vector<Keyed>& h) { portable_heap::make(h, byKey); },
      [](std::vector<Keyed>& h) { portable_heap::push(h, h.size(), byKey); },
      [](std::vector<Keyed>& h) { portable_heap::pop(h, byKey); }, heap);
}

TEST(PortableHeap, HandsOutTheLargestFirst) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::vector<Keyed> heap;
    std::vector<Keyed> all;
    std::mt19937 random(seed);
    for (int k = 0; k < 57; ++k) all.push_back({int(random() % 7), k});
    heap = all;
    portable_heap::make(heap, byKey);
    EXPECT_TRUE(std::is_heap(heap.begin(), heap.end(), byKey));
    std::vector<int> keys;
    while (!heap.empty()) {
      portable_heap::pop(heap, byKey);
      keys.push_back(heap.back().key);
      heap.pop_back();
      EXPECT_TRUE(std::is_heap(heap.begin(), heap.end(), byKey));
    }
    EXPECT_TRUE(std::is_sorted(keys.rbegin(), keys.rend())) << "seed " << seed;
    EXPECT_EQ(keys.size(), all.size());
  }
}

#if defined(__GLIBCXX__)
// Against the native build's standard library: the same items in the same order, ties included, so that the
// native numbers of the adaptive rules are what they were with std::push_heap and std::pop_heap.
TEST(PortableHeap, ArrangesEqualKeysAsTheNativeStandardLibraryDoes) {
  for (unsigned seed = 1; seed <= 50; ++seed) {
    std::vector<Keyed> ours, theirs;
    const std::vector<Keyed> a = portable(seed, ours);
    const std::vector<Keyed> b = run(
        seed, [](std::vector<Keyed>& h) { std::make_heap(h.begin(), h.end(), byKey); },
        [](std::vector<Keyed>& h) { std::push_heap(h.begin(), h.end(), byKey); },
        [](std::vector<Keyed>& h) { std::pop_heap(h.begin(), h.end(), byKey); }, theirs);
    EXPECT_EQ(a, b) << "seed " << seed;
    EXPECT_EQ(ours, theirs) << "seed " << seed;
  }
}
#endif

}  // namespace
}  // namespace rt
