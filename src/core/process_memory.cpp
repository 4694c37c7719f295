#include "core/process_memory.h"

#include <fstream>
#include <unistd.h>

namespace glint {

std::optional<std::uint64_t> resident_memory_bytes() {
  // statm: total program size, then resident pages, in pages.
  std::ifstream statm("/proc/self/statm");
  std::uint64_t size_pages = 0, resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return std::nullopt;
  const long page_bytes = sysconf(_SC_PAGESIZE);
  if (page_bytes <= 0) return std::nullopt;
  return resident_pages * static_cast<std::uint64_t>(page_bytes);
}

}  // namespace glint
