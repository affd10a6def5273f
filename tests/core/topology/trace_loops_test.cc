#include "topology/trace_loops.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "labelled_meshes.h"

namespace meshseg::topology_internal {
namespace {

// The gridded box's six sides with +x relabelled -x: label 0 has two
// patches (the sides do not touch), numbered in order of their lowest face;
// an unlabelled face is in none.
TEST(LabelPatches, NumbersEachLabelsFaceComponentsByTheirLowestFace) {
  testing::LabelledMesh box = testing::GriddedBox({2.0, 3.0, 4.0}, 4);
  std::vector<int> labels = box.face_labels;
  const auto first_of = [&](int label) {
    return static_cast<int>(std::find(labels.begin(), labels.end(), label) - labels.begin());
  };
  const int first_minus_x = first_of(0);
  const int first_plus_x = first_of(1);
  for (int& l : labels) {
    if (l == 1) l = 0;
  }
  const int unlabelled = first_of(3);
  labels[unlabelled] = -1;
  const FacePatches patches = LabelPatches(box.mesh.tri, labels, 6);
  EXPECT_EQ(patches.patch_count, std::vector<int>({2, 0, 1, 1, 1, 1}));
  EXPECT_EQ(patches.face_patch[unlabelled], -1);
  const bool minus_x_first = first_minus_x < first_plus_x;
  for (std::size_t f = 0; f < labels.size(); ++f) {
    if (labels[f] < 0) continue;
    const int side = box.face_labels[f];
    const int expected = side == 0 ? (minus_x_first ? 0 : 1) : side == 1 ? (minus_x_first ? 1 : 0) : 0;
    ASSERT_EQ(patches.face_patch[f], expected) << "face " << f << " of side " << side;
  }
}

// The reference numbering: a flood fill across edges between equally
// labelled faces, seeded in face order, each label's patches counted from 0.
FacePatches FloodFilledPatches(const TriMesh& mesh, const std::vector<int>& labels,
                               int region_count) {
  FacePatches out;
  out.patch_count.assign(region_count, 0);
  out.face_patch.assign(mesh.n_faces(), -1);
  std::vector<int> stack;
  for (int seed = 0; seed < static_cast<int>(mesh.n_faces()); ++seed) {
    if (labels[seed] < 0 || out.face_patch[seed] >= 0) continue;
    const int patch = out.patch_count[labels[seed]]++;
    out.face_patch[seed] = patch;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (const auto h : mesh.fh_range(TriMesh::FaceHandle(f))) {
        const int g = mesh.opposite_face_handle(h).idx();
        if (g < 0 || labels[g] != labels[seed] || out.face_patch[g] >= 0) continue;
        out.face_patch[g] = patch;
        stack.push_back(g);
      }
    }
  }
  return out;
}

// Labels drawn per face from a fixed hash (k labels, about one face in ten
// unlabelled) cut a fine box into hundreds of patches for k >= 2, many of
// them across the face blocks the union-find joins side by side; with one
// label the labelled faces (90%, above the percolation threshold of the
// face graph) mostly form one patch that spans every block. Every face's
// patch index and every count equal the serial flood fill's.
TEST(LabelPatches, EqualsTheFloodFillOnManyPatches) {
  const testing::LabelledMesh box = testing::GriddedBox({2.0, 3.0, 4.0}, 60);  // 43200 faces
  const int nf = static_cast<int>(box.mesh.tri.n_faces());
  for (const int k : {1, 2, 3, 5}) {
    std::vector<int> labels(box.mesh.tri.n_faces());
    uint64_t state = 88172645463325252ull;
    for (int& l : labels) {
      state ^= state << 13;
      state ^= state >> 7;
      state ^= state << 17;
      l = state % 10 == 0 ? -1 : static_cast<int>((state >> 8) % k);
    }
    const FacePatches expected = FloodFilledPatches(box.mesh.tri, labels, k);
    if (k == 1) {
      std::vector<int> size(expected.patch_count[0], 0);
      for (const int p : expected.face_patch) {
        if (p >= 0) ++size[p];
      }
      EXPECT_GT(*std::max_element(size.begin(), size.end()), nf / 2);
    } else {
      int total = 0;
      for (const int c : expected.patch_count) total += c;
      EXPECT_GT(total, 100) << k << " labels";
    }
    const FacePatches patches = LabelPatches(box.mesh.tri, labels, k);
    EXPECT_EQ(patches.patch_count, expected.patch_count) << k << " labels";
    EXPECT_EQ(patches.face_patch, expected.face_patch) << k << " labels";
  }
}

}  // namespace
}  // namespace meshseg::topology_internal
