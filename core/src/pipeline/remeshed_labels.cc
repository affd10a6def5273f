#include "pipeline/remeshed_labels.h"

#include <array>
#include <map>

#include "pipeline/point_labels.h"

namespace meshseg::pipeline_internal {

constexpr int kSamplesPerFace = 4;

std::vector<int> TransferFaceLabels(const TriMesh& remeshed, std::span<const int> remeshed_labels,
                                    const TriMesh& original) {
  std::vector<Eigen::Vector3d> samples;
  samples.reserve(kSamplesPerFace * original.n_faces());
  for (const auto f : original.faces()) {
    std::array<Eigen::Vector3d, 3> corner;
    int k = 0;
    for (const auto v : original.fv_range(f)) corner[k++] = ToEigen(original.point(v));
    const Eigen::Vector3d centroid = (corner[0] + corner[1] + corner[2]) / 3.0;
    samples.push_back(centroid);
    for (const Eigen::Vector3d& c : corner) samples.push_back(0.5 * (centroid + c));
  }
  const std::vector<int> sample_labels = PointLabels(remeshed, remeshed_labels, samples, {});
  std::vector<int> labels(original.n_faces(), -1);
  for (std::size_t f = 0; f < labels.size(); ++f) {
    const int* s = sample_labels.data() + kSamplesPerFace * f;
    int best = s[0], best_votes = 0;
    for (int i = 0; i < kSamplesPerFace; ++i) {
      int votes = 0;
      for (int j = 0; j < kSamplesPerFace; ++j) votes += s[j] == s[i];
      if (votes > best_votes) best = s[i], best_votes = votes;
    }
    labels[f] = best;
  }
  return labels;
}

void CompactRegions(std::vector<int>* face_labels, std::vector<int>* vertex_labels,
                    std::vector<Region>* regions) {
  std::vector<int64_t> faces(regions->size(), 0), vertices(regions->size(), 0);
  for (const int label : *face_labels) {
    if (label >= 0) ++faces[label];
  }
  for (const int label : *vertex_labels) {
    if (label >= 0) ++vertices[label];
  }
  std::vector<int> new_id(regions->size(), -1);
  std::vector<Region> kept;
  for (std::size_t r = 0; r < regions->size(); ++r) {
    if (faces[r] == 0) continue;
    new_id[r] = static_cast<int>(kept.size());
    kept.push_back(std::move((*regions)[r]));
    kept.back().id = new_id[r];
    kept.back().face_count = faces[r];
    kept.back().vertex_count = vertices[r];
  }
  *regions = std::move(kept);
  for (int& label : *face_labels) {
    if (label >= 0) label = new_id[label];
  }
  for (int& label : *vertex_labels) {
    if (label >= 0) label = new_id[label];
  }
}

std::vector<int> VertexLabelsFromFaces(const TriMesh& mesh, std::span<const int> face_labels) {
  std::vector<int> labels(mesh.n_vertices(), -1);
  std::map<int, int> votes;
  for (const auto v : mesh.vertices()) {
    votes.clear();
    for (const auto f : mesh.vf_range(v)) {
      if (face_labels[f.idx()] >= 0) ++votes[face_labels[f.idx()]];
    }
    int most = 0;
    for (const auto& [label, n] : votes) {
      if (n > most) most = n, labels[v.idx()] = label;
    }
  }
  return labels;
}

}  // namespace meshseg::pipeline_internal
