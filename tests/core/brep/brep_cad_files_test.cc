// The whole pipeline with a STEP file on a gmsh tessellation of a real CAD
// part whose original STEP file is the true B-rep (shared/data/cad), where
// segmentation finds every face: the exported solid has the original's face
// count and volume, and each exported face lies on an original face's
// surface within 1e-4 of the part's size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"
#include "scratch_dir.h"
#include "shared_data_files.h"
#include "step_checks.h"

#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_Surface.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

namespace meshseg {
namespace {

constexpr double kVolumeTolerance = 1e-3;    // relative, the 0.1 %
constexpr double kSurfaceTolerance = 1e-4;   // x the part's bounding-box diagonal
constexpr double kSampleSpacing = 1.0 / 60;  // x the diagonal

double Diagonal(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return std::sqrt(box.SquareExtent());
}

// The surfaces of the faces of `shape`, in TopExp_Explorer order.
std::vector<Handle(ShapeAnalysis_Surface)> SurfacesOf(const TopoDS_Shape& shape) {
  std::vector<Handle(ShapeAnalysis_Surface)> out;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    out.push_back(new ShapeAnalysis_Surface(BRep_Tool::Surface(TopoDS::Face(it.Current()))));
  }
  return out;
}

class StepOfCadFile : public ::testing::TestWithParam<std::string> {};

// The pipeline on shared/data/`file` with a STEP file, every face built
// (failures reported), and the file read back; nullopt on an error.
struct Exported {
  int patch_count = 0;
  testing::StepModel model;
  testing::ShapeFacts facts;
  PipelineResult result;
};
std::optional<Exported> Export(const std::string& file, int solids = 1) {
  std::string name = file.substr(file.find_last_of('/') + 1);
  const std::string path = testing_files::ScratchPath(name + ".step");
  PipelineParams params;
  params.step_path = path;
  absl::StatusOr<PipelineResult> result = RunPipeline(testing::SharedData(file), params);
  EXPECT_TRUE(result.ok()) << result.status();
  if (!result.ok()) return std::nullopt;
  EXPECT_TRUE(result->brep.has_value()) << result->brep_error;
  if (!result->brep) return std::nullopt;
  for (const BrepFaceFailure& f : result->brep->failures) {
    ADD_FAILURE() << "region " << f.region << " patch " << f.patch << ": " << f.reason;
  }
  absl::StatusOr<testing::StepModel> model = testing::ReadStep(path);
  EXPECT_TRUE(model.ok()) << model.status();
  if (!model.ok()) return std::nullopt;
  Exported out{result->brep->patch_count, *std::move(model), {}, *std::move(result)};
  out.facts = testing::FactsOf(out.model.shape);
  EXPECT_TRUE(out.facts.valid);
  EXPECT_EQ(out.facts.solids, solids);
  EXPECT_EQ(out.facts.free_edges, 0);
  return out;
}

// The original STEP file beside a tessellation (its extension in either case).
std::string OriginalStep(const std::string& stem) {
  const std::string lower = testing::SharedData("cad/" + stem + ".step");
  return std::filesystem::exists(lower) ? lower : testing::SharedData("cad/" + stem + ".STEP");
}

// The unit to read an original in: its numbers as they stand ("M": no
// scaling) where shared/data/cad/SOURCES.md says the file declares metres but
// holds millimetre values, as the tessellations do; otherwise millimetres.
std::string OriginalUnit(const std::string& stem) {
  for (const char* mislabelled : {"whjdark_AAGNet__partA", "whjdark_AAGNet__partB"}) {
    if (stem == mislabelled) return "M";
  }
  return "";
}

// Faces of `shape` once faces that share an edge and lie on one surface are
// merged (a CAD system splits a full cylinder at seams into two half faces; a
// segmentation sees one surface): two adjacent faces are on one surface when
// every sample of each lies within `bound` of the other's surface.
int FacesOnDistinctSurfaces(const TopoDS_Shape& shape, double spacing, double bound) {
  TopTools_IndexedMapOfShape faces;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) faces.Add(it.Current());
  const testing::FaceSamples samples = testing::SampleFaces(shape, spacing);
  const std::vector<Handle(ShapeAnalysis_Surface)> surfaces = SurfacesOf(shape);
  std::vector<std::vector<gp_Pnt>> points_of(faces.Extent());
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const Eigen::Vector3d& p = samples.points[i];
    points_of[samples.face[i]].emplace_back(p.x(), p.y(), p.z());
  }
  const auto on_surface = [&](int face, int surface) {
    for (const gp_Pnt& p : points_of[face]) {
      surfaces[surface]->ValueOfUV(p, 0.1 * bound);
      if (surfaces[surface]->Gap() > bound) return false;
    }
    return true;
  };
  std::vector<int> group(faces.Extent());
  std::iota(group.begin(), group.end(), 0);
  const auto root = [&](int f) {
    while (group[f] != f) f = group[f] = group[group[f]];
    return f;
  };
  TopTools_IndexedDataMapOfShapeListOfShape faces_of_edge;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces_of_edge);
  int count = faces.Extent();
  for (int e = 1; e <= faces_of_edge.Extent(); ++e) {
    const TopTools_ListOfShape& around = faces_of_edge(e);
    if (around.Extent() != 2) continue;
    const int a = faces.FindIndex(around.First()) - 1, b = faces.FindIndex(around.Last()) - 1;
    if (a < 0 || b < 0 || root(a) == root(b)) continue;
    if (on_surface(a, b) && on_surface(b, a)) {
      group[root(a)] = root(b);
      --count;
    }
  }
  return count;
}

