// Every catalogue part: closed manifold mesh of the expected genus, every
// primitive with enough faces to be found, true parameters as designed.
#include "generate/parts.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <ostream>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "meshseg/generate.h"

namespace meshseg {
namespace {

struct Expected {
  const char* name;
  int genus;
  int primitives;
};

// GoogleTest prints a parameter without PrintTo as its bytes, pointers included,
// and ctest's test names carry that text: printing the name keeps the names
// the same from build to build.
void PrintTo(const Expected& c, std::ostream* os) { *os << c.name; }

// Through holes make the genus; the torus ring has one by itself.
constexpr Expected kParts[] = {
    {"small_block", 1, 8},   {"sphere_cap", 0, 4},    {"rounded_prism", 1, 15},
    {"torus_ring", 1, 1},    {"plate_boss", 2, 12},   {"stepped_shaft", 0, 8},
    {"blend_block", 0, 11},  {"test_piece", 1, 14},
};

// A primitive meant to be found has at least this many faces at default h.
constexpr int kMinFacesPerPrimitive = 200;

class PartsTest : public ::testing::TestWithParam<Expected> {};

TEST_P(PartsTest, ClosedManifoldOfExpectedGenusWithEnoughFacesPerPrimitive) {
  const Expected& e = GetParam();
  const auto part = GeneratePart(e.name);
  ASSERT_TRUE(part.ok()) << part.status();
  const MeshStats s = MeshStatistics(part->mesh);
  EXPECT_EQ(s.dropped_face_count, 0);
  EXPECT_EQ(s.boundary_edge_count, 0);
  EXPECT_EQ(s.non_manifold_edge_count, 0);
  EXPECT_EQ(s.non_manifold_vertex_count, 0);
  EXPECT_EQ(s.isolated_vertex_count, 0);
  EXPECT_EQ(s.component_count, 1);
  // Closed triangle mesh: E = 3F/2, so V - E + F = V - F/2 = 2 - 2g.
  EXPECT_EQ(2 * s.vertex_count - s.face_count, 2 * (2 - 2 * e.genus));
  ASSERT_EQ(static_cast<int>(part->primitives.size()), e.primitives);
  std::map<int, int> faces;
  for (int p : part->face_primitive) ++faces[p];
  EXPECT_EQ(faces.count(-1), 0u) << "faces without a primitive";
  for (const PrimitiveTruth& p : part->primitives) {
    EXPECT_GE(faces[p.id], kMinFacesPerPrimitive) << e.name << " " << p.name;
  }
  // Noise-free vertices lie on the surface of their primitive.
  constexpr double kOnSurfaceTol = 1e-9;  // x h
  double worst = 0.0;
  for (const auto v : part->mesh.tri.vertices()) {
    const int p = part->vertex_primitive[v.idx()];
    ASSERT_GE(p, 0);
    worst = std::max(worst, std::abs(SignedDistance(part->primitives[p].surface,
                                                    ToEigen(part->mesh.tri.point(v)))));
  }
  EXPECT_LT(worst, kOnSurfaceTol * part->voxel_size) << e.name;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, PartsTest, ::testing::ValuesIn(kParts),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(FindPart, KnowsEveryCatalogueNameAndNothingElse) {
  for (const std::string& name : generate_internal::CatalogueNames()) {
    EXPECT_TRUE(generate_internal::FindPart(name).has_value()) << name;
  }
  EXPECT_FALSE(generate_internal::FindPart("Test_Piece").has_value());
}

TEST(FindPart, TestPieceLargeIsTheTestPieceOnAFinerGrid) {
  const auto small = generate_internal::FindPart("test_piece");
  const auto large = generate_internal::FindPart("test_piece_large");
  ASSERT_TRUE(small && large);
  EXPECT_LT(large->default_voxel_size, 0.5 * small->default_voxel_size);
  ASSERT_EQ(small->primitives.size(), large->primitives.size());
}

// The tilt moves the part but keeps its dimensions.
TEST(FindPart, TestPieceHasTheDesignedRadiiAndAngles) {
  const auto spec = generate_internal::FindPart("test_piece");
  ASSERT_TRUE(spec);
  std::map<std::string, Surface> by_name;
  for (const PrimitiveTruth& p : spec->primitives) by_name[p.name] = p.surface;
  EXPECT_DOUBLE_EQ(std::get<Cylinder>(by_name["bore"]).radius, 8.0);
  EXPECT_DOUBLE_EQ(std::get<Cylinder>(by_name["groove"]).radius, 7.0);
  EXPECT_DOUBLE_EQ(std::get<Cylinder>(by_name["round_top_left"]).radius, 5.0);
  EXPECT_DOUBLE_EQ(std::get<Cone>(by_name["countersink"]).half_angle, std::numbers::pi / 4);
  // Bore and countersink share their axis; the groove is perpendicular.
  const Eigen::Vector3d bore_axis = std::get<Cylinder>(by_name["bore"]).axis_direction;
  EXPECT_NEAR(bore_axis.dot(std::get<Cone>(by_name["countersink"]).axis_direction), 1.0, 1e-12);
  EXPECT_NEAR(bore_axis.dot(std::get<Cylinder>(by_name["groove"]).axis_direction), 0.0, 1e-12);
  EXPECT_NEAR(bore_axis.dot(std::get<Plane>(by_name["top"]).normal), 1.0, 1e-12);
  // Not aligned with the grid.
  EXPECT_LT(std::abs(bore_axis.z()), 0.999);
}

}  // namespace
}  // namespace meshseg
