#include "reconstruct/refine.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "reconstruct/fair_unsupported.h"
#include "reconstruct/isotropic_steps.h"
#include "reconstruct/project_to_points.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: refine";
// A triangle with |cross| ≤ this × (longest edge)² is taken as flat: a
// thousand times the threshold below which mesh builders drop faces
// (mesh/build_mesh.cc), so a written and re-read mesh keeps every face.
constexpr double kFlat = 1e-9;
constexpr int kUnflattenRounds = 5;

double SurfaceArea(const TriMesh& m) {
  double area = 0.0;
  for (const auto f : m.faces()) area += m.calc_face_area(f);
  return area;
}

// Faces with |cross| ≤ kFlat l_max².
std::vector<int> FlatFaces(const TriMesh& m) {
  std::vector<int> flat;
  for (const auto f : m.faces()) {
    Eigen::Vector3d c[3];
    int i = 0;
    for (const auto v : f.vertices()) c[i++] = ToEigen(m.point(v));
    const double l2 = std::max({(c[1] - c[0]).squaredNorm(), (c[2] - c[1]).squaredNorm(),
                                (c[0] - c[2]).squaredNorm()});
    if ((c[1] - c[0]).cross(c[2] - c[0]).norm() <= kFlat * l2 || l2 == 0.0) flat.push_back(f.idx());
  }
  return flat;
}

// Moves the corners of flat faces a hundredth of the way to the mean of
// their neighbours, which no two distinct vertices share; returns the
// number of flat faces left.
int64_t Unflatten(TriMesh* m) {
  for (int round = 0; round < kUnflattenRounds; ++round) {
    const std::vector<int> flat = FlatFaces(*m);
    if (flat.empty()) return 0;
    for (const int f : flat) {
      for (const auto v : m->fv_range(TriMesh::FaceHandle(f))) {
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        int count = 0;
        for (const auto w : m->vv_range(v)) mean += ToEigen(m->point(w)), ++count;
        const Eigen::Vector3d p = ToEigen(m->point(v));
        const Eigen::Vector3d q = p + 0.01 * (mean / std::max(count, 1) - p);
        m->set_point(v, TriMesh::Point(q.x(), q.y(), q.z()));
      }
    }
  }
  return static_cast<int64_t>(FlatFaces(*m).size());
}

}  // namespace

absl::StatusOr<RefinedSurface> RefineOnPoints(const TriMesh& coarse,
                                              const SampledSurface& surface,
                                              const ReconstructParams& params,
                                              const RunContext& ctx, ReconstructStats* stats) {
  const double h = surface.h;
  // An equilateral triangle of edge l has area (√3/4) l²: the edge at which
  // the surface holds refine_max_faces of them.
  const double capped =
      std::sqrt(4.0 * SurfaceArea(coarse) / (std::sqrt(3.0) * params.refine_max_faces));
  const double target = std::max(params.refine_edge_length * h, capped);
  stats->refine_edge_length = target;
  const double radius = params.projection_radius * h;
  RefinedSurface out;
  TriMesh& m = out.mesh;
  m = coarse;
  for (int round = 0; round < kRemeshRounds; ++round) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
    SplitLongEdges(target, &m);
    CollapseShortEdges(target, &m);
    m.garbage_collection();
    EqualizeValences(&m);
    RelaxTangentially(&m);
    ProjectToPoints(surface, radius, 1, &m);
    ctx.Progress(kStage, (round + 1.0) / (kRemeshRounds + 1.0));
  }
  const std::vector<int> left = ProjectToPoints(surface, radius, kProjectionIterations, &m);
  out.unsupported.assign(m.n_vertices(), 0);
  for (const int v : left) out.unsupported[v] = 1;
  stats->unsupported_vertex_count = static_cast<int64_t>(left.size());
  FairFreeVertices(out.unsupported, &m);
  if (const int64_t flat = Unflatten(&m); flat > 0) {
    return absl::InternalError(absl::StrCat(kStage, ": ", flat,
                                            " zero-area triangles left after refinement"));
  }
  m.update_normals();
  ctx.Progress(kStage, 1.0);
  return out;
}

}  // namespace meshseg::reconstruct_internal
