#pragma once
// UnzeroedVector<T>: the std::vector that a built structure's large arrays (Bvh::nodes,
// Bvh::prim_indices) are kept in. Two differences from std::vector<T>, both about the cost of
// sizing an array that parallel tasks are about to fill:
//  - resize(n) and UnzeroedVector<T>(n) leave the new elements unwritten instead of value-
//    initialising them. A std::vector of 600k BVH nodes is zeroed (and its 20 MB paged in) by the one
//    thread that sizes it, which on 16 cores took a third of an LBVH build; here the builders' parallel
//    tasks touch the pages first, as they write every element anyway. Every other way of adding
//    elements (push_back, insert, copies, resize(n, value)) constructs them as usual.
//  - Arrays of 4 MB and more are 2 MB aligned and ask for transparent huge pages, and their memory
//    is kept for reuse when freed, like the builders' scratch arrays (parallel_array.h).
// T must be trivially copyable and destructible (an implicit-lifetime type), so the allocation
// itself creates the elements and leaving them unwritten is well defined; reading one before it is
// written gives an unspecified value, so whoever calls resize(n) must write all n.
#include "accel/builders/parallel_array.h"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace glint::accel {

template <typename T>
struct UnzeroedAllocator {
  using value_type = T;

  UnzeroedAllocator() = default;
  template <typename U>
  UnzeroedAllocator(const UnzeroedAllocator<U>&) noexcept {}

  T* allocate(size_t n) {
    if (n > static_cast<size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return reinterpret_cast<T*>(detail::allocate_parallel_array(n * sizeof(T), alignment(n)));
  }
  void deallocate(T* p, size_t n) noexcept {
    detail::free_parallel_array(reinterpret_cast<std::byte*>(p), n * sizeof(T), alignment(n));
  }

  // Value-initialisation (resize(n), vector(n)) writes nothing; anything else constructs as usual.
  template <typename U>
  void construct(U*) noexcept {
    static_assert(std::is_trivially_copyable_v<U> && std::is_trivially_destructible_v<U>);
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <typename U>
  bool operator==(const UnzeroedAllocator<U>&) const noexcept {
    return true;
  }

 private:
  static size_t alignment(size_t n) {
    return n * sizeof(T) >= detail::kHugePageMinBytes ? detail::kHugePageBytes
                                                      : std::max(alignof(T), alignof(std::max_align_t));
  }
};

template <typename T>
using UnzeroedVector = std::vector<T, UnzeroedAllocator<T>>;

}  // namespace glint::accel
