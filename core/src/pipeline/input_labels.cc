#include "pipeline/input_labels.h"

#include <cassert>
#include <cstddef>

namespace meshseg::pipeline_internal {

std::vector<int> InputFaceLabels(std::span<const int> face_of_input,
                                 std::span<const int> mesh_face_labels) {
  std::vector<int> labels(face_of_input.size(), -1);
  for (size_t k = 0; k < face_of_input.size(); ++k) {
    const int f = face_of_input[k];
    if (f < 0) continue;
    assert(static_cast<size_t>(f) < mesh_face_labels.size() && "face_of_input out of range");
    labels[k] = mesh_face_labels[f];
  }
  return labels;
}

}  // namespace meshseg::pipeline_internal
