// Reconstruction of point clouds sampled from the generated test parts, whose
// exact primitives are the true surface (part_clouds.h): issue 6's hard case
// (5 % uniform outliers in the bounding box, Gaussian noise 0.2 × spacing, a
// missing patch), with and without normals. (The sign of f alone no longer
// leaves bubbles on these clouds once the outlier flags keep less of the
// outliers; the graph cut's bubbles test is Reconstruct.GraphCutRemoves-
// BubblesThatTheSignOfFKeeps, on ghost sheets.)
#include <cmath>
#include <ostream>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "clouds.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "meshseg/reconstruct.h"
#include "part_clouds.h"
#include "scratch_dir.h"

namespace meshseg {
namespace {

constexpr double kDistanceTol = 0.5;       // × spacing h, vertex to true surface (issue 6)
constexpr double kMinNearFraction = 0.95;  // of the mesh vertices (issue 6)
// Without normals the fraction within kDistanceTol may be lower by this much,
// as in Reconstruct.PointsWithoutNormalsDoAsWellAsWithNormals.
constexpr double kMaxLossWithoutNormals = 0.03;
constexpr double kHoleRadius = 5.0;  // × h, as the analytic hard cases

struct PartCase {
  const char* part;  // generated at its default voxel size
  int points;        // surface samples; h = sqrt(area / points)
  const char* hole;  // primitive whose centre loses a patch of kHoleRadius
};

// GoogleTest prints a parameter without PrintTo as its bytes, pointers included,
// and ctest's test names carry that text: printing the part keeps the names
// the same from build to build.
void PrintTo(const PartCase& c, std::ostream* os) { *os << c.part; }

// h ≈ 0.96, 0.62 and 0.86 mm, about 1.7 voxels of the generated meshes, which
// serve only to pick the sampled faces and to locate the primitives.
constexpr PartCase kTestPiece{"test_piece", 20000, "front"};
constexpr PartCase kSteppedShaft{"stepped_shaft", 12000, "cylinder_8"};
constexpr PartCase kPlateBoss{"plate_boss", 15000, "boss"};

struct HardCloud {
  test::Shape shape;
  double h = 0.0;
  PointCloud cloud;
};

absl::StatusOr<HardCloud> MakeHardCloud(const PartCase& c, bool normals) {
  const absl::StatusOr<GeneratedPart> part = GeneratePart(c.part);
  if (!part.ok()) return part.status();
  HardCloud out;
  out.shape = test::PartShape(*part);
  out.h = test::Spacing(out.shape, c.points);
  out.cloud = test::MakeCloud(out.shape, {.points = c.points,
                                          .noise = 0.2,
                                          .outliers = 0.05,
                                          .hole_radius = kHoleRadius * out.h,
                                          .hole_center = test::PrimitiveCenter(*part, c.hole),
                                          .normals = normals});
  out.cloud.name = std::string(c.part) + (normals ? "_normals.xyz" : "_points.xyz");
  return out;
}

// Watertight, manifold, exactly one component (issue 6); and so it stays
// when written and read back: no triangle is degenerate enough for ReadMesh
// to drop (coincident vertices once made 5 such, and 11 boundary edges).
void ExpectClosedManifoldSingle(const TriMesh& m, const std::string& name) {
  ASSERT_GT(m.n_faces(), 0u);
  EXPECT_EQ(test::BoundaryEdgeCount(m), 0);
  EXPECT_EQ(test::NonManifoldVertexCount(m), 0);
  EXPECT_EQ(test::ComponentCount(m), 1);
  const std::string path = testing_files::ScratchPath(name + ".ply");
  ASSERT_TRUE(WriteMesh(m, path).ok());
  const absl::StatusOr<Mesh> back = ReadMesh(path);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->tri.n_faces(), m.n_faces());
  EXPECT_EQ(test::BoundaryEdgeCount(back->tri), 0);
}

class ReconstructGeneratedParts : public ::testing::TestWithParam<PartCase> {};

TEST_P(ReconstructGeneratedParts, HardCloudIsWatertightManifoldAndOneComponent) {
  for (const bool normals : {true, false}) {
    SCOPED_TRACE(normals ? "with normals" : "without normals");
    const absl::StatusOr<HardCloud> c = MakeHardCloud(GetParam(), normals);
    ASSERT_TRUE(c.ok()) << c.status();
    const auto r = Reconstruct(c->cloud);
    ASSERT_TRUE(r.ok()) << r.status();
    EXPECT_EQ(r->stats.normals_estimated, !normals);
    ExpectClosedManifoldSingle(r->mesh.tri, c->cloud.name);
  }
}

// Points without normals reconstruct as well as with them (issue 6): the
// fraction within kDistanceTol × h drops by at most kMaxLossWithoutNormals.
// (Closed, manifold and one component without normals: the test above.)
TEST_P(ReconstructGeneratedParts, WithoutNormalsIsAsAccurateAsWithNormals) {
  const absl::StatusOr<HardCloud> with = MakeHardCloud(GetParam(), true);
  const absl::StatusOr<HardCloud> without = MakeHardCloud(GetParam(), false);
  ASSERT_TRUE(with.ok()) << with.status();
  ASSERT_TRUE(without.ok()) << without.status();
  const auto a = Reconstruct(with->cloud);
  const auto b = Reconstruct(without->cloud);
  ASSERT_TRUE(a.ok()) << a.status();
  ASSERT_TRUE(b.ok()) << b.status();
  const double tol = kDistanceTol * with->h;
  const double near_with = test::FractionWithin(a->mesh.tri, with->shape, tol);
  const double near_without = test::FractionWithin(b->mesh.tri, without->shape, tol);
  EXPECT_GE(near_without, near_with - kMaxLossWithoutNormals);
  RecordProperty("near_fraction_with_normals", std::to_string(near_with));
  RecordProperty("near_fraction_without_normals", std::to_string(near_without));
}

INSTANTIATE_TEST_SUITE_P(Parts, ReconstructGeneratedParts,
                         ::testing::Values(kTestPiece, kSteppedShaft, kPlateBoss),
                         [](const ::testing::TestParamInfo<PartCase>& info) {
                           return std::string(info.param.part);
                         });

// A uniform sample of test_piece's surface (100 000 points, Gaussian noise
// of 0.1 nominal spacing along the normal, as `meshseg generate
// --surface-points 100000 --scan-noise 0.1 --seed 1` writes it) once came
// out as two closed components: the part, and a shell of 202 faces (6 682
// once refined) just under its left face, at its corner with the bottom and
// back faces. The cut had turned outside the row of shallow vertices (f
// 0.1 to 0.4 h) that joined the solid beneath that corner to the rest, and
// the piece, resolved by its own points (f up to 7 h), was kept as a solid
// of its own (reconstruct/severed_solid.h). Without the refinement
// and the later steps, which do not make or join components, the labels
// alone decide it.
TEST(ReconstructGeneratedParts, AUniformSampleHasNoSecondShellUnderAFace) {
  const absl::StatusOr<GeneratedPart> part = GeneratePart("test_piece");
  ASSERT_TRUE(part.ok()) << part.status();
  constexpr int kCount = 100000;
  constexpr uint64_t kSeed = 1;
  const SurfaceSamples samples = SampleSurface(*part, kCount, kSeed);
  double area = 0.0;
  for (const auto f : part->mesh.tri.faces()) area += part->mesh.tri.calc_face_area(f);
  std::mt19937_64 rng(kSeed + 1);
  std::normal_distribution<double> gauss(0.0, 0.1 * std::sqrt(area / kCount));
  PointCloud cloud;
  cloud.name = "test_piece_uniform.xyz";
  cloud.points = samples.points;
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    cloud.points[i] += gauss(rng) * samples.normals[i];
  }
  const auto r = Reconstruct(
      cloud, {.refine_edge_length = 0, .support_spacings = 0, .handle_spacings = 0});
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_EQ(test::ComponentCount(r->mesh.tri), 1);
  EXPECT_EQ(test::BoundaryEdgeCount(r->mesh.tri), 0);
}

