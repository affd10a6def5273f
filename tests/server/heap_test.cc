#include "server/heap.h"

#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <vector>

#include "gtest/gtest.h"

namespace meshseg::server {
namespace {

constexpr int64_t kMiB = int64_t{1} << 20;

// Resident bytes of this process (/proc/self/statm, second field in pages).
int64_t ResidentBytes() {
  std::ifstream statm("/proc/self/statm");
  int64_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * sysconf(_SC_PAGESIZE);
}

// 64 KiB blocks (below glibc's mmap threshold, so they come from the arena),
// each written so its pages are resident.
std::vector<std::unique_ptr<char[]>> Blocks(int count) {
  std::vector<std::unique_ptr<char[]>> blocks;
  for (int i = 0; i < count; ++i) {
    blocks.emplace_back(new char[64 * 1024]);
    for (int b = 0; b < 64 * 1024; b += 512) blocks.back()[b] = static_cast<char>(i + b);
  }
  return blocks;
}

TEST(Heap, InUseFollowsAllocationsAndFreeKeepsWhatWasFreed) {
  const std::optional<HeapUsage> before = ReadHeapUsage();
  if (!before) GTEST_SKIP() << "no mallinfo2 in this C library";
  auto blocks = Blocks(256);  // 16 MiB
  const HeapUsage held = *ReadHeapUsage();
  EXPECT_GE(held.in_use_bytes - before->in_use_bytes, 15 * kMiB);
  // Free all but the last block: the freed ones stay in the arena below it.
  blocks.erase(blocks.begin(), blocks.end() - 1);
  const HeapUsage freed = *ReadHeapUsage();
  EXPECT_LE(freed.in_use_bytes - before->in_use_bytes, kMiB);
  EXPECT_GE(freed.free_bytes - before->free_bytes, 15 * kMiB);
}

TEST(Heap, ReturnFreeHeapGivesFreedPagesBackToTheSystem) {
  if (!ReadHeapUsage()) GTEST_SKIP() << "no malloc_trim in this C library";
  auto blocks = Blocks(1024);  // 64 MiB, resident
  // The last block stays allocated, on top of the freed ones: malloc cannot
  // shrink the arena from its top, so the freed 64 MiB stay resident ...
  blocks.erase(blocks.begin(), blocks.end() - 1);
  const int64_t kept = ResidentBytes();
  // ... until they are returned page by page.
  ReturnFreeHeap();
  const int64_t returned = ResidentBytes();
  EXPECT_GE(kept - returned, 48 * kMiB)
      << "resident " << kept / kMiB << " MiB before, " << returned / kMiB << " MiB after";
  EXPECT_EQ(blocks.size(), 1u);
}

// With large blocks mapped on their own, a large buffer freed below a block
// still in use goes back to the system at once, without ReturnFreeHeap, even
// after a larger block was freed (which would raise glibc's own threshold).
TEST(Heap, MapLargeBlocksReturnsAFreedLargeBufferAtOnce) {
  if (!MapLargeBlocks()) GTEST_SKIP() << "no mallopt in this C library";
  {
    // Freed, this mapped 16 MiB block would raise glibc's dynamic threshold to
    // 16 MiB (and put the 2 MiB buffers below in the arena).
    std::unique_ptr<char[]> large(new char[16 * kMiB]);
    char* volatile escaped = large.get();  // the allocation cannot be elided
    escaped[0] = 1;
  }
  std::vector<std::unique_ptr<char[]>> buffers;
  for (int i = 0; i < 16; ++i) {
    buffers.emplace_back(new char[2 * kMiB]);
    for (int64_t b = 0; b < 2 * kMiB; b += 512) buffers.back()[b] = static_cast<char>(b);
  }
  auto small = Blocks(1);  // allocated after the buffers: an arena could not shrink under it
  const int64_t held = ResidentBytes();
  buffers.clear();
  const int64_t after = ResidentBytes();
  EXPECT_GE(held - after, 28 * kMiB)
      << "resident " << held / kMiB << " MiB before the free, " << after / kMiB << " MiB after";
  EXPECT_EQ(small.size(), 1u);
}

}  // namespace
}  // namespace meshseg::server
