// Segment() end to end on generated CT-like parts with ground truth.
#include "meshseg/segment.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "meshseg/curvature.h"
#include "generate/parts.h"
#include "meshseg/generate.h"
#include "segment/absorb_leftovers.h"
#include "segment_eval.h"

namespace meshseg {
namespace {

using testing::Evaluation;
using testing::PrimitiveScore;

constexpr int64_t kMinFaces = 200;       // primitives the type test applies to
constexpr double kMinCovered = 0.9;      // "found as one region"
constexpr double kMinAreaFraction = 0.95;
constexpr double kMaxRegionRatio = 1.2;

struct PartRun {
  GeneratedPart part;
  Segmentation seg;
  Evaluation eval;
};

// The noise seed of the generated parts: 7, or $MESHSEG_NOISE_SEED, so that
// scripts/segment_seed_matrix.sh can run these tests over other noise draws.
uint64_t NoiseSeed() {
  const char* seed = std::getenv("MESHSEG_NOISE_SEED");
  return seed != nullptr ? std::strtoull(seed, nullptr, 10) : 7;
}

// The voxel size of part `name` asked for (`voxel`, 0 for the part's own),
// times $MESHSEG_VOXEL_SCALE if set, so that the seed matrix can also run
// the parts at other resolutions (scripts/segment_seed_matrix.sh, VOXEL_SCALE).
double VoxelSize(const std::string& name, double voxel) {
  const char* scale = std::getenv("MESHSEG_VOXEL_SCALE");
  if (scale == nullptr) return voxel;
  if (voxel == 0.0) {
    const std::optional<generate_internal::PartSpec> spec = generate_internal::FindPart(name);
    EXPECT_TRUE(spec.has_value()) << name;
    if (spec) voxel = spec->default_voxel_size;
  }
  return voxel * std::strtod(scale, nullptr);
}

PartRun Segmented(const std::string& name, double voxel, double noise,
                  uint64_t seed = NoiseSeed()) {
  PartRun run;
  auto part =
      GeneratePart(name, {.voxel_size = VoxelSize(name, voxel), .noise = noise, .seed = seed});
  EXPECT_TRUE(part.ok()) << part.status();
  if (!part.ok()) return run;
  run.part = std::move(*part);
  auto field = EstimateCurvature(run.part.mesh);
  EXPECT_TRUE(field.ok()) << field.status();
  if (!field.ok()) return run;
  auto seg = Segment(run.part.mesh, *field);
  EXPECT_TRUE(seg.ok()) << seg.status();
  if (!seg.ok()) return run;
  run.seg = std::move(*seg);
  run.eval = testing::Evaluate(run.part, run.seg);
  return run;
}

// Parameter bounds, in multiples of the voxel size h and degrees.
struct Bounds {
  double cylinder_radius = 0.1;  // full and half cylinders
  double quarter_radius = 0.25;  // cylinders spanning <= a third of a turn
  double axis_deg = 0.5;
  double sphere_radius = 0.1;
  double cone_angle_deg = 0.5;
  double torus_radii = 0.2;
};

void ExpectTypesAndParameters(const PartRun& run, const Bounds& b, bool check_parameters) {
  const double h = run.part.voxel_size;
  for (const PrimitiveScore& s : run.eval.primitives) {
    if (s.faces < kMinFaces) continue;
    ASSERT_GE(s.region, 0) << s.name;
    EXPECT_GE(s.covered, kMinCovered) << s.name;
    for (const int r : s.regions) {
      EXPECT_EQ(run.seg.regions[r].type, s.true_type)
          << s.name << " region " << r << " is " << SurfaceTypeName(run.seg.regions[r].type);
    }
    const Region& region = run.seg.regions[s.region];
    if (!check_parameters || region.type != s.true_type) continue;
    const Surface& truth = run.part.primitives[s.primitive].surface;
    if (const auto* t = std::get_if<Cylinder>(&truth)) {
      const auto& c = std::get<Cylinder>(region.surface);
      const double tol = s.angular_span <= 1.0 / 3.0 ? b.quarter_radius : b.cylinder_radius;
      EXPECT_NEAR(c.radius, t->radius, tol * h) << s.name << " span " << s.angular_span;
      EXPECT_LE(testing::AxisAngleDeg(c.axis_direction, t->axis_direction), b.axis_deg) << s.name;
    } else if (const auto* t = std::get_if<Sphere>(&truth)) {
      EXPECT_NEAR(std::get<Sphere>(region.surface).radius, t->radius, b.sphere_radius * h) << s.name;
    } else if (const auto* t = std::get_if<Cone>(&truth)) {
      const auto& c = std::get<Cone>(region.surface);
      EXPECT_NEAR(c.half_angle * 180.0 / std::numbers::pi, t->half_angle * 180.0 / std::numbers::pi,
                  b.cone_angle_deg) << s.name;
      EXPECT_LE(testing::AxisAngleDeg(c.axis_direction, t->axis_direction), b.axis_deg) << s.name;
    } else if (const auto* t = std::get_if<Torus>(&truth)) {
      const auto& c = std::get<Torus>(region.surface);
      EXPECT_NEAR(c.major_radius, t->major_radius, b.torus_radii * h) << s.name;
      EXPECT_NEAR(c.minor_radius, t->minor_radius, b.torus_radii * h) << s.name;
    }
  }
}

void ExpectLabelsAndCount(const PartRun& run) {
  EXPECT_GE(run.eval.area_fraction, kMinAreaFraction);
  EXPECT_LE(run.eval.region_count, kMaxRegionRatio * run.eval.true_count);
  // B-rep-ready: a region is one piece of faces unless its primitive is
  // (test_piece's top, cut in two by the groove); no fragments.
  EXPECT_LE(run.eval.region_extra_pieces, run.eval.true_extra_pieces);
  // Every region's surface is of its type (a merge once kept a cone's
  // surface under the type torus).
  for (const Region& r : run.seg.regions) {
    EXPECT_EQ(TypeOf(r.surface), r.type) << "region " << r.id << " is " << SurfaceTypeName(r.type);
  }
}

class SegmentPart : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(SegmentPart, FindsEveryPrimitiveWithItsTypeAndParameters) {
  const auto& [name, voxel] = GetParam();
  for (const double noise : {0.0, 0.05}) {
    SCOPED_TRACE(name + " noise " + std::to_string(noise));
    const PartRun run = Segmented(name, voxel, noise);
    SCOPED_TRACE(::testing::Message() << run.eval);
    ExpectTypesAndParameters(run, Bounds{}, /*check_parameters=*/true);
    ExpectLabelsAndCount(run);
  }
}

// Draws other than seed 7 at 0.05 h, one per way the segmentation once
// went wrong at this noise (git log of this file has the history): a flat
// boss top beside a tangent round typed a spindle torus (plate_boss, 2),
// planes grown first from flat-looking seeds splitting a torus (torus_ring,
// 10), a countersink cone whose axis, fitted alone on its narrow band, was
// half a degree off its bore's (test_piece, 54), a fragment on a sphere's rim
// kept as a small curved face (sphere_cap, 26). The full 400-draw matrix
// (scripts/segment_seed_matrix.sh) is the measure; these keep each
// mechanism under test in CI.
class SegmentPartOtherSeed
    : public ::testing::TestWithParam<std::tuple<std::string, double, uint64_t>> {};

TEST_P(SegmentPartOtherSeed, FindsEveryPrimitiveWithItsTypeAndParameters) {
  const auto& [name, voxel, seed] = GetParam();
  const PartRun run = Segmented(name, voxel, 0.05, seed);
  SCOPED_TRACE(::testing::Message() << run.eval);
  ExpectTypesAndParameters(run, Bounds{}, /*check_parameters=*/true);
  ExpectLabelsAndCount(run);
}

INSTANTIATE_TEST_SUITE_P(Draws, SegmentPartOtherSeed,
                         ::testing::Values(std::tuple{std::string("plate_boss"), 0.0, uint64_t{2}},
                                           std::tuple{std::string("torus_ring"), 0.0, uint64_t{10}},
                                           std::tuple{std::string("test_piece"), 1.0, uint64_t{54}},
                                           std::tuple{std::string("sphere_cap"), 0.0, uint64_t{26}}),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_seed_" +
                                  std::to_string(std::get<2>(info.param));
                         });

// Noise 0.15 h (three times the nominal level): the same types and
// coverage, with parameter bounds loosened threefold, as the fits' errors
// scale with the noise: cylinder radius 0.3 h (quarter 0.75 h), axis 1.5 deg,
// sphere radius 0.3 h, cone half-angle 1.5 deg; torus radii 0.5 h. The
// quarter bound was 0.6 h until stop 18: rounded_prism's rounds scatter by
// about 0.25 h over draws (-0.53 to +0.46 h on seeds 1, 2, 3, 7) and 3 of
// 30 draws fell just outside it (-0.64 to -0.69 h) with the right types.
class SegmentPartHighNoise : public SegmentPart {};

void ExpectTypesAtHighNoise(const PartRun& run) {
  SCOPED_TRACE(::testing::Message()
               << run.eval << "noise " << run.part.noise << " estimated " << run.seg.estimates.noise_sigma
               << ", th_dis " << run.seg.estimates.distance_tolerance << ", th_nm "
               << run.seg.estimates.angle_tolerance_deg << " deg, l_avg "
               << run.seg.estimates.mean_edge_length);
  const Bounds loose{.cylinder_radius = 0.3,
                     .quarter_radius = 0.75,
                     .axis_deg = 1.5,
                     .sphere_radius = 0.3,
                     .cone_angle_deg = 1.5,
                     .torus_radii = 0.5};
  ExpectTypesAndParameters(run, loose, /*check_parameters=*/true);
  ExpectLabelsAndCount(run);
}

TEST_P(SegmentPartHighNoise, KeepsTypesAtHighNoise) {
  const auto& [name, voxel] = GetParam();
  ExpectTypesAtHighNoise(Segmented(name, voxel, 0.15));
}

// Draws other than seed 7 at 0.15 h, one per way the segmentation once
// went wrong at this noise (git log of this file has the 53 draws it
// listed): a round taken by a wide cylinder when the noise was
// overestimated (small_block, 3); a round fitted under its radius (19), or
// alone on part of its arc after the faces took its tangent rows (226), or
// left as two plane strips one cylinder fits better (288) (rounded_prism);
// a long cone grown as a sphere with a torus along its crease (8) and a
// chamfer fitted off its shaft's axis (82) (stepped_shaft); a countersink
// typed torus over the cone it is a limit of (47), a boss top absorbed
// into a sphere with a piece of its cone (261), a round in two narrow
// cylinders (69) or in two on one axis cut into pieces by the faces (372),
// a groove grown from two seeds left as two cylinders (107) (test_piece);
// a flat side grown as a cylinder of huge radius (92), and the edge round
// between the boss and its top grown over the top (120), fitted from its
// narrow band and dropped (152) or left bent over the top at a fixed point
// of the expansion (380) (plate_boss). The full 400-draw matrix
// (scripts/segment_seed_matrix.sh) is the measure; these keep each
// mechanism under test in CI.
class SegmentPartHighNoiseOtherSeed
    : public ::testing::TestWithParam<std::tuple<std::string, double, uint64_t>> {};

TEST_P(SegmentPartHighNoiseOtherSeed, KeepsTypesAtHighNoise) {
  const auto& [name, voxel, seed] = GetParam();
  ExpectTypesAtHighNoise(Segmented(name, voxel, 0.15, seed));
}

INSTANTIATE_TEST_SUITE_P(Draws, SegmentPartHighNoiseOtherSeed,
                         ::testing::Values(std::tuple{std::string("small_block"), 0.0, uint64_t{3}},
                                           std::tuple{std::string("rounded_prism"), 0.0, uint64_t{19}},
                                           std::tuple{std::string("rounded_prism"), 0.0, uint64_t{226}},
                                           std::tuple{std::string("rounded_prism"), 0.0, uint64_t{288}},
                                           std::tuple{std::string("stepped_shaft"), 0.0, uint64_t{8}},
                                           std::tuple{std::string("stepped_shaft"), 0.0, uint64_t{82}},
                                           std::tuple{std::string("test_piece"), 1.0, uint64_t{47}},
                                           std::tuple{std::string("test_piece"), 1.0, uint64_t{261}},
                                           std::tuple{std::string("test_piece"), 1.0, uint64_t{69}},
                                           std::tuple{std::string("test_piece"), 1.0, uint64_t{372}},
                                           std::tuple{std::string("test_piece"), 1.0, uint64_t{107}},
                                           std::tuple{std::string("plate_boss"), 0.0, uint64_t{92}},
                                           std::tuple{std::string("plate_boss"), 0.0, uint64_t{120}},
                                           std::tuple{std::string("plate_boss"), 0.0, uint64_t{152}},
                                           std::tuple{std::string("plate_boss"), 0.0, uint64_t{380}}),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_seed_" +
                                  std::to_string(std::get<2>(info.param));
                         });

