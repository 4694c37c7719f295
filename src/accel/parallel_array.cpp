#include "accel/parallel_array.h"

#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace glint::accel::detail {

std::byte* allocate_parallel_array(size_t bytes, size_t alignment) {
  auto* storage = static_cast<std::byte*>(::operator new(bytes, std::align_val_t{alignment}));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: where transparent huge pages are off (or already always on) nothing changes, and a
  // failure leaves ordinary pages.
  if (alignment == kHugePageBytes) (void)madvise(storage, bytes / kHugePageBytes * kHugePageBytes, MADV_HUGEPAGE);
#endif
  return storage;
}

void free_parallel_array(std::byte* storage, size_t alignment) { ::operator delete(storage, std::align_val_t{alignment}); }

}  // namespace glint::accel::detail
