// The chord vertices of a FacetMesh (facet_mesh.h) found on first use are
// those found up front, vertex for vertex, when many threads read them at
// once in an order of their own: on a noisy voxel part and on an exact CAD
// tessellation.
#include "segment/facet_mesh.h"

#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "meshseg/generate.h"
#include "meshseg/mesh.h"

namespace meshseg::segment_internal {
namespace {

void ExpectSameChords(const TriMesh& mesh, const std::string& what) {
  const FacetMesh up_front = BuildFacetMesh(mesh);
  const FacetMesh on_use = BuildFacetMesh(mesh, ChordVertices::kOnFirstUse);
  const int n = static_cast<int>(up_front.points.size());
  ASSERT_EQ(static_cast<int>(on_use.points.size()), n) << what;
  // Every vertex read by two threads' worth of blocks, last vertex first,
  // each read twice (the second finds it found); small blocks so that
  // neighbouring reads interleave.
  std::atomic<int> on_chord{0};
  tbb::parallel_for(0, 2 * n, 7, [&](int k) {
    const int v = n - 1 - k % n;
    const bool on = OnChord(on_use, v, 1e30);
    const std::array<int, 2> ends = on_use.ChordEnds(v);
    if (k < n && on) on_chord.fetch_add(1);
    (void)ends;
  });
  int differ = 0;
  for (int v = 0; v < n; ++v) {
    const bool same = on_use.ChordEnds(v) == up_front.chord_ends[v] &&
                      (on_use.chord_offset[v] == up_front.chord_offset[v] ||
                       (up_front.chord_ends[v][0] < 0 && on_use.chord_ends[v][0] < 0));
    differ += !same;
  }
  EXPECT_EQ(differ, 0) << what;
  // Chord vertices exist in both meshes (the test compares found entries,
  // not only "none").
  EXPECT_GT(on_chord.load(), 0) << what;
}

TEST(FacetMesh, ChordVerticesFoundOnFirstUseAreThoseFoundUpFront) {
  const absl::StatusOr<GeneratedPart> voxel =
      GeneratePart("test_piece", {.voxel_size = 1.0, .noise = 0.05});
  ASSERT_TRUE(voxel.ok()) << voxel.status();
  ExpectSameChords(voxel->mesh.tri, "voxel test_piece");
  const std::vector<std::string> cad_names = CadPartNames();
  ASSERT_FALSE(cad_names.empty());
  const absl::StatusOr<GeneratedPart> cad =
      GenerateCadPart(cad_names.front(), {.deflection = CadDeflection::kFine});
  ASSERT_TRUE(cad.ok()) << cad.status();
  ExpectSameChords(cad->mesh.tri, "CAD " + cad_names.front());
}

}  // namespace
}  // namespace meshseg::segment_internal
