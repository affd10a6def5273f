// The segmentation of each kind of input surface, shared by RunPipeline's
// input paths (pipeline.cc): each segments the surface, extracts boundaries
// and features into `result` and returns the labels per face of the mesh
// the topology refers to.
#ifndef MESHSEG_PIPELINE_SEGMENT_INPUT_H_
#define MESHSEG_PIPELINE_SEGMENT_INPUT_H_

#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"
#include "meshseg/point_cloud.h"
#include "meshseg/reconstruct.h"
#include "meshseg/run_context.h"
#include "meshseg/segment.h"
#include "meshseg/voxel.h"

namespace meshseg::pipeline_internal {

// Segments `mesh` and fills everything of `result` but the labels; returns
// the labels per mesh face.
absl::StatusOr<std::vector<int>> SegmentMesh(const Mesh& mesh, const PipelineParams& params,
                                             const RunContext& ctx, PipelineResult* result);

// An exact tessellation (meshseg/segment.h: SegmentExactFacets), facet by
// facet on the input itself: no curvature, no remesh.
absl::StatusOr<std::vector<int>> SegmentExact(const Mesh& mesh, const Exactness& exactness,
                                              const PipelineParams& params, const RunContext& ctx,
                                              PipelineResult* result);

// A CAD tessellation (meshseg/remesh.h): segments an isotropic remesh, then
// labels the faces and vertices of `mesh` from it and extracts boundaries and
// features on `mesh` itself, so curve vertex ids are ids of the input.
// `surface` is what is remeshed: `mesh` itself, or (binary occupancy) its
// de-terraced simplification, whose vertices are not on `mesh`'s facets.
// With `binary` (the binary-occupancy samples of `mesh`), planes are refitted
// as the separators of those samples, as on the relaxed route.
absl::StatusOr<std::vector<int>> SegmentRemeshed(const Mesh& surface, const Mesh& mesh,
                                                 double edge_length, bool on_facets,
                                                 const PipelineParams& params,
                                                 const RunContext& ctx, PipelineResult* result,
                                                 const BinaryVertices* binary = nullptr);

// ALGORITHMS.md S4 (binary voxels) for a binary-occupancy surface `mesh` on
// voxels of size h: its terraces (steps of one voxel on every slanted face)
// defeat curvature and growing, so it is segmented on a de-terraced surface
// (PipelineParams::BinarySurface) that keeps the feature vertices; labels
// and surfaces come back to the full surface's own faces and vertices.
absl::StatusOr<std::vector<int>> SegmentBinary(const Mesh& mesh, const BinaryVertices& binary,
                                               double h, const PipelineParams& params,
                                               const RunContext& ctx, PipelineResult* result);

// Segments the mesh reconstructed from `cloud` as SegmentMesh does, with
// the regions' surfaces refitted to the input points (the data; the mesh's
// vertices round creases over a spacing and the faces that close unscanned
// areas carry none), and labels every point (PointLabelsBySurface) before
// the boundaries and features are extracted from those surfaces. The
// vertices of those closing patches are segmented as unmeasured
// (SegmentParams::measured): they take their neighbours' labels but
// neither propose nor pay for one.
absl::StatusOr<std::vector<int>> SegmentReconstruction(const Reconstruction& reconstruction,
                                                       const PointCloud& cloud,
                                                       const PipelineParams& params,
                                                       const RunContext& ctx,
                                                       PipelineResult* result);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_SEGMENT_INPUT_H_
