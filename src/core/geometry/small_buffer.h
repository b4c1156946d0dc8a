// An array of N slots kept inline that grows onto the heap when asked for more: the convex polygons
// (convex_polygon.h) and the shadow clipper's scratch arrays.
//
// Almost every polygon the clipper makes has a few corners (a quadrilateral cut by a handful of planes), so
// N slots inline cost no allocation; an occluder of a hundred corners, or a piece cut by many cones, asks
// for more with reserve() and gets them, instead of losing the corners past N. The buffer does not count
// its entries: the caller keeps the count (ConvexPolygon::count) and reserves before it writes.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>

namespace rt {

template <class T, int N>
class SmallBuffer {
  static_assert(N > 0);

 public:
  static constexpr int kInline = N;

  // (data_ is set in the bodies: the inline slots are left unset, as a plain array's would be.)
  SmallBuffer() noexcept { data_ = inline_.data(); }
  SmallBuffer(const SmallBuffer& other) {
    data_ = inline_.data();
    copyFrom(other);
  }
  SmallBuffer(SmallBuffer&& other) noexcept {
    data_ = inline_.data();
    moveFrom(other);
  }
  SmallBuffer& operator=(const SmallBuffer& other) {
    if (this != &other) copyFrom(other);
    return *this;
  }
  SmallBuffer& operator=(SmallBuffer&& other) noexcept {
    if (this != &other) moveFrom(other);
    return *this;
  }
  ~SmallBuffer() = default;

  T* data() { return data_; }
  const T* data() const { return data_; }
  T* begin() { return data_; }
  const T* begin() const { return data_; }
  T& operator[](std::size_t k) { return data_[k]; }
  const T& operator[](std::size_t k) const { return data_[k]; }
  int capacity() const { return capacity_; }

  // Room for at least `n` entries; the entries held so far are kept.
  void reserve(int n) {
    if (n > capacity_) grow(n);
  }
  // Room for `n` entries, the first n set to `value`.
  void assign(int n, const T& value) {
    reserve(n);
    std::fill_n(data_, std::max(0, n), value);
  }

 private:
  void grow(int n) {
    const int capacity = std::max(n, 2 * capacity_);
    std::unique_ptr<T[]> heap(new T[static_cast<std::size_t>(capacity)]);
    std::copy_n(data_, capacity_, heap.get());
    heap_ = std::move(heap);
    data_ = heap_.get();
    capacity_ = capacity;
  }
  // The other's entries, all of its capacity (the count lives with the caller).
  void copyFrom(const SmallBuffer& other) {
    reserve(other.capacity_);
    std::copy_n(other.data_, other.capacity_, data_);
  }
  void moveFrom(SmallBuffer& other) {
    if (other.heap_) {
      heap_ = std::move(other.heap_);
      data_ = heap_.get();
      capacity_ = other.capacity_;
      other.data_ = other.inline_.data();
      other.capacity_ = N;
    } else {
      std::copy_n(other.inline_.data(), N, data_);
    }
  }

  std::array<T, N> inline_;
  std::unique_ptr<T[]> heap_;
  T* data_ = nullptr;
  int capacity_ = N;
};

}  // namespace rt
