#include "segment/exact_seed_walk.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <numbers>
#include <stop_token>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "meshseg/mesh.h"
#include "segment/exact_tolerance.h"
#include "segment/facet_mesh.h"
#include "shared_data_files.h"

namespace meshseg::segment_internal {
namespace {

// `count` x `count` prisms along x over a square of side 7.5 with corners
// rounded by 2.54 in 9 strips each, fan caps, every vertex exact: many
// seeds, each prism's seeds close together in the order, as in a CAD export
// of a pin array.
Mesh PrismGrid(int count) {
  std::vector<Eigen::Vector2d> profile;
  const double side = 7.5, radius = 2.54, inner = side / 2 - radius;
  const Eigen::Vector2d centres[] = {
      {inner, -inner}, {inner, inner}, {-inner, inner}, {-inner, -inner}};
  profile.emplace_back(-inner, -side / 2);
  for (int k = 0; k < 4; ++k) {
    for (int j = 0; j <= 9 && !(k == 3 && j == 9); ++j) {
      const double a = (k - 1 + j / 9.0) * std::numbers::pi / 2;
      profile.push_back(centres[k] + radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
  }
  const int m = static_cast<int>(profile.size());
  std::vector<Eigen::Vector3d> v;
  std::vector<std::array<int, 3>> f;
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < count; ++j) {
      const int base = static_cast<int>(v.size());
      for (const double x : {0.0, 20.0}) {
        for (const Eigen::Vector2d& p : profile)
          v.emplace_back(x, 12.0 * i + p.x(), 12.0 * j + p.y());
      }
      v.emplace_back(0.0, 12.0 * i, 12.0 * j);
      v.emplace_back(20.0, 12.0 * i, 12.0 * j);
      const int c0 = base + 2 * m, c1 = c0 + 1;
      for (int a = 0; a < m; ++a) {
        const int b = (a + 1) % m;
        f.push_back({base + a, base + b, base + m + b});
        f.push_back({base + a, base + m + b, base + m + a});
        f.push_back({c0, base + b, base + a});
        f.push_back({c1, base + m + a, base + m + b});
      }
    }
  }
  absl::StatusOr<Mesh> mesh = BuildMesh(std::move(v), f, "prism grid");
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

// The seed walk's hypotheses with at most `threads` threads.
std::vector<Hypothesis> Walked(const FacetMesh& fm, double tau, int threads) {
  tbb::task_arena arena(threads);
  absl::StatusOr<std::vector<Hypothesis>> out =
      arena.execute([&] { return SeedHypotheses(fm, tau, RunContext{}); });
  EXPECT_TRUE(out.ok()) << out.status();
  return out.ok() ? *std::move(out) : std::vector<Hypothesis>{};
}

// The surface's parameters as numbers, compared exactly.
std::vector<double> Parameters(const Surface& surface) {
  return std::visit(
      [](const auto& s) {
        std::vector<double> out;
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) {
          out = {s.point.x(), s.point.y(), s.point.z(), s.normal.x(), s.normal.y(), s.normal.z()};
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          out = {
              s.axis_origin.x(),    s.axis_origin.y(),    s.axis_origin.z(), s.axis_direction.x(),
              s.axis_direction.y(), s.axis_direction.z(), s.radius};
        } else if constexpr (std::is_same_v<T, Cone>) {
          out = {s.apex.x(),           s.apex.y(),           s.apex.z(),          s.half_angle,
                 s.axis_direction.x(), s.axis_direction.y(), s.axis_direction.z()};
        } else if constexpr (std::is_same_v<T, Sphere>) {
          out = {s.center.x(), s.center.y(), s.center.z(), s.radius};
        } else if constexpr (std::is_same_v<T, Torus>) {
          out = {s.center.x(),         s.center.y(),         s.center.z(),   s.axis_direction.x(),
                 s.axis_direction.y(), s.axis_direction.z(), s.major_radius, s.minor_radius};
        }
        return out;
      },
      surface);
}

// Walking ahead on other threads changes nothing: the hypotheses, their
// order, supports and parameters to the bit, are those of the walk on one
// thread.
void ExpectSameOnAnyThreads(const Mesh& mesh) {
  const FacetMesh fm = BuildFacetMesh(mesh.tri);
  std::vector<Eigen::Vector3d> positions;
  for (const auto v : mesh.tri.vertices()) positions.push_back(ToEigen(mesh.tri.point(v)));
  const double tau = ExactTolerance(positions, fm.diagonal, PlanarityFloor(fm));
  const std::vector<Hypothesis> one = Walked(fm, tau, 1);
  ASSERT_GT(one.size(), 10u);
  for (const int threads : {2, 4}) {
    const std::vector<Hypothesis> many = Walked(fm, tau, threads);
    ASSERT_EQ(many.size(), one.size()) << threads << " threads";
    for (std::size_t i = 0; i < one.size(); ++i) {
      EXPECT_EQ(many[i].type, one[i].type) << "hypothesis " << i << ", " << threads << " threads";
      EXPECT_EQ(many[i].support, one[i].support) << "hypothesis " << i;
      EXPECT_EQ(Parameters(many[i].surface), Parameters(one[i].surface)) << "hypothesis " << i;
    }
  }
}

TEST(ExactSeedWalk, PrismGridGivesTheOneThreadHypothesesOnAnyThreads) {
  const Mesh mesh = PrismGrid(4);  // 2,560 facets, 160 seed positions per prism
  ExpectSameOnAnyThreads(mesh);
}

// Real CAD exports, each one connected part whose faces are seeded far
// apart in the order (inside first, borders last): walking ahead guesses
// wrong there, and the walk computes what the guess skipped.
TEST(ExactSeedWalk, RealCadPartsGiveTheOneThreadHypothesesOnAnyThreads) {
  for (const std::string name :
       {"cad/xupeiwust_hierarchical-cadnet__6_true.obj", "cad/whjdark_AAGNet__partA_stl.obj"}) {
    SCOPED_TRACE(name);
    const absl::StatusOr<Mesh> mesh = ReadMesh(testing::SharedData(name));
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    ExpectSameOnAnyThreads(*mesh);
  }
}

// A stop requested once the walk has begun (and the walk ahead with it)
// ends both, with CANCELLED.
TEST(ExactSeedWalk, StopsWithCancelledWhileWalkingAhead) {
  const Mesh mesh = PrismGrid(4);
  const FacetMesh fm = BuildFacetMesh(mesh.tri);
  std::stop_source stop;
  RunContext ctx{.stop = stop.get_token(),
                 .on_progress = [&](std::string_view, double) { stop.request_stop(); }};
  tbb::task_arena arena(2);
  const absl::StatusOr<std::vector<Hypothesis>> out =
      arena.execute([&] { return SeedHypotheses(fm, 1e-9 * fm.diagonal, ctx); });
  EXPECT_EQ(out.status().code(), absl::StatusCode::kCancelled) << out.status();
}

}  // namespace
}  // namespace meshseg::segment_internal
