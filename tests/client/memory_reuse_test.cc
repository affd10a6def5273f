#include "client/memory_reuse.h"

#include <sys/resource.h>

#include <cstddef>
#include <cstdlib>

#include <gtest/gtest.h>

namespace meshseg::cli {
namespace {

long MinorFaults() {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// Page faults taken to allocate `bytes`, write every page, and free them.
long FaultsToUse(std::size_t bytes) {
  const long before = MinorFaults();
  volatile char* block = static_cast<char*>(std::malloc(bytes));
  for (std::size_t i = 0; i < bytes; i += 4096) block[i] = 1;
  const long faults = MinorFaults() - before;
  std::free(const_cast<char*>(block));
  return faults;
}

TEST(KeepFreedMemoryForReuse, AFreedBlockIsUsedAgainWithoutPageFaults) {
  ASSERT_TRUE(KeepFreedMemoryForReuse());
  // Over glibc's default mmap threshold (128 KiB), under the 32 MiB set.
  constexpr std::size_t kBytes = std::size_t{16} << 20;
  EXPECT_GT(FaultsToUse(kBytes), 0);  // first use: its 4096 pages fault in
  // Given back to the kernel, the second use would fault all 4096 pages
  // again; kept, it faults none (a few for the counters' own pages at most).
  EXPECT_LT(FaultsToUse(kBytes), 64);
  EXPECT_LT(FaultsToUse(kBytes / 2), 64);
}

}  // namespace
}  // namespace meshseg::cli
