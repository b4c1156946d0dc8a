#include "core/parallel.h"

#if RT_HAVE_TBB
#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#endif

namespace rt {

#if RT_HAVE_TBB

namespace {

// Slots for PerWorker: an arena's thread indices stay below its concurrency, and a loop asks for at most
// this many threads.
int slots() {
  static const int count = std::max(64, tbb::info::default_concurrency());
  return count;
}

}  // namespace

void parallelForChunks(std::size_t first, std::size_t last, const ParallelOptions& options,
                       const std::function<void(std::size_t begin, std::size_t end)>& body) {
  if (!(first < last)) return;
  const tbb::blocked_range<std::size_t> range(first, last, std::max<std::size_t>(1, options.grain));
  auto chunk = [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); };
  auto run = [&] {
    if (options.chunkPerTask) {
      tbb::simple_partitioner partitioner;
      tbb::parallel_for(range, chunk, partitioner);
    } else {
      tbb::parallel_for(range, chunk);
    }
  };
  if (options.threads > 0) {
    tbb::task_arena arena(std::min(options.threads, slots()));
    arena.execute(run);
  } else {
    run();
  }
}

bool parallelBuild() {
  return true;
}

int workerIndex() {
  const int index = tbb::this_task_arena::current_thread_index();
  return index >= 0 && index < slots() ? index : 0;
}

int workerSlots() {
  return slots();
}

#else

void parallelForChunks(std::size_t first, std::size_t last, const ParallelOptions&,
                       const std::function<void(std::size_t begin, std::size_t end)>& body) {
  if (first < last) body(first, last);
}

bool parallelBuild() {
  return false;
}
int workerIndex() {
  return 0;
}
int workerSlots() {
  return 1;
}

#endif

}  // namespace rt