TEST_P(StepOfCadFile, MatchesTheOriginalBrep) {
  absl::StatusOr<testing::StepModel> original =
      testing::ReadStep(OriginalStep(GetParam()), OriginalUnit(GetParam()));
  ASSERT_TRUE(original.ok()) << original.status();
  const testing::ShapeFacts truth = testing::FactsOf(original->shape);
  ASSERT_GE(truth.solids, 1);
  // One solid per body of the original (a part may be several bodies).
  const std::optional<Exported> exported = Export("cad/" + GetParam() + ".obj", truth.solids);
  ASSERT_TRUE(exported.has_value());
  const testing::StepModel& ours = exported->model;
  const testing::ShapeFacts& facts = exported->facts;
  EXPECT_NEAR(facts.volume, truth.volume, kVolumeTolerance * truth.volume);
  const double diagonal = Diagonal(original->shape);
  const double bound = kSurfaceTolerance * diagonal;
  // The issue allows faces on one surface to be merged (and says so).
  EXPECT_EQ(facts.faces, FacesOnDistinctSurfaces(original->shape, kSampleSpacing * diagonal, bound))
      << "the original has " << truth.faces << " faces";

  // Each of our faces against the original face whose surface it is nearest
  // to over all its samples: its farthest sample from that surface.
  const testing::FaceSamples samples = testing::SampleFaces(ours.shape, kSampleSpacing * diagonal);
  EXPECT_EQ(samples.untessellated_faces, 0);
  const std::vector<Handle(ShapeAnalysis_Surface)> surfaces = SurfacesOf(original->shape);
  std::vector<std::vector<gp_Pnt>> points_of(facts.faces);
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const Eigen::Vector3d& p = samples.points[i];
    points_of[samples.face[i]].emplace_back(p.x(), p.y(), p.z());
  }
  for (int f = 0; f < facts.faces; ++f) {
    ASSERT_FALSE(points_of[f].empty()) << "face " << f << " has no sample";
    double best = std::numeric_limits<double>::infinity();
    for (const Handle(ShapeAnalysis_Surface) & s : surfaces) {
      double worst = 0.0;
      for (const gp_Pnt& p : points_of[f]) {
        s->ValueOfUV(p, 0.1 * bound);
        worst = std::max(worst, s->Gap());
        if (worst >= best) break;
      }
      best = std::min(best, worst);
    }
    EXPECT_LE(best, bound) << "face " << f << " (" << ours.face_names[f] << ") lies "
                           << best / diagonal << " x the diagonal off every original surface";
  }
}

// Every gmsh tessellation in shared/data/cad whose original STEP file is there.
INSTANTIATE_TEST_SUITE_P(
    Cad, StepOfCadFile,
    ::testing::Values("hducg_MFCAD__1-5-7-10-14-23", "hducg_MFCAD__3-7-11-13-14-23",
                      "hducg_MFCAD__7-10-11-11-14-23", "whjdark_AAGNet__partA",
                      "whjdark_AAGNet__partB", "whjdark_AAGNet__partC", "whjdark_AAGNet__test",
                      "mikedh_trimesh__base_interface_AP214",
                      "deep-geometry_abc-dataset__00000050_80d90bfdd2e74e709956122a_step_000"),
    testing::FileTestName);

// Parts whose regions are all analytic (the segmentation may merge small
// faces of the original, so face count and volume differ from the original
// STEP's): every face is built, the B-rep closes into one valid solid as the
// file reads back, and its volume is the mesh's within 1 %. partA has fitted
// edges whose points, drawn onto two nearly parallel surfaces, fall out of
// order along their intersection. cadnet 6 has 3 mm faces between 90 degree
// edges and plate_holes corner rounds and full-round edges a few long
// triangles span (l_avg 23 mm): short curves whose vertices lie on both their
// surfaces, real edges and not label zig-zags to contract; plate_holes' bores
// meet their countersinks with their seams a quarter turn apart.
constexpr double kMeshVolumeTolerance = 0.01;  // relative

class ClosedStepOfCadFile : public ::testing::TestWithParam<std::string> {};

TEST_P(ClosedStepOfCadFile, IsOneValidSolid) {
  const std::optional<Exported> exported = Export(GetParam());
  ASSERT_TRUE(exported.has_value());
  EXPECT_EQ(exported->facts.faces, exported->patch_count);
  const BrepReport& report = *exported->result.brep;
  EXPECT_TRUE(report.valid);
  EXPECT_TRUE(report.closed);
  EXPECT_EQ(report.solid_count, 1);
  EXPECT_NEAR(report.volume, exported->facts.volume, 1e-9 * std::abs(exported->facts.volume));
  absl::StatusOr<Mesh> mesh = ReadMesh(testing::SharedData(GetParam()));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const double mesh_volume = testing::EnclosedVolume(mesh->tri);
  EXPECT_NEAR(exported->facts.volume, mesh_volume, kMeshVolumeTolerance * mesh_volume);
}

INSTANTIATE_TEST_SUITE_P(Cad, ClosedStepOfCadFile,
                         ::testing::Values("cad/whjdark_AAGNet__partA.obj",
                                           "cad/xupeiwust_hierarchical-cadnet__6_true.obj",
                                           "plate_holes.stl"),
                         testing::FileTestName);

}  // namespace
}  // namespace meshseg
