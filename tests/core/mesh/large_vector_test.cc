#include "mesh/large_vector.h"

#include <cstdint>
#include <numeric>

#include <gtest/gtest.h>

namespace meshseg::mesh_internal {
namespace {

TEST(LargeVector, HoldsSmallAndHugeBuffersLikeStdVector) {
  LargeVector<int> small(10, 7);
  EXPECT_EQ(small[9], 7);
  LargeVector<int64_t> big(3'000'000);  // 24 MB: mapped in huge pages
  EXPECT_EQ(reinterpret_cast<uintptr_t>(big.data()) % (2 << 20), 0u);
  EXPECT_EQ(big[2'999'999], 0);
  std::iota(big.begin(), big.end(), 0);
  big.resize(5'000'000, -1);  // moves to a new mapping
  EXPECT_EQ(big[2'999'999], 2'999'999);
  EXPECT_EQ(big[4'999'999], -1);
  big.clear();
  big.shrink_to_fit();
  EXPECT_EQ(big.capacity(), 0u);
}

}  // namespace
}  // namespace meshseg::mesh_internal
