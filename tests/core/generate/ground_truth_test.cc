// Face labels checked against analytic areas, distances and boundaries.
#include "generate/ground_truth.h"

#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "meshseg/generate.h"

namespace meshseg {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Vector3d Centroid(const TriMesh& mesh, TriMesh::FaceHandle f) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto v : mesh.fv_range(f)) c += ToEigen(mesh.point(v));
  return c / 3.0;
}

// Mesh area per primitive name.
std::map<std::string, double> AreaByPrimitive(const GeneratedPart& part) {
  std::map<std::string, double> area;
  const TriMesh& mesh = part.mesh.tri;
  for (const auto f : mesh.faces()) {
    const int p = part.face_primitive[f.idx()];
    if (p >= 0) area[part.primitives[p].name] += mesh.calc_face_area(f);
  }
  return area;
}

// Faces at a sharp edge cut the corner; their area goes to either side.
// Allowed error: this fraction of h times the primitive's boundary length.
constexpr double kBandTol = 0.5;

TEST(FacePrimitives, SmallBlockAreasMatchTheDrawing) {
  const auto part = GeneratePart("small_block");
  ASSERT_TRUE(part.ok()) << part.status();
  const double h = part->voxel_size;
  const auto area = AreaByPrimitive(*part);
  const double r_bore = 3.5, r_round = 3.0;
  EXPECT_NEAR(area.at("bore"), 2 * kPi * r_bore * 8, kBandTol * h * 4 * kPi * r_bore);
  EXPECT_NEAR(area.at("round"), kPi / 2 * r_round * 14, kBandTol * h * (28 + kPi * r_round));
  EXPECT_NEAR(area.at("top"), 17 * 14 - kPi * r_bore * r_bore,
              kBandTol * h * (2 * 17 + 28 + 2 * kPi * r_bore));
  EXPECT_NEAR(area.at("bottom"), 20 * 14 - kPi * r_bore * r_bore,
              kBandTol * h * (68 + 2 * kPi * r_bore));
}

// Fillets meet their neighbours tangentially; faces straddling a tangent
// line go to either side (measured: about 0.15 h times the line's length).
TEST(FacePrimitives, FilletAreasMatchTheDrawing) {
  constexpr double kChordRelTol = 0.01;
  constexpr double kTangentBandTol = 0.25;  // x h x tangent line length
  const auto plate = GeneratePart("plate_boss");
  ASSERT_TRUE(plate.ok()) << plate.status();
  // Quarter of the torus tube (R 14, r 4) facing the boss axis and the plate;
  // tangent to the boss at radius 10 and to the plate at radius 14.
  const double torus_area = 2 * kPi * 4 * (14 * kPi / 2 - 4);
  EXPECT_NEAR(AreaByPrimitive(*plate).at("boss_fillet"), torus_area,
              kChordRelTol * torus_area + kTangentBandTol * plate->voxel_size * 2 * kPi * 24);
  const auto block = GeneratePart("blend_block");
  ASSERT_TRUE(block.ok()) << block.status();
  // Quarter cylinder r 5, 30 long, tangent to two planes; sharp at its ends.
  const double fillet_area = kPi / 2 * 5 * 30;
  EXPECT_NEAR(AreaByPrimitive(*block).at("inner_fillet"), fillet_area,
              kChordRelTol * fillet_area + kTangentBandTol * block->voxel_size * 60 +
                  kBandTol * block->voxel_size * kPi * 5);
}

// Smooth closed surfaces: only the chord error of marching cubes remains.
TEST(FacePrimitives, TorusAndSphereCapAreasMatchWithinOnePercent) {
  constexpr double kRelTol = 0.01;
  const auto torus = GeneratePart("torus_ring");
  ASSERT_TRUE(torus.ok()) << torus.status();
  EXPECT_NEAR(AreaByPrimitive(*torus).at("torus"), 4 * kPi * kPi * 15 * 5,
              kRelTol * 4 * kPi * kPi * 15 * 5);
  const auto cap = GeneratePart("sphere_cap");
  ASSERT_TRUE(cap.ok()) << cap.status();
  const double cap_height = 20.0 - std::sqrt(20.0 * 20.0 - 15.0 * 15.0);
  const double cap_area = 2 * kPi * 20 * cap_height;
  EXPECT_NEAR(AreaByPrimitive(*cap).at("cap"), cap_area,
              kRelTol * cap_area + kBandTol * cap->voxel_size * 2 * kPi * 15);
}

// Every face lies close to the surface it is labelled with; away from
// boundaries only the chord error of the curved surfaces remains.
TEST(FacePrimitives, CentroidsLieNearTheirPrimitive) {
  constexpr double kAnyFaceTol = 0.5;      // x h
  constexpr double kInteriorFaceTol = 0.05;  // x h
  const auto part = GeneratePart("test_piece", {.voxel_size = 0.8});
  ASSERT_TRUE(part.ok()) << part.status();
  const double h = part->voxel_size;
  int interior = 0;
  for (const auto f : part->mesh.tri.faces()) {
    const int p = part->face_primitive[f.idx()];
    ASSERT_GE(p, 0);
    const double d = std::abs(SignedDistance(part->primitives[p].surface, Centroid(part->mesh.tri, f)));
    EXPECT_LT(d, kAnyFaceTol * h) << "face " << f.idx();
    if (!part->face_near_boundary[f.idx()]) {
      ++interior;
      EXPECT_LT(d, kInteriorFaceTol * h) << "face " << f.idx();
    }
  }
  EXPECT_GT(interior, static_cast<int>(part->mesh.tri.n_faces() / 2));
}

TEST(NearBoundary, TorusHasNoBoundary) {
  const auto part = GeneratePart("torus_ring", {.voxel_size = 0.8});
  ASSERT_TRUE(part.ok()) << part.status();
  for (uint8_t b : part->face_near_boundary) ASSERT_EQ(b, 0);
}

TEST(NearBoundary, MarksMixedFacesAndTheirNeighboursOnly) {
  const auto part = GeneratePart("small_block");
  ASSERT_TRUE(part.ok()) << part.status();
  const TriMesh& mesh = part->mesh.tri;
  const double h = part->voxel_size;
  int marked = 0;
  for (const auto f : mesh.faces()) {
    marked += part->face_near_boundary[f.idx()];
    std::set<int> labels;
    for (const auto v : mesh.fv_range(f)) labels.insert(part->vertex_primitive[v.idx()]);
    if (labels.size() > 1) {
      EXPECT_TRUE(part->face_near_boundary[f.idx()]) << "face " << f.idx();
    }
  }
  // The band is about 2 h wide along the edges (about 300 mm here).
  const double band_area = 300.0 * 2.0 * h;
  const double total_area = 2 * (20 * 14 + 20 * 8 + 14 * 8);
  const double expected = band_area / total_area * mesh.n_faces();
  EXPECT_GT(marked, 0.5 * expected);
  EXPECT_LT(marked, 2.0 * expected);
}

}  // namespace
}  // namespace meshseg
