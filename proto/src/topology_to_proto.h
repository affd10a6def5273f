// Topology and features into the public result message.
#ifndef MESHSEG_PROTO_SRC_TOPOLOGY_TO_PROTO_H_
#define MESHSEG_PROTO_SRC_TOPOLOGY_TO_PROTO_H_

#include <span>

#include "meshseg/features.h"
#include "meshseg/topology.h"
#include "meshseg/v1/segmentation.pb.h"

namespace meshseg {

// Copies an Eigen vector into a Vec3 (shared with to_proto.cc).
void SetVec3(const Eigen::Vector3d& v, v1::Vec3* out);

// Appends the curves, loops, corners, adjacency arcs and features to `out`
// (ids and order as in `topology` and `features`).
void SetTopology(const Topology& topology, std::span<const Feature> features,
                 v1::SegmentationResult* out);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_SRC_TOPOLOGY_TO_PROTO_H_
