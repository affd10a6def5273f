// Segment() on the real meshes of shared/data as read (no remeshing): every
// mesh without error. The ABC part against its ground truth, and CAD inputs
// through the remesh path, are in tests/core/pipeline/real_files_test.cc.
#include <cstdio>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "shared_data_files.h"

#include "meshseg/curvature.h"
#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg {
namespace {

class SegmentRealFile : public ::testing::TestWithParam<std::string> {};

// Every valid face gets a region; prints the region count and types (the
// numbers for the note).
TEST_P(SegmentRealFile, LabelsEveryFace) {
  const absl::StatusOr<Mesh> mesh = ReadMesh(testing::SharedData(GetParam()));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const auto field = EstimateCurvature(*mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  const auto seg = Segment(*mesh, *field);
  ASSERT_TRUE(seg.ok()) << seg.status();
  ASSERT_EQ(seg->face_labels.size(), mesh->tri.n_faces());
  int64_t unlabelled = 0;
  for (const int label : seg->face_labels) {
    if (label < 0 || label >= static_cast<int>(seg->regions.size())) ++unlabelled;
  }
  EXPECT_EQ(unlabelled, 0);
  std::map<std::string, int> types;
  for (const Region& r : seg->regions) ++types[SurfaceTypeName(r.type)];
  std::string summary;
  for (const auto& [t, n] : types) summary += " " + t + " " + std::to_string(n);
  const SegmentEstimates& e = seg->estimates;
  std::printf("%s: %zu regions:%s (l_avg %.4g, sigma %.3g, th_dis %.3g, th_nm %.3g deg)\n",
              GetParam().c_str(), seg->regions.size(), summary.c_str(), e.mean_edge_length,
              e.noise_sigma, e.distance_tolerance, e.angle_tolerance_deg);
  EXPECT_FALSE(seg->regions.empty());
}

INSTANTIATE_TEST_SUITE_P(Files, SegmentRealFile, testing::SharedMeshFiles(), testing::FileTestName);

}  // namespace
}  // namespace meshseg
