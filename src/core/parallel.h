// The core's parallel loops: TBB in the native build, a plain serial loop where TBB is absent (the
// WebAssembly build, which has no threads). Every parallel loop of the core goes through here, so that the
// core builds on both without a TBB type in its sources. The loops' results never depend on how a range is
// cut: the callers seed their random numbers by index or by fixed chunk, never by task or thread.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace rt {

// How a range is cut into tasks (the native build; the serial build runs the whole range as one chunk).
struct ParallelOptions {
  std::size_t grain = 1;  // no chunk smaller than this, but for the last
  // True: exactly one chunk of `grain` indices per task (TBB's simple partitioner), for iterations whose
  // costs differ by orders of magnitude; false: TBB's automatic partitioner.
  bool chunkPerTask = false;
  int threads = 0;  // at most this many threads (0: all cores)
};

// Calls body(begin, end) on disjoint chunks covering [first, last), in parallel where the build has threads.
void parallelForChunks(std::size_t first, std::size_t last, const ParallelOptions& options,
                       const std::function<void(std::size_t begin, std::size_t end)>& body);

// Calls body(i) for every i in [first, last).
template <class Index, class Body>
void parallelFor(Index first, Index last, Body&& body, const ParallelOptions& options = {}) {
  if (!(first < last)) return;
  parallelForChunks(0, static_cast<std::size_t>(last - first), options,
                    [&](std::size_t begin, std::size_t end) {
                      for (std::size_t k = begin; k != end; ++k) body(static_cast<Index>(first + Index(k)));
                    });
}

// True when this build runs the loops above on more than one thread.
bool parallelBuild();

// The worker running the calling code, in [0, workerSlots()): no two threads inside one parallel loop share
// it. Outside any loop it is 0.
int workerIndex();
int workerSlots();

// One value per worker, made on first use by the worker that uses it: scratch space and counters that a
// loop's iterations share without locks. forEach visits the values made, after the loop.
template <class T>
class PerWorker {
 public:
  template <class... Args>
  explicit PerWorker(Args... args)
      : values_(static_cast<std::size_t>(workerSlots())),
        make_([args...] { return std::make_unique<T>(args...); }) {}

  T& local() {
    std::unique_ptr<T>& slot = values_[static_cast<std::size_t>(workerIndex())];
    if (!slot) slot = make_();
    return *slot;
  }
  template <class Visit>
  void forEach(Visit&& visit) {
    for (std::unique_ptr<T>& value : values_)
      if (value) visit(*value);
  }

 private:
  std::vector<std::unique_ptr<T>> values_;
  std::function<std::unique_ptr<T>()> make_;
};

// Sorts [first, last) by `less`, a strict weak order: chunks sorted in parallel, then merged.
template <class Iterator, class Less>
void parallelSort(Iterator first, Iterator last, Less less) {
  const auto n = static_cast<std::size_t>(last - first);
  const std::size_t parts = parallelBuild() ? std::size_t(std::max(1, workerSlots())) : 1;
  if (parts < 2 || n < 4096) {
    std::sort(first, last, less);
    return;
  }
  const std::size_t size = (n + parts - 1) / parts;
  parallelForChunks(0, parts, {}, [&](std::size_t begin, std::size_t end) {
    for (std::size_t p = begin; p != end; ++p)
      std::sort(first + std::min(n, p * size), first + std::min(n, (p + 1) * size), less);
  });
  for (std::size_t width = size; width < n; width *= 2)
    for (std::size_t start = 0; start + width < n; start += 2 * width)
      std::inplace_merge(first + start, first + start + width, first + std::min(n, start + 2 * width), less);
}

}  // namespace rt
