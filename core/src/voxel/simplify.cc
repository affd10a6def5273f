// Simplify(): copies the mesh, locks feature points (given, and the ends of
// edges between differently labelled faces), finds the creases of a plain
// mesh, runs the quadric collapse loop (edge_collapse.h), and rebuilds a
// compact Mesh with the labels of the surviving faces and the Hausdorff
// distance to the input.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"
#include "voxel/edge_collapse.h"

namespace meshseg {
namespace {

absl::Status ValidateParams(const TriMesh& mesh, const SimplifyParams& params,
                            std::span<const uint8_t> feature_vertex,
                            std::span<const int> face_labels) {
  if (params.target_faces <= 0 && !(params.max_error > 0.0)) {
    return absl::InvalidArgumentError("simplify: give a target face count or a max error");
  }
  if (params.target_faces < 0 || !std::isfinite(params.max_error) || params.max_error < 0.0) {
    return absl::InvalidArgumentError(absl::StrCat("simplify: target_faces ", params.target_faces,
                                                   " and max_error ", params.max_error,
                                                   " must not be negative"));
  }
  if (!(params.max_normal_flip_deg > 0.0 && params.max_normal_flip_deg <= 180.0)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "simplify: max_normal_flip_deg ", params.max_normal_flip_deg, " must be in (0, 180]"));
  }
  if (mesh.n_faces() == 0) return absl::InvalidArgumentError("simplify: the mesh has no faces");
  if (!feature_vertex.empty() && feature_vertex.size() != mesh.n_vertices()) {
    return absl::InvalidArgumentError(absl::StrCat("simplify: ", feature_vertex.size(),
                                                   " feature flags for ", mesh.n_vertices(),
                                                   " vertices"));
  }
  if (!face_labels.empty() && face_labels.size() != mesh.n_faces()) {
    return absl::InvalidArgumentError(absl::StrCat("simplify: ", face_labels.size(),
                                                   " face labels for ", mesh.n_faces(), " faces"));
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<Simplification> Simplify(const TriMesh& mesh, const SimplifyParams& params,
                                        std::span<const uint8_t> feature_vertex,
                                        std::span<const int> face_labels, const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(mesh, params, feature_vertex, face_labels));
  ctx.Progress("simplify", 0.0);
  TriMesh work = mesh;
  // Locked: the given feature points and the ends of label-boundary edges.
  std::vector<uint8_t> locked(work.n_vertices(), 0);
  if (!feature_vertex.empty())
    std::copy(feature_vertex.begin(), feature_vertex.end(), locked.begin());
  if (!face_labels.empty()) {
    for (auto e : work.edges()) {
      if (work.is_boundary(e)) continue;
      const int a = face_labels[work.face_handle(work.halfedge_handle(e, 0)).idx()];
      const int b = face_labels[work.face_handle(work.halfedge_handle(e, 1)).idx()];
      if (a == b) continue;
      locked[work.to_vertex_handle(work.halfedge_handle(e, 0)).idx()] = 1;
      locked[work.to_vertex_handle(work.halfedge_handle(e, 1)).idx()] = 1;
    }
  }
  // Creases are found on plain meshes; given feature points (a binary
  // surface's feature voxels) already say where the features are, and there
  // every terrace step would count as a crease.
  std::vector<uint8_t> crease;
  if (feature_vertex.empty() && params.crease_deg > 0.0) {
    crease = voxel_internal::CreaseEdges(work, params.crease_deg);
  } else {
    crease.assign(work.n_edges(), 0);
    for (auto e : work.edges()) crease[e.idx()] = work.is_boundary(e);
  }
  const voxel_internal::CollapseParams collapse{
      .target_faces = static_cast<size_t>(params.target_faces),
      .max_error = params.max_error,
      .min_cos_normal = std::cos(params.max_normal_flip_deg * std::numbers::pi / 180.0),
      .two_lanes_min_faces = static_cast<size_t>(std::max<int64_t>(0, params.two_lanes_min_faces))};
  MESHSEG_RETURN_IF_ERROR(voxel_internal::CollapseEdges(work, collapse, locked, crease, ctx));
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("simplify"));

  // A compact copy: surviving vertices in input order, faces likewise.
  std::vector<int> new_index(work.n_vertices(), -1);
  std::vector<Eigen::Vector3d> points;
  Simplification out;
  for (auto v : work.vertices()) {
    if (work.status(v).deleted()) continue;
    new_index[v.idx()] = static_cast<int>(points.size());
    points.push_back(ToEigen(work.point(v)));
    out.input_vertex.push_back(v.idx());
  }
  std::vector<std::array<int, 3>> triangles;
  for (auto f : work.faces()) {
    if (work.status(f).deleted()) continue;
    std::array<int, 3> t;
    int c = 0;
    for (auto v : work.fv_range(f)) t[c++] = new_index[v.idx()];
    triangles.push_back(t);
    if (!face_labels.empty()) out.face_labels.push_back(face_labels[f.idx()]);
  }
  MESHSEG_ASSIGN_OR_RETURN(out.mesh, BuildMesh(std::move(points), triangles, "simplified"));
  if (!face_labels.empty()) {
    // BuildMesh may drop a triangle (degenerate): keep labels per mesh face.
    std::vector<int> labels(out.mesh.tri.n_faces(), -1);
    for (size_t t = 0; t < out.mesh.face_of_input.size(); ++t) {
      if (out.mesh.face_of_input[t] >= 0) labels[out.mesh.face_of_input[t]] = out.face_labels[t];
    }
    out.face_labels = std::move(labels);
  }
  ctx.Progress("simplify", 0.95);
  if (params.measure_hausdorff) out.hausdorff = Hausdorff(mesh, out.mesh.tri);
  ctx.Progress("simplify", 1.0);
  return out;
}

}  // namespace meshseg
