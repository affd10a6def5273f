// Over loopback: the result carries the mesh its ids index when the upload
// asks for it (UploadHeader.include_mesh), so an STL client can use curves
// and corners; the upload's length unit is checked at upload, echoed in the
// result and declared in the STEP file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "meshseg/pipeline.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/result_json.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_server::FreshDir;
using testing_server::TestServer;

Eigen::Vector3d Vertex(const v1::MeshGeometry& g, int v) {
  return {g.vertices(3 * v), g.vertices(3 * v + 1), g.vertices(3 * v + 2)};
}

// The labels of the returned triangles on each side of every mesh edge
// (the smaller vertex id first): face_labels through input_faces, or per
// triangle when there are no input faces (a reconstruction).
std::map<std::pair<int, int>, std::set<int>> EdgeLabels(const v1::SegmentationResult& r) {
  const v1::MeshGeometry& g = r.mesh_geometry();
  std::map<std::pair<int, int>, std::set<int>> labels;
  for (int t = 0; t < g.faces_size() / 3; ++t) {
    const int label = r.face_labels(g.input_faces_size() > 0 ? g.input_faces(t) : t);
    for (int i = 0; i < 3; ++i) {
      const int a = g.faces(3 * t + i), b = g.faces(3 * t + (i + 1) % 3);
      labels[{std::min(a, b), std::max(a, b)}].insert(label);
    }
  }
  return labels;
}

// Every curve runs along edges of the returned triangles, between faces of
// its two regions; a line curve's returned vertices lie on its line within
// its max_deviation; a corner's vertex ends its curves.
void ExpectCurvesIndexTheReturnedMesh(const v1::SegmentationResult& r) {
  const v1::MeshGeometry& g = r.mesh_geometry();
  const int vertex_count = g.vertices_size() / 3;
  const auto edges = EdgeLabels(r);
  ASSERT_GT(r.curves_size(), 0);
  for (const v1::BoundaryCurve& c : r.curves()) {
    ASSERT_GE(c.vertices_size(), 2) << "curve " << c.id();
    for (int i = 0; i < c.vertices_size(); ++i) {
      ASSERT_GE(c.vertices(i), 0);
      ASSERT_LT(c.vertices(i), vertex_count) << "curve " << c.id();
    }
    for (int i = 0; i + 1 < c.vertices_size(); ++i) {
      const int a = c.vertices(i), b = c.vertices(i + 1);
      const auto it = edges.find({std::min(a, b), std::max(a, b)});
      ASSERT_NE(it, edges.end()) << "curve " << c.id() << ": " << a << "-" << b << " is no edge";
      EXPECT_TRUE(it->second.contains(c.left_region())) << "curve " << c.id();
      EXPECT_TRUE(it->second.contains(c.right_region())) << "curve " << c.id();
    }
    if (c.geometry().type() == v1::CURVE_GEOMETRY_TYPE_LINE) {
      const Eigen::Vector3d p(c.geometry().point().x(), c.geometry().point().y(),
                              c.geometry().point().z());
      const Eigen::Vector3d d(c.geometry().direction().x(), c.geometry().direction().y(),
                              c.geometry().direction().z());
      for (int v : c.vertices()) {
        const Eigen::Vector3d q = Vertex(g, v) - p;
        EXPECT_LE((q - q.dot(d) * d).norm(), c.geometry().max_deviation() + 1e-9)
            << "curve " << c.id() << " vertex " << v;
      }
    }
  }
  for (const v1::Corner& k : r.corners()) {
    ASSERT_GE(k.vertex(), 0);
    ASSERT_LT(k.vertex(), vertex_count);
    for (int c : k.curves()) {
      const v1::BoundaryCurve& curve = r.curves(c);
      EXPECT_TRUE(curve.vertices(0) == k.vertex() ||
                  curve.vertices(curve.vertices_size() - 1) == k.vertex())
          << "corner " << k.id() << " is not an end of curve " << c;
    }
  }
}

// A box with sides split 4 x 4 as binary STL: the server welds the facets'
// corners, so the returned vertices are the welded ones and each returned
// triangle names the facet it came from (the same corners, as floats).
TEST(ResultMesh, IncludeMeshReturnsTheMeshCurveAndCornerIdsIndex) {
  const testing_files::TestMesh box = testing_files::SplitBox(4, {2.0, 1.5, 1.0});
  const std::string path = FreshDir("files") + "/box.stl";
  testing_files::WriteStlBinary(box, path);
  TestServer server;
  MeshsegClient client = server.Client();
  const absl::StatusOr<v1::SegmentationResult> r = client.Segment(path, {.include_mesh = true});
  ASSERT_TRUE(r.ok()) << r.status();
  ASSERT_TRUE(r->has_mesh_geometry());
  const v1::MeshGeometry& g = r->mesh_geometry();
  EXPECT_EQ(g.vertices_size(), 3 * r->mesh().vertex_count());
  EXPECT_EQ(r->mesh().vertex_count(), static_cast<int64_t>(box.v.size())) << "welded";
  ASSERT_EQ(g.faces_size(), 3 * r->mesh().mesh_face_count());
  ASSERT_EQ(g.input_faces_size(), g.faces_size() / 3);
  for (int t = 0; t < g.input_faces_size(); ++t) {
    const int facet = g.input_faces(t);
    ASSERT_GE(facet, 0);
    ASSERT_LT(facet, static_cast<int>(box.f.size()));
    std::set<std::array<float, 3>> returned, written;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d p = Vertex(g, g.faces(3 * t + i));
      returned.insert(
          {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
      const Eigen::Vector3d q = box.v[box.f[facet][i]];
      written.insert(
          {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z())});
    }
    EXPECT_EQ(returned, written) << "triangle " << t << " vs facet " << facet;
  }
  ASSERT_EQ(r->regions_size(), 6);
  EXPECT_EQ(r->curves_size(), 12);
  EXPECT_EQ(r->corners_size(), 8);
  ExpectCurvesIndexTheReturnedMesh(*r);
  // A box corner's vertex is at a corner of the box.
  for (const v1::Corner& k : r->corners()) {
    const Eigen::Vector3d p = Vertex(g, k.vertex());
    for (int axis = 0; axis < 3; ++axis) {
      const double size = std::array<double, 3>{2.0, 1.5, 1.0}[axis];
      EXPECT_TRUE(p[axis] == 0.0 || p[axis] == size) << "corner " << k.id() << " axis " << axis;
    }
  }

  // The same bytes as the offline pipeline asked for the mesh.
  PipelineParams params;
  params.include_mesh = true;
  const absl::StatusOr<PipelineResult> offline = RunPipeline(path, params);
  ASSERT_TRUE(offline.ok()) << offline.status();
  EXPECT_EQ(*ResultJson(*r), *ResultJson(ToProto(*offline)));

  // Not asked for: no mesh (results keep their size).
  const absl::StatusOr<v1::SegmentationResult> plain = client.Segment(path);
  ASSERT_TRUE(plain.ok()) << plain.status();
  EXPECT_FALSE(plain->has_mesh_geometry());
  EXPECT_EQ(plain->face_labels_size(), r->face_labels_size());
}

