#include "meshseg/generate.h"

#include <cstdio>

#include <gtest/gtest.h>

namespace meshseg {
namespace {

TEST(GeneratePart, Smoke) {
  for (const std::string& name : PartNames()) {
    if (name == "test_piece_large") continue;
    auto part = GeneratePart(name, {.voxel_size = 0.0});
    ASSERT_TRUE(part.ok()) << part.status();
    const MeshStats s = MeshStatistics(part->mesh);
    std::printf("%s h=%g V=%ld F=%ld boundary=%ld nm_e=%ld nm_v=%ld comp=%ld dropped=%ld\n", name.c_str(),
                part->voxel_size, s.vertex_count, s.face_count, s.boundary_edge_count,
                s.non_manifold_edge_count, s.non_manifold_vertex_count, s.component_count,
                s.dropped_face_count);
  }
}

}  // namespace
}  // namespace meshseg
