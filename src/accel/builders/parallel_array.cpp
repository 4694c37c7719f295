#include "accel/builders/parallel_array.h"

#include <algorithm>
#include <mutex>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace glint::accel::detail {
namespace {

// A large block's size as allocated: whole huge pages, so that a block freed by one array fits
// any later array that rounds up to the same.
size_t block_bytes(size_t bytes) { return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes; }

struct RetainedBlock {
  std::byte* storage;
  size_t bytes;
};

// Freed large blocks, oldest first.
class RetainedBlocks {
 public:
  // The smallest kept block of at least `bytes` and at most twice that (a larger one would hold
  // memory that the array leaves unused), taken out; null if none.
  std::byte* take(size_t bytes) {
    const std::lock_guard lock(mutex_);
    auto best = blocks_.end();
    for (auto it = blocks_.begin(); it != blocks_.end(); ++it)
      if (it->bytes >= bytes && it->bytes <= 2 * bytes && (best == blocks_.end() || it->bytes < best->bytes)) best = it;
    if (best == blocks_.end()) return nullptr;
    std::byte* storage = best->storage;
    total_ -= best->bytes;
    blocks_.erase(best);
    return storage;
  }

  // Keeps the block, giving the oldest ones back to the system while more than the limit are kept.
  void keep(std::byte* storage, size_t bytes) {
    std::vector<RetainedBlock> released;
    {
      const std::lock_guard lock(mutex_);
      blocks_.push_back({storage, bytes});
      total_ += bytes;
      while (total_ > kRetainedBlockBytes) {
        released.push_back(blocks_.front());
        total_ -= blocks_.front().bytes;
        blocks_.erase(blocks_.begin());
      }
    }
    for (const RetainedBlock& block : released) release(block);
  }

  size_t total() {
    const std::lock_guard lock(mutex_);
    return total_;
  }

  void release_all() {
    std::vector<RetainedBlock> released;
    {
      const std::lock_guard lock(mutex_);
      released.swap(blocks_);
      total_ = 0;
    }
    for (const RetainedBlock& block : released) release(block);
  }

 private:
  static void release(const RetainedBlock& block) {
    ::operator delete(block.storage, std::align_val_t{kHugePageBytes});
  }

  std::mutex mutex_;
  std::vector<RetainedBlock> blocks_;
  size_t total_ = 0;
};

// Never destroyed: an array in a static object that outlives this one still frees into it at exit.
RetainedBlocks& retained_blocks() {
  static auto* blocks = new RetainedBlocks;
  return *blocks;
}

}  // namespace

std::byte* allocate_parallel_array(size_t bytes, size_t alignment) {
  if (alignment != kHugePageBytes) return static_cast<std::byte*>(::operator new(bytes, std::align_val_t{alignment}));
  const size_t size = block_bytes(bytes);
  if (std::byte* reused = retained_blocks().take(size)) return reused;
  auto* storage = static_cast<std::byte*>(::operator new(size, std::align_val_t{alignment}));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: where transparent huge pages are off (or already always on) nothing changes, and a
  // failure leaves ordinary pages.
  (void)madvise(storage, size, MADV_HUGEPAGE);
#endif
  return storage;
}

void free_parallel_array(std::byte* storage, size_t bytes, size_t alignment) {
  if (storage == nullptr) return;
  if (alignment == kHugePageBytes)
    retained_blocks().keep(storage, block_bytes(bytes));
  else
    ::operator delete(storage, std::align_val_t{alignment});
}

size_t retained_block_bytes() { return retained_blocks().total(); }

void release_retained_blocks() { retained_blocks().release_all(); }

}  // namespace glint::accel::detail
