#include "mesh/weld.h"

#include <gtest/gtest.h>

namespace meshseg::mesh_internal {
namespace {

TEST(Welder, NumbersDistinctKeysInOrderOfFirstAppearance) {
  Welder<uint32_t> welder(1);  // grows past its first guess
  std::vector<int> index;
  for (uint32_t i = 0; i < 100; ++i) index.push_back(welder.Insert({i % 7, 1, 2}));
  ASSERT_EQ(welder.keys().size(), 7u);
  for (uint32_t i = 0; i < 100; ++i) EXPECT_EQ(index[i], static_cast<int>(i % 7));
  EXPECT_EQ(welder.keys()[3], (std::array<uint32_t, 3>{3, 1, 2}));
}

TEST(Welder, TellsKeysApartThatDifferInOneCoordinate) {
  Welder<uint64_t> welder(4);
  EXPECT_EQ(welder.Insert({1, 2, 3}), 0);
  EXPECT_EQ(welder.Insert({1, 2, 4}), 1);
  EXPECT_EQ(welder.Insert({0, 2, 3}), 2);
  EXPECT_EQ(welder.Insert({1, 2, 3}), 0);
}

}  // namespace
}  // namespace meshseg::mesh_internal