// Fraction of the mesh vertices of the hard cloud's reconstruction within
// kDistanceTol × h of the true surface, with and without normals.
void ExpectNearTrueSurface(const PartCase& part) {
  for (const bool normals : {true, false}) {
    const absl::StatusOr<HardCloud> c = MakeHardCloud(part, normals);
    ASSERT_TRUE(c.ok()) << c.status();
    const auto r = Reconstruct(c->cloud);
    ASSERT_TRUE(r.ok()) << r.status();
    const double near = test::FractionWithin(r->mesh.tri, c->shape, kDistanceTol * c->h);
    EXPECT_GE(near, kMinNearFraction)
        << c->cloud.name << ": " << r->mesh.tri.n_vertices() << " vertices, h " << c->h;
    ::testing::Test::RecordProperty(
        normals ? "near_fraction_with_normals" : "near_fraction_without_normals",
        std::to_string(near));
  }
}

// Measured (with / without normals, fraction within 0.5 h): stepped shaft
// 0.981 / 0.979, test piece 0.976 / 0.977, plate_boss 0.972 / 0.971.
// Before the smoothing weighted its umbrella by 1/|e| (smoothing.h) the test
// piece and plate_boss gave 0.945 and 0.944: equal weights let the long edges
// that join a flat face's vertex to the far side of the plate or round an
// edge drag it up to 5 h into the part.
TEST(ReconstructGeneratedPart, SteppedShaftHardCloudIsWithinHalfSpacingOfTheTrueSurface) {
  ExpectNearTrueSurface(kSteppedShaft);
}

TEST(ReconstructGeneratedPart, TestPieceHardCloudIsWithinHalfSpacingOfTheTrueSurface) {
  ExpectNearTrueSurface(kTestPiece);
}

TEST(ReconstructGeneratedPart, PlateBossHardCloudIsWithinHalfSpacingOfTheTrueSurface) {
  ExpectNearTrueSurface(kPlateBoss);
}

}  // namespace
}  // namespace meshseg
