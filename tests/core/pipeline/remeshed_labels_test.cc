#include "pipeline/remeshed_labels.h"

#include <vector>

#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace meshseg::pipeline_internal {
namespace {

using ::testing::ElementsAre;

// Two unit squares side by side in z = 0, each of two triangles:
// faces 0, 1 cover x in [0, 1], faces 2, 3 cover x in [1, 2].
TriMesh TwoSquares(double x0) {
  TriMesh m;
  std::vector<TriMesh::VertexHandle> v;
  for (int i = 0; i < 3; ++i) {
    v.push_back(m.add_vertex({x0 + i, 0.0, 0.0}));
    v.push_back(m.add_vertex({x0 + i, 1.0, 0.0}));
  }
  for (int i = 0; i < 2; ++i) {
    m.add_face(v[2 * i], v[2 * i + 2], v[2 * i + 3]);
    m.add_face(v[2 * i], v[2 * i + 3], v[2 * i + 1]);
  }
  return m;
}

TEST(TransferFaceLabels, EachFaceTakesTheLabelOfTheSurfaceUnderIt) {
  const TriMesh fine = TwoSquares(0.0);
  const TriMesh coarse = TwoSquares(0.0);
  EXPECT_THAT(TransferFaceLabels(fine, std::vector<int>{4, 4, 9, 9}, coarse),
              ElementsAre(4, 4, 9, 9));
}

TEST(TransferFaceLabels, MajorityOfTheFourSamplesWins) {
  // The original's faces straddle the remesh's label change at x = 1.2:
  // original face 2 (x in [1.2, 2.2]... shifted by 0.2) has its centroid and
  // most samples right of it.
  const TriMesh fine = TwoSquares(0.0);
  const TriMesh shifted = TwoSquares(0.2);
  const std::vector<int> labels = TransferFaceLabels(fine, std::vector<int>{4, 4, 9, 9}, shifted);
  EXPECT_EQ(labels[0], 4);
  EXPECT_EQ(labels[2], 9);
}

TEST(VertexLabelsFromFaces, MostFacesWinAndTiesGoToTheSmallerLabel) {
  const TriMesh m = TwoSquares(0.0);
  // Vertex 0 touches faces 0, 1; vertex 2 (x = 1, y = 0) faces 0, 2, 3.
  const std::vector<int> labels = VertexLabelsFromFaces(m, std::vector<int>{5, 3, 7, 7});
  EXPECT_EQ(labels[0], 3);  // tie 3 / 5
  EXPECT_EQ(labels[2], 7);
  EXPECT_EQ(labels[4], 7);
}

TEST(CompactRegions, DropsRegionsWithoutFacesAndRenumbers) {
  std::vector<Region> regions(4);
  for (int i = 0; i < 4; ++i) regions[i].id = i;
  regions[3].area = 42.0;
  std::vector<int> faces = {3, 3, 1, -1};
  std::vector<int> vertices = {3, 1, 2, -1};
  CompactRegions(&faces, &vertices, &regions);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].id, 0);
  EXPECT_EQ(regions[0].face_count, 1);
  EXPECT_EQ(regions[1].id, 1);
  EXPECT_EQ(regions[1].area, 42.0);
  EXPECT_EQ(regions[1].face_count, 2);
  EXPECT_EQ(regions[1].vertex_count, 1);
  EXPECT_THAT(faces, ElementsAre(1, 1, 0, -1));
  // Region 2 had a vertex but no face: its vertex is unlabelled now.
  EXPECT_THAT(vertices, ElementsAre(1, 0, -1, -1));
}

}  // namespace
}  // namespace meshseg::pipeline_internal
