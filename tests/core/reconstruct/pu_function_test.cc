#include "reconstruct/pu_function.h"

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

Support Ball(const Eigen::Vector3d& center, double radius, const Eigen::Vector3d& m,
             double offset) {
  Support s;
  s.center = center;
  s.radius = radius;
  s.m = m.normalized();
  s.d = -offset * s.m;  // g(x) = m·x + offset
  return s;
}

TEST(PuFunction, OneSupportGivesItsLocalFunctionInsideTheBall) {
  const std::vector<Support> supports = {Ball({0, 0, 0}, 1.0, {0, 0, 1}, 0.2)};
  const PuFunction f(supports);
  EXPECT_DOUBLE_EQ(f({0, 0, 0}), 0.2);
  EXPECT_DOUBLE_EQ(f({0.3, 0.1, 0.5}), 0.7);
  EXPECT_DOUBLE_EQ(f({0, 0, 2}), -1.0);  // no ball reaches: outside, −largest radius
}

TEST(PuFunction, BlendsOverlappingSupportsWithWeightsSummingToOne) {
  // Two supports with the same g on very different radii (two radius groups).
  const std::vector<Support> same = {Ball({0, 0, 0}, 0.5, {1, 0, 0}, 0.0),
                                     Ball({0.3, 0, 0}, 4.0, {1, 0, 0}, 0.0)};
  const PuFunction f(same);
  for (const double x : {-0.3, 0.0, 0.2, 1.5}) EXPECT_NEAR(f({x, 0.1, 0}), x, 1e-12);
  // Different g: at the small ball's centre its weight b2(0) = 0.75 against
  // the big one's b2(1.5 · 0.3 / 4).
  const std::vector<Support> mixed = {Ball({0, 0, 0}, 0.5, {0, 0, 1}, 1.0),
                                      Ball({0.3, 0, 0}, 4.0, {0, 0, 1}, -1.0)};
  const PuFunction g(mixed);
  const double w0 = B2(0.0), w1 = B2(1.5 * 0.3 / 4.0);
  EXPECT_NEAR(g({0, 0, 0}), (w0 - w1) / (w0 + w1), 1e-12);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
