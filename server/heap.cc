#include "server/heap.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace meshseg::server {

void ReturnFreeHeap() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

bool MapLargeBlocks(int64_t threshold_bytes) {
#if defined(__GLIBC__)
  // Setting it disables glibc's dynamic threshold (and its trim threshold's).
  return mallopt(M_MMAP_THRESHOLD, static_cast<int>(threshold_bytes)) == 1;
#else
  return false;
#endif
}

std::optional<HeapUsage> ReadHeapUsage() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 33)
  const struct mallinfo2 info = mallinfo2();
  HeapUsage usage;
  usage.in_use_bytes = static_cast<int64_t>(info.uordblks + info.hblkhd);
  usage.free_bytes = static_cast<int64_t>(info.fordblks);
  return usage;
#else
  return std::nullopt;
#endif
}

}  // namespace meshseg::server