// A point cloud's mesh is reconstructed: the returned triangles are those
// face_labels counts (one label each), with no input faces.
// The box cloud has 32 points per edge: at 16 its smallest side is 7 mean
// edges of the reconstructed mesh wide, under the curvature stage's pass-2
// window (2 W2 = 10 edges), so the segmentation's noise estimate measures
// the edges (th_dis a third of the box's thickness) and one torus can take
// the whole surface, leaving no curve to check (point_cloud_test.cc checks
// that a box cloud this dense is six planes).
TEST(ResultMesh, IncludeMeshOfAPointCloudReturnsTheReconstructedMesh) {
  const std::string path = FreshDir("files") + "/box.xyz";
  testing_files::WriteXyz(testing_files::SplitBox(32, {2.0, 1.5, 1.0}), path);
  TestServer server;
  MeshsegClient client = server.Client();
  const absl::StatusOr<v1::SegmentationResult> r = client.Segment(path, {.include_mesh = true});
  ASSERT_TRUE(r.ok()) << r.status();
  const v1::MeshGeometry& g = r->mesh_geometry();
  EXPECT_EQ(g.vertices_size(), 3 * r->mesh().vertex_count());
  EXPECT_EQ(g.faces_size(), 3 * r->face_labels_size());
  EXPECT_EQ(g.input_faces_size(), 0);
  EXPECT_GT(r->point_labels_size(), 0);
  ExpectCurvesIndexTheReturnedMesh(*r);
}

// The length unit is echoed lowercase in the result and is the STEP file's
// unit when no step_unit is given.
TEST(ResultMesh, LengthUnitIsEchoedAndDeclaredInTheStepFile) {
  const std::string dir = FreshDir("files");
  const std::string path = dir + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(6, {2, 1, 0.5}), path);
  TestServer server;
  MeshsegClient client = server.Client();

  const absl::StatusOr<v1::SegmentationResult> unspecified = client.Segment(path);
  ASSERT_TRUE(unspecified.ok()) << unspecified.status();
  EXPECT_EQ(unspecified->length_unit(), "");

  v1::Job job;
  const absl::StatusOr<v1::SegmentationResult> inches =
      client.Segment(path, {.step = true, .length_unit = "IN"}, {}, &job);
  ASSERT_TRUE(inches.ok()) << inches.status();
  EXPECT_EQ(inches->length_unit(), "in");
  EXPECT_EQ(inches->brep().length_unit(), "in");
  ASSERT_GT(job.step_size(), 0) << inches->brep().error();
  const std::string step_path = dir + "/box.step";
  ASSERT_TRUE(client.SaveStep(job.job_id(), step_path).ok());
  EXPECT_THAT(testing_files::ReadText(step_path), HasSubstr("CONVERSION_BASED_UNIT('INCH'"));
}

// Unknown units, and a STEP unit that is not the input's, are refused at
// upload, naming the field, the value and the units allowed; no job is made.
TEST(ResultMesh, UnknownOrConflictingUnitsAreRefusedAtUpload) {
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), path);
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string units = "mm, cm, m, km, in, ft, mi, mil, um, uin";
  struct Case {
    UploadOptions options;
    std::vector<std::string> message;
  };
  const std::vector<Case> cases = {
      {{.step = true, .step_unit = "furlong"}, {"step_unit \"furlong\"", units}},
      {{.step_unit = "parsec"}, {"step_unit \"parsec\"", units}},
      {{.length_unit = "yd"}, {"length_unit \"yd\"", units}},
      {{.step = true, .step_unit = "in", .length_unit = "mm"},
       {"step_unit \"in\" is not length_unit \"mm\"", "unscaled"}},
  };
  for (const Case& c : cases) {
    const absl::StatusOr<v1::UploadResponse> up = client.Upload(path, c.options);
    ASSERT_EQ(up.status().code(), absl::StatusCode::kInvalidArgument) << up.status();
    for (const std::string& part : c.message) EXPECT_THAT(up.status().message(), HasSubstr(part));
  }
  const absl::StatusOr<std::vector<v1::Job>> jobs = client.ListJobs();
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  EXPECT_TRUE(jobs->empty());
}

}  // namespace
}  // namespace meshseg
