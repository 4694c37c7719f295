#pragma once
// Internal to the builders: a fixed-size array whose elements are constructed by parallel TBB chunks.
// A std::vector of n elements is constructed (and its fresh pages faulted in) by one thread; for the
// builders' scratch arrays of about a million nodes that serial step alone took longer on 16 cores
// than the parallel build steps around it. Elements are value-initialised, as in a std::vector, or,
// with kForOverwrite, not initialised at all. A contiguous range, so it converts to std::span.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace glint::accel::detail {

// Tag for arrays every element of which is written before it is read: no construction pass at all.
struct ForOverwrite {};
inline constexpr ForOverwrite kForOverwrite{};

// Arrays of at least this many bytes ask the kernel for transparent huge pages (Linux madvise): a
// fresh array's first touch then costs one page fault per 2 MB instead of per 4 KB, and page faults
// were a third of an LBVH build's time on atrium.
inline constexpr size_t kHugePageBytes = size_t{2} << 20;
inline constexpr size_t kHugePageMinBytes = 2 * kHugePageBytes;

// Raw storage of `bytes`, 2 MB aligned and marked for huge pages when large (alignment ==
// kHugePageBytes). Large blocks are not given back to the system when freed but kept for the next
// allocation they fit, up to kRetainedBlockBytes in all: a fresh block costs a page fault and the
// kernel's zeroing per page, which on atrium were a quarter of a repeated lbvh build (a third on the
// GPU machine's host). Embree keeps a dynamic scene's build arrays between builds for the same reason.
std::byte* allocate_parallel_array(size_t bytes, size_t alignment);
void free_parallel_array(std::byte* storage, size_t bytes, size_t alignment);

inline constexpr size_t kRetainedBlockBytes = size_t{256} << 20;

// The large blocks kept for reuse: how many bytes, and giving them all back to the system.
size_t retained_block_bytes();
void release_retained_blocks();

template <typename T>
class ParallelArray {
  // Nothing to destroy and nothing to do on a move, so the array can be plain uninitialised storage.
  static_assert(std::is_trivially_destructible_v<T> && std::is_trivially_copyable_v<T>);

 public:
  ParallelArray() = default;
  explicit ParallelArray(size_t size) : ParallelArray(size, kForOverwrite) {
    T* elements = data();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, size, 8192), [elements](const tbb::blocked_range<size_t>& r) {
      std::uninitialized_value_construct(elements + r.begin(), elements + r.end());
    });
  }
  // Elements left unconstructed: T is trivially copyable and destructible (an implicit-lifetime type),
  // so the storage's allocation creates them and the first assignment gives them values. Pages are
  // then first touched by whoever writes them, usually a parallel loop.
  ParallelArray(size_t size, ForOverwrite)
      : size_(size), storage_(size == 0 ? nullptr : allocate_parallel_array(size * sizeof(T), alignment(size)),
                              Free{size * sizeof(T), alignment(size)}) {}

  ParallelArray(ParallelArray&& other) noexcept
      : size_(std::exchange(other.size_, 0)), storage_(std::move(other.storage_)) {}
  ParallelArray& operator=(ParallelArray&& other) noexcept {
    size_ = std::exchange(other.size_, 0);
    storage_ = std::move(other.storage_);
    return *this;
  }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* data() { return std::launder(reinterpret_cast<T*>(storage_.get())); }
  const T* data() const { return std::launder(reinterpret_cast<const T*>(storage_.get())); }
  T& operator[](size_t i) { return data()[i]; }
  const T& operator[](size_t i) const { return data()[i]; }
  T* begin() { return data(); }
  T* end() { return data() + size_; }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size_; }

 private:
  struct Free {
    size_t bytes = 0;
    size_t alignment = alignof(std::max_align_t);
    void operator()(std::byte* storage) const { free_parallel_array(storage, bytes, alignment); }
  };
  static size_t alignment(size_t size) {
    const size_t bytes = size * sizeof(T);
    return bytes >= kHugePageMinBytes ? kHugePageBytes : std::max(alignof(T), alignof(std::max_align_t));
  }
  size_t size_ = 0;
  std::unique_ptr<std::byte, Free> storage_;
};

}  // namespace glint::accel::detail
