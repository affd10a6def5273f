#include "client/memory_reuse.h"

#include <malloc.h>

#include <climits>

namespace meshseg::cli {

bool KeepFreedMemoryForReuse() {
  // glibc's ceiling for the threshold: HEAP_MAX_SIZE / 2 on 64-bit targets.
  constexpr int kMmapThreshold = 32 << 20;
  const bool mmap_set = mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1;
  const bool trim_set = mallopt(M_TRIM_THRESHOLD, INT_MAX) == 1;
  return mmap_set && trim_set;
}

}  // namespace meshseg::cli
