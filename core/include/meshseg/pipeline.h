// File: pipeline.h
// -----------------------------------------------------------------------------
// The whole job, as both the in-process CLI and the server's workers run it:
// read the input, (reconstruct a point cloud,) estimate curvature, segment,
// and map labels back to the faces of the input file. Reports progress per
// stage and honours cancellation. Same input and params give the same result
// on any thread count.
#ifndef MESHSEG_PIPELINE_H_
#define MESHSEG_PIPELINE_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/curvature.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"
#include "meshseg/segment.h"

namespace meshseg {

struct PipelineParams {
  // Overrides format detection (e.g. the upload's format hint).
  std::optional<FileFormat> format;
  CurvatureParams curvature;
  SegmentParams segment;
  // Upper bound on declared vertex/face counts of the input.
  int64_t max_elements = 200'000'000;
};

struct PipelineResult {
  MeshStats mesh;                 // statistics of the mesh that was segmented
  std::vector<int> face_labels;   // one per INPUT face, in input order; -1 = no region
  std::vector<int> vertex_labels; // one per mesh vertex; -1 = no region
  std::vector<Region> regions;
  SegmentEstimates estimates;
};

// Returns the segmentation of the mesh in `input_path`.
// Errors: those of ReadMesh, EstimateCurvature and Segment, prefixed with the
// stage; CANCELLED on stop.
absl::StatusOr<PipelineResult> RunPipeline(const std::string& input_path,
                                           const PipelineParams& params = {},
                                           const RunContext& ctx = {});

}  // namespace meshseg

#endif  // MESHSEG_PIPELINE_H_
