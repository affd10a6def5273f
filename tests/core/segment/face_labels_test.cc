#include "segment/face_labels.h"

#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace meshseg::segment_internal {
namespace {

// An n x n grid of unit squares in z = 0, two triangles each: square (i, j)
// (column i, row j) has faces 2 (j n + i) and 2 (j n + i) + 1.
TriMesh Grid(int n) {
  TriMesh mesh;
  std::vector<TriMesh::VertexHandle> v;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) v.push_back(mesh.add_vertex(TriMesh::Point(i, j, 0)));
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1];
      const auto c = v[(j + 1) * (n + 1) + i], d = v[(j + 1) * (n + 1) + i + 1];
      mesh.add_face(a, b, d);
      mesh.add_face(a, d, c);
    }
  }
  return mesh;
}

// Labels per square from a function of (i, j).
template <typename F>
std::vector<int> SquareLabels(int n, F label) {
  std::vector<int> out(2 * n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) out[2 * (j * n + i)] = out[2 * (j * n + i) + 1] = label(i, j);
  }
  return out;
}

int LabelOfSquare(const std::vector<int>& labels, int n, int i, int j) {
  return labels[2 * (j * n + i)];
}

TEST(MergeFaceFragmentsTest, PieceCutOffItsRegionJoinsTheRegionAroundIt) {
  const int n = 20;
  const TriMesh mesh = Grid(n);
  // Left half 0, right half 1, and one square of 0 inside the right half.
  std::vector<int> labels =
      SquareLabels(n, [](int i, int j) { return i < 10 || (i == 15 && j == 8) ? 0 : 1; });
  MergeFaceFragments(mesh, &labels);
  EXPECT_EQ(LabelOfSquare(labels, n, 15, 8), 1);
  EXPECT_EQ(LabelOfSquare(labels, n, 9, 8), 0);
  EXPECT_EQ(LabelOfSquare(labels, n, 10, 8), 1);
}

TEST(MergeFaceFragmentsTest, PieceOnAJunctionTakesTheLabelItSharesMostEdgesWith) {
  const int n = 20;
  const TriMesh mesh = Grid(n);
  // Regions 0 (i < 10), 1 (i >= 10, j < 10), 2 (i >= 10, j >= 10), and
  // two squares of 0 at (10..11, 10) reaching into the junction of 1 and 2.
  std::vector<int> labels = SquareLabels(n, [](int i, int j) {
    if (i < 10 || (j == 10 && i <= 11)) return 0;
    return j < 10 ? 1 : 2;
  });
  MergeFaceFragments(mesh, &labels);
  // They join region 0 across i = 10: one piece with it, not a fragment.
  EXPECT_EQ(LabelOfSquare(labels, n, 11, 10), 0);

  // A square of 0 at (12, 10), cut off region 0: it shares one edge with 1
  // (below) and three with 2.
  labels = SquareLabels(n, [](int i, int j) {
    if (i < 10 || (j == 10 && i == 12)) return 0;
    return j < 10 ? 1 : 2;
  });
  MergeFaceFragments(mesh, &labels);
  EXPECT_EQ(LabelOfSquare(labels, n, 12, 10), 2);
}

// Pieces of each label: the largest and those of kMaxFragmentFaces or more
// are not fragments; returns the number of the others.
int Fragments(const TriMesh& mesh, const std::vector<int>& labels) {
  std::vector<int> piece(labels.size(), -1);
  std::vector<std::size_t> size;
  std::vector<int> label;
  for (std::size_t s = 0; s < labels.size(); ++s) {
    if (labels[s] < 0 || piece[s] >= 0) continue;
    const int id = static_cast<int>(size.size());
    size.push_back(0);
    label.push_back(labels[s]);
    std::vector<int> stack = {static_cast<int>(s)};
    piece[s] = id;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      ++size[id];
      for (auto it = mesh.cff_iter(TriMesh::FaceHandle(f)); it.is_valid(); ++it) {
        if (piece[it->idx()] < 0 && labels[it->idx()] == labels[s]) {
          piece[it->idx()] = id;
          stack.push_back(it->idx());
        }
      }
    }
  }
  int fragments = 0;
  for (std::size_t id = 0; id < size.size(); ++id) {
    bool largest = true;
    for (std::size_t other = 0; other < size.size(); ++other) {
      if (label[other] == label[id] && size[other] > size[id]) largest = false;
    }
    fragments += !largest && size[id] < kMaxFragmentFaces;
  }
  return fragments;
}

// A noisy junction: within 3 columns of the line between regions 0 and 1,
// two fifths of the faces take a random one of 0, 1 and 2 (region 2 has its
// own block elsewhere). Fragments of different labels lie side by side.
TEST(MergeFaceFragmentsTest, NoisyJunctionEndsWithoutFragments) {
  const int n = 40;
  const TriMesh mesh = Grid(n);
  std::vector<int> labels = SquareLabels(n, [](int i, int j) {
    if (i >= 30 && j >= 30) return 2;
    return i < 20 ? 0 : 1;
  });
  std::mt19937 random(9);
  std::uniform_real_distribution<double> share(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 2);
  for (int j = 0; j < n; ++j) {
    for (int i = 17; i < 23; ++i) {
      for (int k = 0; k < 2; ++k) {
        if (share(random) < 0.4) labels[2 * (j * n + i) + k] = pick(random);
      }
    }
  }
  ASSERT_GT(Fragments(mesh, labels), 20);
  MergeFaceFragments(mesh, &labels);
  EXPECT_EQ(Fragments(mesh, labels), 0);
  // The block of 2 and the two halves away from the junction are untouched.
  EXPECT_EQ(LabelOfSquare(labels, n, 35, 35), 2);
  EXPECT_EQ(LabelOfSquare(labels, n, 5, 5), 0);
  EXPECT_EQ(LabelOfSquare(labels, n, 28, 5), 1);
}

TEST(MergeFaceFragmentsTest, LargePiecesAndWholeSmallRegionsStay) {
  const int n = 20;
  const TriMesh mesh = Grid(n);
  // Region 0: the left 5 columns and, apart, an 8 x 4 block (64 faces) on
  // the right; region 2: one square on its own, the region's only piece.
  std::vector<int> labels = SquareLabels(n, [](int i, int j) {
    if (i < 5 || (i >= 12 && j >= 12 && j < 16)) return 0;
    if (i == 8 && j == 3) return 2;
    return 1;
  });
  const std::vector<int> before = labels;
  MergeFaceFragments(mesh, &labels);
  EXPECT_EQ(labels, before);
}

TEST(MergeFaceFragmentsTest, UnlabelledFacesAreNeitherGivenNorTaken) {
  const int n = 10;
  const TriMesh mesh = Grid(n);
  // A piece of 0 cut off inside unlabelled faces keeps its label; the
  // unlabelled faces stay -1.
  std::vector<int> labels = SquareLabels(n, [](int i, int j) {
    if (i < 3) return 0;
    if (i == 7 && j == 5) return 0;
    return -1;
  });
  const std::vector<int> before = labels;
  MergeFaceFragments(mesh, &labels);
  EXPECT_EQ(labels, before);
}

}  // namespace
}  // namespace meshseg::segment_internal
