// Topology of a result message back into core types (the inverse of
// SetTopology; features are not read back).
#ifndef MESHSEG_PROTO_SRC_TOPOLOGY_FROM_PROTO_H_
#define MESHSEG_PROTO_SRC_TOPOLOGY_FROM_PROTO_H_

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/topology.h"
#include "meshseg/v1/segmentation.pb.h"

namespace meshseg {

// Returns the Eigen vector of a Vec3 (shared with result_from_proto.cc).
inline Eigen::Vector3d FromProto(const v1::Vec3& v) { return {v.x(), v.y(), v.z()}; }

// Returns the curves, loops, corners and adjacency of `result`, with one
// RegionTopology per region (patch_count: the patches its loops bound, at
// least 1 for a region with faces; normal_sign 0: not in the message).
// Errors (INVALID_ARGUMENT): ids that are not their index, unknown enum
// values, references to curves, corners or regions that do not exist.
absl::StatusOr<Topology> TopologyFromProto(const v1::SegmentationResult& result);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_SRC_TOPOLOGY_FROM_PROTO_H_