// test_piece's boss top (a disc of radius 5 h, 183 faces) is under the 200
// faces the checks above ask for, but a flat top reported curved is wrong
// all the same: the region holding most of it must be a plane covering 90 %
// of it within 2 sigma. At 0.15 h it was once taken inside the boss cone
// after a release took it for a strip (seed 56), inside a cylinder with rows
// of the cone when a plane trial cut its first vertices before its fit had
// settled (seed 317), and flattened at the end from a sphere grown over the
// top and a ring of the cone (seed 190); git log of this file has the rest.
void ExpectBossTopIsAPlane(const PartRun& run) {
  SCOPED_TRACE(::testing::Message() << run.eval);
  const auto top =
      std::find_if(run.eval.primitives.begin(), run.eval.primitives.end(),
                   [](const testing::PrimitiveScore& p) { return p.name == "boss_top"; });
  ASSERT_NE(top, run.eval.primitives.end());
  ASSERT_GE(top->region, 0);
  const Region& region = run.seg.regions[top->region];
  EXPECT_EQ(region.type, SurfaceType::kPlane) << SurfaceTypeName(region.type);
  EXPECT_GE(top->covered, kMinCovered);
  // Without noise both are rounding error (1e-15).
  if (run.part.noise > 0.0) {
    EXPECT_LE(region.rms_distance, 2.0 * run.seg.estimates.noise_sigma);
  }
}

