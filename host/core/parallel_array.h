#pragma once
// Large per-item arrays whose elements are constructed on all threads. A std::vector of n
// shade points or hits value-initialises (and first-touches) all n elements on the calling
// thread; for the hundreds of thousands of record-ray hits per batch that serial pass left the
// other threads idle. ParallelArray constructs element i as make(i) (or by default) under
// parallelFor; ArrayView is the read-only (pointer, size) that functions taking either a
// std::vector or a ParallelArray accept.
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

#include "core/parallel.h"

namespace rc {

template <class T>
class ArrayView {
 public:
  ArrayView() = default;
  ArrayView(const T* data, size_t size) : data_(data), size_(size) {}
  ArrayView(const std::vector<T>& v) : data_(v.data()), size_(v.size()) {}  // NOLINT: implicit by design
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const T* data() const { return data_; }
  const T& operator[](size_t i) const { return data_[i]; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

 private:
  const T* data_ = nullptr;
  size_t size_ = 0;
};

template <class T>
class ParallelArray {
  // Elements are never destroyed one by one (the storage is released whole).
  static_assert(std::is_trivially_destructible<T>::value, "ParallelArray holds trivially destructible types");

 public:
  // Items per parallel task when constructing: an array of a few thousand items still splits into
  // many more tasks than threads, so the thread that takes the last one does not hold the loop up
  // long; each element is make(i) whatever the split.
  static constexpr size_t kChunk = 1024;

  ParallelArray() = default;
  // n default-constructed elements.
  explicit ParallelArray(size_t n) : ParallelArray(n, [](size_t) { return T(); }) {}
  // n elements left unconstructed, for a caller that constructs every one in place (placement
  // new from its own parallel loop) before any is read: neither a default-construction pass
  // over the whole array nor a copy of each element into it.
  struct Unconstructed {};
  ParallelArray(size_t n, Unconstructed) : data_(allocate(n)), size_(n) {}
  // Element i = make(i).
  template <class Make>
  ParallelArray(size_t n, Make&& make) : data_(allocate(n)), size_(n) {
    T* p = data_.get();
    parallelFor(n, kChunk, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) new (p + i) T(make(i));
    });
  }
  ParallelArray(ParallelArray&&) noexcept = default;
  ParallelArray& operator=(ParallelArray&&) noexcept = default;

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  T* begin() { return data_.get(); }
  T* end() { return data_.get() + size_; }
  const T* begin() const { return data_.get(); }
  const T* end() const { return data_.get() + size_; }
  operator ArrayView<T>() const { return ArrayView<T>(data_.get(), size_); }  // NOLINT: implicit by design

 private:
  struct Release {
    void operator()(T* p) const { ::operator delete(static_cast<void*>(p), std::align_val_t(alignof(T))); }
  };
  static T* allocate(size_t n) {
    return n ? static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(alignof(T)))) : nullptr;
  }
  std::unique_ptr<T[], Release> data_;
  size_t size_ = 0;
};

}  // namespace rc
