// A binary max-heap on a std::vector whose arrangement depends only on the comparisons made, so that the
// order in which equal keys leave it is the same with every standard library. std::push_heap and
// std::pop_heap promise only that the largest leaves first: libstdc++ (the native build) and libc++ (the
// WebAssembly build) arrange equal keys differently, and an adaptive rule that stops part way through
// equally rated cells then integrates different cells in the two builds (docs/web.md, the agreement test).
// The hole goes down to a leaf along the larger children (the right one of two equal) and the value rises
// from there (Floyd's way): the arrangement of the native build's standard library, so that the native
// numbers stay what they were.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace rt::portable_heap {

// Puts `value` in the hole at heap[hole], rising while it is larger than its parent, not above `top`.
template <class T, class Less>
void rise(std::vector<T>& heap, std::size_t hole, std::size_t top, T value, Less& less) {
  while (hole > top) {
    const std::size_t parent = (hole - 1) / 2;
    if (!less(heap[parent], value)) break;
    heap[hole] = std::move(heap[parent]);
    hole = parent;
  }
  heap[hole] = std::move(value);
}

// Fills the hole at heap[hole] of the heap heap[0, size) with `value`: the hole down to a leaf, then up.
template <class T, class Less>
void fill(std::vector<T>& heap, std::size_t hole, std::size_t size, T value, Less& less) {
  const std::size_t top = hole;
  std::size_t child = hole;
  while (size >= 2 && child < (size - 1) / 2) {
    child = 2 * child + 2;
    if (less(heap[child], heap[child - 1])) --child;
    heap[hole] = std::move(heap[child]);
    hole = child;
  }
  if (size >= 2 && size % 2 == 0 && child == (size - 2) / 2) {
    child = 2 * child + 1;
    heap[hole] = std::move(heap[child]);
    hole = child;
  }
  rise(heap, hole, top, std::move(value), less);
}

// Arranges the whole vector as a heap.
template <class T, class Less>
void make(std::vector<T>& heap, Less less) {
  const std::size_t size = heap.size();
  if (size < 2) return;
  for (std::size_t parent = (size - 2) / 2 + 1; parent-- > 0;) {
    T value = std::move(heap[parent]);
    fill(heap, parent, size, std::move(value), less);
  }
}

// Takes heap[size - 1] into the heap of heap[0, size - 1).
template <class T, class Less>
void push(std::vector<T>& heap, std::size_t size, Less less) {
  if (size < 2) return;
  T value = std::move(heap[size - 1]);
  rise(heap, size - 1, 0, std::move(value), less);
}

// Moves the largest to the back, the rest a heap before it (the caller pops it off the vector).
template <class T, class Less>
void pop(std::vector<T>& heap, Less less) {
  const std::size_t size = heap.size();
  if (size < 2) return;
  T value = std::move(heap[size - 1]);
  heap[size - 1] = std::move(heap[0]);
  fill(heap, 0, size - 1, std::move(value), less);
}

}  // namespace rt::portable_heap
