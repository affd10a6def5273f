// RunPipeline() on the real meshes of shared/data, labels per input face:
// the ABC CAD part against its per-face ground truth (.yml), the CAD
// exports that go through the remesh path (meshseg/remesh.h), and the one
// too fine to remesh.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "scratch_dir.h"
#include "shared_data_files.h"

#include "meshseg/fit.h"
#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"

namespace meshseg {
namespace {

// One B-rep patch of an ABC features file.
struct Patch {
  std::string type;  // "Plane", "Cylinder", ...
  double radius = 0.0;
  std::vector<int> faces;  // 0-based OBJ face indices
};

// The text of `key: [ ... ]` (without brackets) starting the search at `from`
// and not beyond `end`; empty if absent.
std::string ListAfter(const std::string& s, const std::string& key, std::size_t from,
                      std::size_t end) {
  const std::size_t k = s.find(key + ": [", from);
  if (k == std::string::npos || k >= end) return {};
  const std::size_t open = k + key.size() + 3;
  const std::size_t close = s.find(']', open);
  return s.substr(open, close - open);
}

// A small hand parser for the flow-style `surfaces: [{...}, {...}]` list of
// the ABC features YAML (no nested braces inside a surface).
std::vector<Patch> ReadPatches(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string s = buf.str();
  std::vector<Patch> patches;
  std::size_t pos = s.find("surfaces:");
  if (pos == std::string::npos) return patches;
  while ((pos = s.find('{', pos)) != std::string::npos) {
    const std::size_t end = s.find('}', pos);
    if (end == std::string::npos) break;
    Patch p;
    const std::size_t t = s.find("type: ", pos);
    if (t < end) p.type = s.substr(t + 6, s.find_first_of(",}", t) - t - 6);
    const std::size_t r = s.find("radius: ", pos);
    if (r < end) p.radius = std::stod(s.substr(r + 8, 40));
    std::stringstream faces(ListAfter(s, "face_indices", pos, end));
    std::string item;
    while (std::getline(faces, item, ',')) p.faces.push_back(std::stoi(item));
    patches.push_back(std::move(p));
    pos = end + 1;
  }
  return patches;
}

SurfaceType TypeOfName(const std::string& name) {
  if (name == "Plane") return SurfaceType::kPlane;
  if (name == "Cylinder") return SurfaceType::kCylinder;
  if (name == "Cone") return SurfaceType::kCone;
  if (name == "Sphere") return SurfaceType::kSphere;
  if (name == "Torus") return SurfaceType::kTorus;
  return SurfaceType::kFreeform;
}

// A patch counts as covered if one region holds at least this share of its
// faces; the faces along its rim may go to the neighbour.
constexpr double kMinPatchCover = 0.8;
constexpr double kRadiusTolerance = 0.01;  // relative, issue 3

// A coarse exact CAD export (l_avg 1.39 against radii 0.5-2; 37 % of the
// vertices sharp) goes through the exact-facet path (exact_facets.h): 25
// regions for the 24 patches, cylinder radii exact to 1e-6.
// Patch 22 is left out: a channel of r 0.5 (283 degrees of arc) whose mouth
// two flat faces (a key) close, tessellated with two facets. Its three rulings
// are 141.6 degrees apart around the axis, so the facets meet in a V of 38.4
// degrees, and the key's faces at 19.2 and 32.4 degrees. Three parallel lines
// lie on a cylinder whatever they are; a plane beside them tangent to that
// circle would say "round", but the key's faces cross it at 90 degrees (one
// contains the axis) and 77. Nothing tells it from a V-groove, and it comes
// out as two planes.
constexpr std::size_t kTwoFacetPatch = 22;

TEST(SegmentReal, AbcPartPatchesGetRegionsOfTheirType) {
  const std::vector<Patch> patches = ReadPatches(testing::SharedData("abc_00007974_5.yml"));
  ASSERT_EQ(patches.size(), 24u);  // SOURCES.md: 14 planes, 10 cylinders
  const absl::StatusOr<PipelineResult> seg =
      RunPipeline(testing::SharedData("abc_00007974_5.obj"));
  ASSERT_TRUE(seg.ok()) << seg.status();
  EXPECT_EQ(seg->estimates.path, SegmentationPath::kExactFacets);
  EXPECT_LE(seg->regions.size(), 26u);
  for (std::size_t i = 0; i < patches.size(); ++i) {
    if (i == kTwoFacetPatch) continue;
    const Patch& p = patches[i];
    std::map<int, int> count;
    for (const int f : p.faces) {
      ASSERT_LT(f, static_cast<int>(seg->face_labels.size()));
      ++count[seg->face_labels[f]];
    }
    int region = -1, best = 0;
    for (const auto& [r, n] : count) {
      if (n > best) best = n, region = r;
    }
    SCOPED_TRACE(::testing::Message() << "patch " << i << " " << p.type << " r " << p.radius
                                      << ", " << p.faces.size() << " faces, region " << region
                                      << " holds " << best);
    ASSERT_GE(region, 0);
    EXPECT_GE(best, kMinPatchCover * p.faces.size());
    const Region& reg = seg->regions[region];
    EXPECT_EQ(reg.type, TypeOfName(p.type)) << SurfaceTypeName(reg.type);
    if (const auto* c = std::get_if<Cylinder>(&reg.surface); c && p.type == "Cylinder") {
      EXPECT_NEAR(c->radius, p.radius, kRadiusTolerance * p.radius);
    }
  }
}

// tray_bottom_1002.stl is an exact CAD export, segmented facet by facet.
// Its truth, read off the file (circles through the wall facets' corners,
// all exact to 1e-4, and looked at in the coloured PLY): the top and the
// bottom, 8 octagon sides with 8 corner rounds of radius 5/32", a slot of 4
// sides and 4 rounds of 0.1", and 22 holes: 4 of radius 1.13, 4 of 1/16", 3
// of 1.899, 4 of 2.489, 3 of 3.264 and 4 of 4.564. Every round and hole is
// one exact cylinder along the plate's normal (y), whole although some of
// their facets carry a vertex on a chord (facet_on_surface.h, test 1);
// nothing else is curved, and the top and bottom fans are whole.
TEST(SegmentReal, TrayBottomIsSegmentedFacetByFacet) {
  const absl::StatusOr<PipelineResult> result =
      RunPipeline(testing::SharedData("tray_bottom_1002.stl"));
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->estimates.path, SegmentationPath::kExactFacets);
  EXPECT_EQ(result->remesh_face_count, 0);
  EXPECT_EQ(result->estimates.noise_sigma, 0.0);
  std::map<double, int> holes;  // radius rounded to 0.01 -> cylinders
  int planes = 0, plate_faces = 0;
  for (const Region& r : result->regions) {
    if (const auto* c = std::get_if<Cylinder>(&r.surface)) {
      EXPECT_EQ(r.type, SurfaceType::kCylinder);
      EXPECT_NEAR(std::abs(c->axis_direction.y()), 1.0, 1e-6) << "region " << r.id;
      EXPECT_LT(r.max_distance, 1e-3) << "region " << r.id;
      ++holes[std::round(100.0 * c->radius) / 100.0];
    } else {
      ASSERT_EQ(r.type, SurfaceType::kPlane) << "region " << r.id;
      ++planes;
      const auto& plane = std::get<Plane>(r.surface);
      if (std::abs(plane.normal.y()) > 1.0 - 1e-9) plate_faces += r.face_count;
    }
  }
  const std::map<double, int> truth = {{1.13, 4}, {1.59, 4}, {1.9, 3},  {2.49, 4},
                                       {2.54, 4}, {3.26, 3}, {3.97, 8}, {4.56, 4}};
  EXPECT_EQ(holes, truth);
  EXPECT_EQ(planes, 2 + 8 + 4);
  EXPECT_EQ(plate_faces, 2 * 1310);  // the top and bottom fans, whole
  EXPECT_EQ(result->surfaces.size(), result->regions.size());
}

// plate_holes.stl (SOURCES.md): five holes of r 3.3782, four under 82°
// countersinks, one under a counterbore of r 5.5563 whose floor is at
// z 6.35; an exact export, segmented facet by facet. Its vertical corners
// are rounds of r 25.4 (15-degree strips from z 6.35 to the top), its
// bottom edges rounds of r 6.35, blended at the corners by tori
// (19.05, 6.35): 29 surfaces in all, as the scan path found them on main.
void ExpectPlateHoles(const PipelineResult& result, double scale) {
  EXPECT_EQ(result.estimates.path, SegmentationPath::kExactFacets);
  EXPECT_EQ(result.regions.size(), 29u);
  int holes = 0, counterbores = 0, countersinks = 0, corner_rounds = 0, edge_rounds = 0, tori = 0;
  for (const Region& r : result.regions) {
    EXPECT_NE(r.type, SurfaceType::kFreeform) << "region " << r.id;
    if (const auto* c = std::get_if<Cylinder>(&r.surface);
        c != nullptr && std::abs(c->axis_direction.z()) > 1.0 - 1e-6) {
      if (std::abs(c->radius - 3.3782 * scale) < 0.01 * scale) ++holes;
      if (std::abs(c->radius - 5.5563 * scale) < 0.01 * scale) ++counterbores;
      if (std::abs(c->radius - 25.4 * scale) < 0.01 * scale) ++corner_rounds;
    } else if (c != nullptr && std::abs(c->radius - 6.35 * scale) < 0.01 * scale) {
      EXPECT_LT(std::abs(c->axis_direction.z()), 1e-6) << "region " << r.id;
      ++edge_rounds;
    }
    if (const auto* t = std::get_if<Torus>(&r.surface)) {
      EXPECT_NEAR(t->major_radius, 19.05 * scale, 0.01 * scale) << "region " << r.id;
      EXPECT_NEAR(t->minor_radius, 6.35 * scale, 0.01 * scale) << "region " << r.id;
      ++tori;
    }
    if (const auto* c = std::get_if<Cone>(&r.surface)) {
      EXPECT_NEAR(std::abs(c->axis_direction.z()), 1.0, 1e-6) << "region " << r.id;
      EXPECT_NEAR(c->half_angle * 180.0 / std::numbers::pi, 41.0, 0.1) << "region " << r.id;
      ++countersinks;
    }
    if (r.type != SurfaceType::kFreeform) {
      EXPECT_LT(r.rms_distance, 1e-4 * scale) << SurfaceTypeName(r.type) << " region " << r.id;
    }
  }
  EXPECT_EQ(holes, 5);
  EXPECT_EQ(counterbores, 1);
  EXPECT_EQ(countersinks, 4);
  EXPECT_EQ(corner_rounds, 4);
  EXPECT_EQ(edge_rounds, 4);
  EXPECT_EQ(tori, 4);
}

TEST(SegmentReal, PlateHolesAreCylindersUnderConesAndACounterbore) {
  const absl::StatusOr<PipelineResult> result = RunPipeline(testing::SharedData("plate_holes.stl"));
  ASSERT_TRUE(result.ok()) << result.status();
  ExpectPlateHoles(*result, 1.0);
}

// An exact CAD export's vertices lie on its surfaces, so no region lies on
// a neighbour's surface (within 1e-4 l_avg) unless the two should be
// one. On abc_00016513_gt.ply, before evenly stepped seeds went first
// (exact_facets.h), 8 spheres of 5-44 faces cut from the r 0.107 and 0.048
// cylinders did, to 1e-8, and before facets grew from their largest face,
// two planes of 35 faces did on the plane of 252 beside them, to 3e-8.
void ExpectNoRegionOnItsNeighbour(const PipelineResult& result, const std::string& file) {
  const absl::StatusOr<Mesh> mesh = ReadMesh(testing::SharedData(file));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(result.face_labels.size(), mesh->tri.n_faces());
  const double exact = 1e-4 * result.topology.mean_edge_length;
  for (const Adjacency& arc : result.topology.adjacency) {
    for (const auto& [piece, whole] :
         {std::pair{arc.region_a, arc.region_b}, std::pair{arc.region_b, arc.region_a}}) {
      // A FREEFORM region has no surface to lie on (its quadric is for display).
      if (result.regions[whole].type == SurfaceType::kFreeform) continue;
      double farthest = 0.0;
      for (const auto f : mesh->tri.faces()) {
        if (result.face_labels[f.idx()] != piece) continue;
        for (const auto v : mesh->tri.fv_range(f)) {
          const auto& p = mesh->tri.point(v);
          farthest =
              std::max(farthest, std::abs(SignedDistance(result.regions[whole].surface,
                                                         Eigen::Vector3d(p[0], p[1], p[2]))));
        }
      }
      EXPECT_GT(farthest, exact) << SurfaceTypeName(result.regions[piece].type) << " region "
                                 << piece << " lies on the surface of its neighbour " << whole;
    }
  }
}

// abc_00016513_gt.ply has no per-face truth, but the refit on the input
// vertices is exact where a region holds only its own faces (measured: all
// 12 cylinders at rms < 2e-7), and no region lies on its neighbour. The part
// is planes and cylinders only: no FREEFORM region (slivers between a plane
// and its cylinders once were, exact_facets.cc: JoinGapPieces).
void ExpectExactCylindersInOnePiece(const PipelineResult& result, const std::string& file) {
  int exact_cylinders = 0, planes = 0, freeform = 0;
  for (const Region& r : result.regions) {
    if (r.type == SurfaceType::kPlane) ++planes;
    if (r.type == SurfaceType::kCylinder && r.rms_distance < 1e-6) ++exact_cylinders;
    if (r.type == SurfaceType::kFreeform) ++freeform;
  }
  EXPECT_GE(exact_cylinders, 12);
  EXPECT_GE(planes, 4);
  EXPECT_EQ(freeform, 0);
  ExpectNoRegionOnItsNeighbour(result, file);
}

// Every input face gets a region; prints the region count and types and
// whether the mesh was remeshed (the numbers for the note).
class RealFile : public ::testing::TestWithParam<std::string> {};

TEST_P(RealFile, LabelsEveryInputFace) {
  const absl::StatusOr<PipelineResult> result = RunPipeline(testing::SharedData(GetParam()));
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_EQ(result->face_labels.size(), result->mesh.input_face_count);
  int64_t unlabelled = 0;
  for (const int label : result->face_labels) {
    if (label < 0 || label >= static_cast<int>(result->regions.size())) ++unlabelled;
  }
  EXPECT_EQ(unlabelled, result->mesh.dropped_face_count);
  std::map<std::string, int> types;
  int64_t faces = 0;
  for (const Region& r : result->regions) {
    ++types[SurfaceTypeName(r.type)];
    faces += r.face_count;
    EXPECT_GT(r.face_count, 0) << "region " << r.id;
  }
  EXPECT_EQ(faces, result->mesh.face_count);
  std::string summary;
  for (const auto& [t, n] : types) summary += " " + t + " " + std::to_string(n);
  std::printf("%s: %zu regions:%s (remeshed to %lld faces at %.4g)\n", GetParam().c_str(),
              result->regions.size(), summary.c_str(),
              static_cast<long long>(result->remesh_face_count), result->remesh_edge_length);
  if (GetParam() == "abc_00016513_gt.ply") ExpectExactCylindersInOnePiece(*result, GetParam());
  if (GetParam() == "tray_bottom_1002.stl" || GetParam() == "abc_00007974_5.obj") {
    ExpectNoRegionOnItsNeighbour(*result, GetParam());
  }
}

// The CAD exports of shared/data with long thin triangles are CAD-like
// (remesh.h: Assess; they are segmented facet by facet, being exact).
TEST_P(RealFile, CadExportsAreCadLike) {
  const absl::StatusOr<Mesh> mesh = ReadMesh(testing::SharedData(GetParam()));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const bool cad_export = GetParam() == "plate_holes.stl" || GetParam() == "tray_bottom_1002.stl" ||
                          GetParam() == "abc_00016513_gt.ply";
  EXPECT_EQ(Assess(*mesh).cad_like, cad_export);
}

INSTANTIATE_TEST_SUITE_P(Files, RealFile, testing::SharedMeshFiles(), testing::FileTestName);

// A real file in another frame: every vertex scaled by `scale` and moved by
// `shift`, and with `jitter_seed` > 0 each coordinate also multiplied by
// 1 + u 1e-12 (u uniform in [-1, 1]: another exporter's rounding), written as
// PLY (doubles) to the scratch folder.
std::string MovedCopy(const std::string& name, double scale, const Eigen::Vector3d& shift,
                      uint64_t jitter_seed = 0) {
  absl::StatusOr<Mesh> mesh = ReadMesh(testing::SharedData(name));
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  if (!mesh.ok()) return "";
  std::mt19937_64 rng(jitter_seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const auto v : mesh->tri.vertices()) {
    const auto& p = mesh->tri.point(v);
    Eigen::Vector3d q = scale * Eigen::Vector3d(p[0], p[1], p[2]) + shift;
    if (jitter_seed > 0) {
      for (int k = 0; k < 3; ++k) q[k] *= 1.0 + 1e-12 * unit(rng);
    }
    mesh->tri.set_point(v, TriMesh::Point(q.x(), q.y(), q.z()));
  }
  const std::string path = testing_files::ScratchPath(name + ".moved.ply");
  EXPECT_TRUE(WriteMesh(mesh->tri, path).ok());
  return path;
}

struct FrameCase {
  const char* file;
  const char* frame;
  double scale = 1.0;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
};

void PrintTo(const FrameCase& c, std::ostream* os) { *os << c.file << " " << c.frame; }

// CAD exports read in another unit or frame get the same regions: the last
// bits of the coordinates change (x 1000 is not exact in binary), and no
// decision may hang on them. (tray_bottom_1002.stl in micrometres once got
// a slot side as a 46 mm cylinder; exact_facets.h.)
class RealFileFrame : public ::testing::TestWithParam<FrameCase> {};

TEST_P(RealFileFrame, GetsTheSameRegions) {
  const FrameCase& c = GetParam();
  const absl::StatusOr<PipelineResult> as_read = RunPipeline(testing::SharedData(c.file));
  ASSERT_TRUE(as_read.ok()) << as_read.status();
  const absl::StatusOr<PipelineResult> moved = RunPipeline(MovedCopy(c.file, c.scale, c.shift));
  ASSERT_TRUE(moved.ok()) << moved.status();
  EXPECT_EQ(moved->face_labels, as_read->face_labels);
  ASSERT_EQ(moved->regions.size(), as_read->regions.size());
  for (std::size_t r = 0; r < moved->regions.size(); ++r) {
    EXPECT_EQ(moved->regions[r].type, as_read->regions[r].type) << "region " << r;
  }
}

INSTANTIATE_TEST_SUITE_P(Frames, RealFileFrame,
                         ::testing::Values(FrameCase{"tray_bottom_1002.stl", "micrometres", 1000.0},
                                           FrameCase{"tray_bottom_1002.stl", "metres", 0.001},
                                           FrameCase{"abc_00007974_5.obj", "metres", 0.001},
                                           FrameCase{"abc_00007974_5.obj", "far", 1.0,
                                                     Eigen::Vector3d(20000.0, -15000.0, 30000.0)},
                                           FrameCase{"abc_00016513_gt.ply", "micrometres", 1000.0}),
                         [](const auto& info) {
                           return testing::FileTestName(
                                      {std::string(info.param.file), info.index}) +
                                  "_" + info.param.frame;
                         });

// plate_holes.stl with 1e-12 relative jitter on every coordinate (another
// exporter's rounding): the same holes and countersinks, every analytic
// region exact on the input's vertices.
class PlateHolesJittered : public ::testing::TestWithParam<uint64_t> {};

TEST_P(PlateHolesJittered, HolesAndCountersinksAreFound) {
  const absl::StatusOr<PipelineResult> result =
      RunPipeline(MovedCopy("plate_holes.stl", 1.0, Eigen::Vector3d::Zero(), GetParam()));
  ASSERT_TRUE(result.ok()) << result.status();
  ExpectPlateHoles(*result, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Draws, PlateHolesJittered, ::testing::Range<uint64_t>(1, 4));

// The same in micrometres and in metres.
class PlateHolesScaled : public ::testing::TestWithParam<double> {};

TEST_P(PlateHolesScaled, HolesAndCountersinksAreFound) {
  const absl::StatusOr<PipelineResult> result =
      RunPipeline(MovedCopy("plate_holes.stl", GetParam(), Eigen::Vector3d::Zero()));
  ASSERT_TRUE(result.ok()) << result.status();
  ExpectPlateHoles(*result, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Units, PlateHolesScaled, ::testing::Values(1000.0, 0.001),
                         [](const auto& info) {
                           return info.param > 1.0 ? std::string("micrometres")
                                                   : std::string("metres");
                         });

}  // namespace
}  // namespace meshseg
