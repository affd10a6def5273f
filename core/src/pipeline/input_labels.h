// Maps per-mesh-face labels back to the faces of the input file.
#ifndef MESHSEG_PIPELINE_INPUT_LABELS_H_
#define MESHSEG_PIPELINE_INPUT_LABELS_H_

#include <span>
#include <vector>

namespace meshseg::pipeline_internal {

// Returns one label per input face: the label of the mesh face it became,
// or -1 where it was dropped (face_of_input[k] == -1).
std::vector<int> InputFaceLabels(std::span<const int> face_of_input,
                                 std::span<const int> mesh_face_labels);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_INPUT_LABELS_H_
