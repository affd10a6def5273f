#include "subdiv/feature_lines.h"

#include <cmath>
#include <vector>

#include "meshseg/curvature.h"
#include "shapes.h"

namespace meshseg::subdiv_internal {
namespace {

constexpr int kW = 24, kH = 16;

int At(int i, int j) { return j * kW + i; }

// A flat kW x kH grid of unit squares split along (i, j)-(i + 1, j + 1).
Mesh Grid() {
  testing::Triangles t;
  for (int j = 0; j < kH; ++j) {
    for (int i = 0; i < kW; ++i) t.vertices.emplace_back(i, j, 0.0);
  }
  for (int j = 0; j + 1 < kH; ++j) {
    for (int i = 0; i + 1 < kW; ++i) {
      t.faces.push_back({At(i, j), At(i + 1, j), At(i + 1, j + 1)});
      t.faces.push_back({At(i, j), At(i + 1, j + 1), At(i, j + 1)});
    }
  }
  absl::StatusOr<Mesh> mesh = testing::ToMesh(t, "grid");
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

// Sharp flags and strengths per vertex of Grid().
struct Field {
  std::vector<uint8_t> sharp = std::vector<uint8_t>(kW * kH, 0);
  std::vector<double> strength = std::vector<double>(kW * kH, 0.0);
  void Set(int i, int j, double s) {
    sharp[At(i, j)] = 1;
    strength[At(i, j)] = s;
  }
};

// A band three vertices wide, rows 4 to 6 of columns 2 to 17, whose
// curvature peaks on row 5 (as across a crease): the crest line is row 5.
Field Band() {
  Field f;
  for (int i = 2; i <= 17; ++i) {
    for (int j = 4; j <= 6; ++j) f.Set(i, j, 3.0 - std::abs(j - 5) + 0.01 * i);
  }
  return f;
}

// The flagged edges as (i, j) pairs of their end vertices.
std::vector<std::array<int, 4>> Edges(const Mesh& mesh, const FeatureLines& lines) {
  std::vector<std::array<int, 4>> out;
  for (auto e : mesh.tri.edges()) {
    if (!lines.edge[e.idx()]) continue;
    const int a = e.v0().idx(), b = e.v1().idx();
    out.push_back({a % kW, a / kW, b % kW, b / kW});
  }
  return out;
}

TEST(DetectFeatureLines, ThinsASharpBandToItsCrestLine) {
  const Mesh mesh = Grid();
  const Field f = Band();
  const FeatureLines lines = DetectFeatureLines(mesh.tri, f.sharp, f.strength, 4);
  const auto edges = Edges(mesh, lines);
  EXPECT_EQ(edges.size(), 15u);  // columns 2 .. 17 along row 5
  for (const auto& e : edges) {
    EXPECT_TRUE(e[1] == 5 && e[3] == 5) << e[0] << "," << e[1] << " - " << e[2] << "," << e[3];
  }
  EXPECT_EQ(lines.count[At(2, 5)], 1);
  EXPECT_EQ(lines.count[At(17, 5)], 1);
  EXPECT_EQ(lines.count[At(9, 5)], 2);
}

TEST(DetectFeatureLines, DropsSpursAndShortPiecesButKeepsLongBranches) {
  const Mesh mesh = Grid();
  Field f = Band();
  // A spur of two vertices off the line at column 6 (weaker than the line),
  // an isolated piece of three vertices, and a branch of eight vertices at
  // column 13 down to row 13.
  f.Set(6, 7, 2.5);
  f.Set(6, 8, 2.5);
  for (int i = 3; i <= 5; ++i) f.Set(i, 12, 1.0);
  for (int j = 7; j <= 14; ++j) f.Set(13, j, 2.5);
  const FeatureLines lines = DetectFeatureLines(mesh.tri, f.sharp, f.strength, 4);
  int row5 = 0, branch = 0, other = 0;
  for (const auto& e : Edges(mesh, lines)) {
    if (e[1] == 5 && e[3] == 5) {
      ++row5;
    } else if (e[0] == 13 && e[2] == 13) {
      ++branch;
    } else {
      ++other;
    }
  }
  EXPECT_EQ(row5, 15);
  EXPECT_GE(branch, 7);
  EXPECT_EQ(other, 0);
  int junctions = 0;
  for (int c : lines.count) junctions += c >= 3;
  EXPECT_EQ(junctions, 1);  // where the branch meets the line
  EXPECT_EQ(lines.count[At(6, 6)] + lines.count[At(6, 7)] + lines.count[At(6, 8)], 0);
  EXPECT_EQ(lines.count[At(4, 12)], 0);
}

TEST(RidgeVertices, FindNoneOnATubeCurvedTighterThanTheSharpThresholdAllOver) {
  // A tube of radius 1 sampled by 20 edges around (h about 0.36): its
  // radius is under 3 h, so the curvature stage flags most of its vertices
  // sharp, but no vertex stands above its surroundings.
  const testing::KnotTube tube;
  const double h0 = testing::MeanEdge(tube.Mesh(200, 20, 0.0, 1));
  auto mesh = testing::ToMesh(tube.Mesh(200, 20, 0.05 * h0, 3), "tube");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto field = EstimateCurvature(*mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  int sharp = 0, ridges = 0;
  for (uint8_t s : field->sharp) sharp += s;
  for (uint8_t r : RidgeVertices(mesh->tri, *field, 5.0, kMinRidgeContrast)) ridges += r;
  EXPECT_GT(sharp, 2000);  // of 4000
  EXPECT_EQ(ridges, 0);
}

TEST(DetectFeatureLines, FollowsTheCreasesOfANoisyMarchingCubesBody) {
  // A superellipsoid unioned with a cylinder (marching cubes, noise 0.05 h
  // along the normal): two closed creases, the cylinder's rim and the curve
  // where it leaves the superellipsoid. The curvature stage's sharp vertices
  // form bands along both, where a dihedral-angle test sees a network of
  // short lines and junctions (the slivers that straddle each crease). The feature lines must follow the creases
  // within 1 h, cover most of their length and have no junction.
  const testing::BlendedBody body;
  const double h0 = testing::MeanEdge(body.Mesh(0.6, 0.0, 1));
  const testing::Triangles t = body.Mesh(0.6, 0.05 * h0, 9);
  const double h = testing::MeanEdge(t);
  auto mesh = testing::ToMesh(t, "blended");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto field = EstimateCurvature(*mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  std::vector<double> strength;
  for (double k : field->kappa_max) strength.push_back(std::abs(k));
  const FeatureLines lines = DetectFeatureLines(
      mesh->tri, RidgeVertices(mesh->tri, *field, 5.0, kMinRidgeContrast), strength, 4);
  auto crease_distance = [&](const Eigen::Vector3d& p) {
    const double radial = std::hypot(p.x(), p.y()) - body.rho;
    return std::min(std::hypot(radial, p.z() - body.top),
                    std::hypot(radial, body.body.Distance(p)));
  };
  double length = 0.0, worst = 0.0;
  for (auto e : mesh->tri.edges()) {
    if (!lines.edge[e.idx()]) continue;
    const Eigen::Vector3d a = ToEigen(mesh->tri.point(e.v0()));
    const Eigen::Vector3d b = ToEigen(mesh->tri.point(e.v1()));
    length += (a - b).norm();
    worst = std::max({worst, crease_distance(a), crease_distance(b)});
  }
  EXPECT_LE(worst, h);
  // Both creases are circles of radius rho (the lower one nearly so).
  EXPECT_GE(length, 0.9 * 2 * (2 * M_PI * body.rho)) << "h " << h;
  int junctions = 0;
  for (int c : lines.count) junctions += c >= 3;
  EXPECT_EQ(junctions, 0);
}

}  // namespace
}  // namespace meshseg::subdiv_internal