// At the noise seed (7, or $MESHSEG_NOISE_SEED: the seed matrix reports it
// as test_piece@0.15h-small).
class SegmentPartSmallFaces : public SegmentPart {};

TEST_P(SegmentPartSmallFaces, BossTopIsAPlaneAtHighNoise) {
  const auto& [name, voxel] = GetParam();
  ExpectBossTopIsAPlane(Segmented(name, voxel, 0.15));
}

INSTANTIATE_TEST_SUITE_P(Parts, SegmentPartSmallFaces,
                         ::testing::Values(std::tuple{std::string("test_piece"), 1.0}),
                         [](const auto& info) { return std::get<0>(info.param); });

class BossTopAtHighNoise : public ::testing::TestWithParam<uint64_t> {};

TEST_P(BossTopAtHighNoise, IsAPlaneRegion) {
  ExpectBossTopIsAPlane(Segmented("test_piece", 1.0, 0.15, GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Draws, BossTopAtHighNoise,
                         ::testing::Values(uint64_t{56}, uint64_t{317}, uint64_t{190}),
                         [](const auto& info) { return "seed_" + std::to_string(info.param); });

// Coarser than the part's voxel size (MESHSEG_VOXEL_SCALE runs the matrix
// so): the boss top falls under the size floor and, freed, bent the boss
// cone that took it, until stop 25. At 1.25 h and 0.15 h (seeds 1, 2, 4 of
// 1-4) the top was split off the cone and released as a narrow plane; the
// cone came out at 31.2 and 30.2 degrees (true 20.6) in seeds 2 and 4, and
// seed 1 lost the top. At 1.5 h and noise 0 it was released by size (41
// vertices), and the cone with it became a sphere. absorb_leftovers.h says
// what keeps it now.
class CoarserTestPiece : public ::testing::TestWithParam<uint64_t> {};

TEST_P(CoarserTestPiece, KeepsTypesAndTheBossTopAtHighNoiseAQuarterCoarser) {
  const PartRun run = Segmented("test_piece", 1.25, 0.15, GetParam());
  ExpectTypesAtHighNoise(run);
  ExpectBossTopIsAPlane(run);
}

INSTANTIATE_TEST_SUITE_P(Draws, CoarserTestPiece,
                         ::testing::Values(uint64_t{1}, uint64_t{2}, uint64_t{4}),
                         [](const auto& info) { return "seed_" + std::to_string(info.param); });

TEST(CoarserTestPieceNoNoise, FindsEveryPrimitiveHalfAgainAsCoarse) {
  const PartRun run = Segmented("test_piece", 1.5, 0.0);
  SCOPED_TRACE(::testing::Message() << run.eval);
  ExpectTypesAndParameters(run, Bounds{}, /*check_parameters=*/true);
  ExpectLabelsAndCount(run);
  ExpectBossTopIsAPlane(run);
}

INSTANTIATE_TEST_SUITE_P(Parts, SegmentPart,
                         ::testing::Values(std::tuple{std::string("test_piece"), 1.0},
                                           std::tuple{std::string("sphere_cap"), 0.0},
                                           std::tuple{std::string("torus_ring"), 0.0},
                                           std::tuple{std::string("blend_block"), 0.0},
                                           std::tuple{std::string("small_block"), 0.0},
                                           std::tuple{std::string("rounded_prism"), 0.0},
                                           std::tuple{std::string("plate_boss"), 0.0},
                                           std::tuple{std::string("stepped_shaft"), 0.0}),
                         [](const auto& info) { return std::get<0>(info.param); });

// All 8 parts pass with noise seed 7. Other seeds still fail some parts
// (scripts/segment_seed_matrix.sh lists which): at stop 24, 6 of the 6800
// (part, noise) pairs of seeds 1-400, all at 0.15 h (stepped_shaft's chamfer
// axis, seeds 82 and 208; rounded_prism's quarter-round radius, 226 and 235;
// test_piece's countersink, 382, and boss top, 398).
INSTANTIATE_TEST_SUITE_P(Parts, SegmentPartHighNoise,
                         ::testing::Values(std::tuple{std::string("test_piece"), 1.0},
                                           std::tuple{std::string("torus_ring"), 0.0},
                                           std::tuple{std::string("sphere_cap"), 0.0},
                                           std::tuple{std::string("blend_block"), 0.0},
                                           std::tuple{std::string("rounded_prism"), 0.0},
                                           std::tuple{std::string("plate_boss"), 0.0},
                                           std::tuple{std::string("small_block"), 0.0},
                                           std::tuple{std::string("stepped_shaft"), 0.0}),
                         [](const auto& info) { return std::get<0>(info.param); });

// The noise estimate that th_dis and th_nm derive from matches the noise
// the generator added, on the generated parts (the small block, with most of its
// vertices near an edge, was overestimated 1.8 times when the median of all
// local fit residuals was the estimate).
class NoiseEstimate : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(NoiseEstimate, MatchesTheAddedNoise) {
  constexpr double kRelativeError = 0.15;
  const auto& [name, relative_noise] = GetParam();
  auto part = GeneratePart(name, {.noise = relative_noise, .seed = NoiseSeed()});
  ASSERT_TRUE(part.ok()) << part.status();
  auto field = EstimateCurvature(part->mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  auto seg = Segment(part->mesh, *field);
  ASSERT_TRUE(seg.ok()) << seg.status();
  EXPECT_NEAR(seg->estimates.noise_sigma, part->noise, kRelativeError * part->noise);
}

INSTANTIATE_TEST_SUITE_P(Parts, NoiseEstimate,
                         ::testing::Combine(::testing::Values("sphere_cap", "torus_ring",
                                                              "blend_block", "small_block",
                                                              "rounded_prism", "plate_boss",
                                                              "stepped_shaft"),
                                            ::testing::Values(0.05, 0.15)),
                         [](const auto& info) {
                           return std::get<0>(info.param) +
                                  (std::get<1>(info.param) < 0.1 ? "_low" : "_high");
                         });

// No region of the result is under the size floor the stage releases
// regions at (kMinRegionVertices): steps after the last release used to
// shrink a plane strip on test_piece's groove at 0.15 h (seed 124) from 62
// vertices to 56, and it stayed, typed plane.
TEST(SegmentSizeFloor, NoRegionEndsUnderIt) {
  const PartRun run = Segmented("test_piece", 1.0, 0.15, /*seed=*/124);
  ASSERT_FALSE(run.seg.regions.empty());
  for (const Region& r : run.seg.regions) {
    EXPECT_GE(r.vertex_count, static_cast<int64_t>(segment_internal::kMinRegionVertices))
        << "region " << r.id << " " << SurfaceTypeName(r.type);
  }
}

// The same labels, types and surfaces with one TBB thread as with many.
TEST(SegmentDeterminism, OneThreadGivesTheSameResultAsMany) {
  const PartRun many = Segmented("plate_boss", 0.0, 0.05);
  PartRun one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = Segmented("plate_boss", 0.0, 0.05);
  }
  ASSERT_FALSE(many.seg.face_labels.empty());
  EXPECT_EQ(one.seg.face_labels, many.seg.face_labels);
  EXPECT_EQ(one.seg.vertex_labels, many.seg.vertex_labels);
  ASSERT_EQ(one.seg.regions.size(), many.seg.regions.size());
  for (std::size_t r = 0; r < one.seg.regions.size(); ++r) {
    EXPECT_EQ(one.seg.regions[r].type, many.seg.regions[r].type) << r;
    EXPECT_EQ(one.seg.regions[r].rms_distance, many.seg.regions[r].rms_distance) << r;
  }
}

// The mean edge length measured once by the caller (MeshStatistics) is the
// value Segment sums itself, so passing it gives the same segmentation bit
// for bit; a length that is not finite and > 0 is refused, named.
TEST(SegmentWithMeanEdgeLength, GivesTheSameResultAsMeasuringItAgain) {
  auto part = GeneratePart("plate_boss", {.noise = 0.05, .seed = 7});
  ASSERT_TRUE(part.ok()) << part.status();
  auto field = EstimateCurvature(part->mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  const absl::StatusOr<Segmentation> own = Segment(part->mesh, *field);
  const absl::StatusOr<Segmentation> given =
      Segment(part->mesh, *field, MeanEdgeLength(part->mesh.tri));
  ASSERT_TRUE(own.ok()) << own.status();
  ASSERT_TRUE(given.ok()) << given.status();
  ASSERT_FALSE(own->face_labels.empty());
  EXPECT_EQ(given->face_labels, own->face_labels);
  EXPECT_EQ(given->vertex_labels, own->vertex_labels);
  EXPECT_EQ(given->estimates.mean_edge_length, own->estimates.mean_edge_length);
  EXPECT_EQ(given->estimates.distance_tolerance, own->estimates.distance_tolerance);
  ASSERT_EQ(given->regions.size(), own->regions.size());
  for (std::size_t r = 0; r < own->regions.size(); ++r) {
    EXPECT_EQ(given->regions[r].type, own->regions[r].type) << r;
    EXPECT_EQ(given->regions[r].rms_distance, own->regions[r].rms_distance) << r;
  }
  for (const double bad : {0.0, -1.0, std::nan("")}) {
    const absl::StatusOr<Segmentation> refused = Segment(part->mesh, *field, bad);
    EXPECT_EQ(refused.status().code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_NE(refused.status().message().find("mean edge length"), std::string::npos)
        << refused.status();
  }
}

// A part where its CAD frame leaves it (tens of metres from the origin),
// turned, or in other units (micrometres, metres) gets the same regions with
// its surfaces moved and scaled alike: no threshold is absolute, and the
// fits keep their precision far from the origin.
struct Frame {
  std::string name;
  double scale = 1.0;
  Eigen::AngleAxisd turn{0.0, Eigen::Vector3d::UnitZ()};
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
};

void PrintTo(const Frame& frame, std::ostream* os) { *os << frame.name; }

class SegmentFrame : public ::testing::TestWithParam<Frame> {};

TEST_P(SegmentFrame, MovedTurnedOrScaledPartGetsTheSameRegions) {
  const Frame& frame = GetParam();
  const PartRun base = Segmented("plate_boss", 0.0, 0.05);
  ASSERT_FALSE(base.seg.regions.empty());
  const Eigen::Affine3d to =
      Eigen::Translation3d(frame.shift) * frame.turn * Eigen::Scaling(frame.scale);
  Mesh moved = base.part.mesh;
  for (const auto v : moved.tri.vertices()) {
    const auto& p = moved.tri.point(v);
    const Eigen::Vector3d q = to * Eigen::Vector3d(p[0], p[1], p[2]);
    moved.tri.set_point(v, TriMesh::Point(q.x(), q.y(), q.z()));
  }
  moved.tri.update_normals();
  const absl::StatusOr<CurvatureField> field = EstimateCurvature(moved);
  ASSERT_TRUE(field.ok()) << field.status();
  const absl::StatusOr<Segmentation> seg = Segment(moved, *field);
  ASSERT_TRUE(seg.ok()) << seg.status();

  // The fits differ in the last bits once turned; 1e-3 leaves them room.
  constexpr double kRelative = 1e-3;
  EXPECT_NEAR(seg->estimates.noise_sigma, frame.scale * base.seg.estimates.noise_sigma,
              kRelative * frame.scale * base.seg.estimates.noise_sigma);
  ASSERT_EQ(seg->regions.size(), base.seg.regions.size());
  std::size_t same = 0;
  for (std::size_t f = 0; f < seg->face_labels.size(); ++f) {
    same += seg->face_labels[f] == base.seg.face_labels[f];
  }
  EXPECT_EQ(same, base.seg.face_labels.size()) << "faces labelled alike";
  for (std::size_t r = 0; r < seg->regions.size(); ++r) {
    const Region& a = base.seg.regions[r];
    const Region& b = seg->regions[r];
    EXPECT_EQ(b.type, a.type) << r;
    EXPECT_NEAR(b.rms_distance, frame.scale * a.rms_distance,
                kRelative * frame.scale * a.rms_distance)
        << r;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Frames, SegmentFrame,
    ::testing::Values(Frame{.name = "far", .shift = Eigen::Vector3d(20000.0, -15000.0, 30000.0)},
                      Frame{.name = "turned",
                            .turn = Eigen::AngleAxisd(0.7, Eigen::Vector3d(2, -1, 3).normalized())},
                      Frame{.name = "micrometres", .scale = 1000.0},
                      Frame{.name = "metres", .scale = 0.001}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace meshseg
