#include "pipeline/binary_types.h"

#include <cmath>
#include <optional>
#include <set>
#include <variant>

#include "meshseg/fit.h"
#include "pipeline/separating_planes.h"

namespace meshseg::pipeline_internal {
namespace {

constexpr std::size_t kMinVertices = 30;
constexpr double kScoreMargin = 10.0;   // a likelihood ratio of e^5
constexpr double kMaxAxisOffset = 0.1;  // of the sphere's radius

struct Axis {
  Eigen::Vector3d point, direction;
};

std::optional<Axis> AxisOfTurned(const Surface& s) {
  if (const auto* c = std::get_if<Cylinder>(&s)) return Axis{c->axis_origin, c->axis_direction};
  if (const auto* c = std::get_if<Cone>(&s)) return Axis{c->apex, c->axis_direction};
  return std::nullopt;
}

double Criterion(const std::vector<Eigen::Vector3d>& points, double rms, int parameters) {
  const double m = static_cast<double>(points.size());
  return m * std::log(rms * rms) + parameters * std::log(m);
}

}  // namespace

void RetypeCoaxialSpheresOnInputVertices(const TriMesh& mesh, std::span<const int> face_labels,
                                         std::vector<Region>* regions) {
  const std::vector<int> interior = InteriorRegionOfVertex(mesh, face_labels);
  std::vector<std::vector<Eigen::Vector3d>> points(regions->size());
  for (const auto v : mesh.vertices()) {
    if (interior[v.idx()] >= 0) points[interior[v.idx()]].push_back(ToEigen(mesh.point(v)));
  }
  // Neighbouring regions across each edge.
  std::vector<std::set<int>> around(regions->size());
  for (const auto e : mesh.edges()) {
    if (mesh.is_boundary(e)) continue;
    const int a = face_labels[mesh.face_handle(mesh.halfedge_handle(e, 0)).idx()];
    const int b = face_labels[mesh.face_handle(mesh.halfedge_handle(e, 1)).idx()];
    if (a >= 0 && b >= 0 && a != b) around[a].insert(b), around[b].insert(a);
  }
  for (Region& region : *regions) {
    const auto* sphere = std::get_if<Sphere>(&region.surface);
    const std::vector<Eigen::Vector3d>& band = points[region.id];
    if (sphere == nullptr || band.size() < kMinVertices) continue;
    const FitResult own =
        FitOfType(SurfaceType::kSphere, {.points = band, .normals = {}, .weights = {}});
    if (!own.ok() || !(own.rms_distance > 0.0)) continue;
    const double own_score = Criterion(band, own.rms_distance, 4);
    std::optional<FitResult> best;
    double best_score = own_score - kScoreMargin;
    for (const int n : around[region.id]) {
      const Region& face = (*regions)[n];
      const std::optional<Axis> axis = AxisOfTurned(face.surface);
      if (!axis || points[n].size() < kMinVertices) continue;
      const Eigen::Vector3d d = axis->direction.normalized();
      const Eigen::Vector3d off = sphere->center - axis->point;
      if ((off - off.dot(d) * d).norm() > kMaxAxisOffset * sphere->radius) continue;
      const CoaxialMember members[] = {
          {face.type, {.points = points[n], .normals = {}, .weights = {}}},
          {SurfaceType::kCone, {.points = band, .normals = {}, .weights = {}}}};
      const FitResult cone = FitCoaxial(members, axis->point, d)[1];
      if (!cone.ok() || !(cone.rms_distance > 0.0)) continue;
      const double score = Criterion(band, cone.rms_distance, 2);
      if (score < best_score) best = cone, best_score = score;
    }
    if (best) {
      region.type = SurfaceType::kCone;
      region.surface = best->surface;
      region.rms_distance = best->rms_distance;
      region.max_distance = best->max_distance;
    }
  }
}

}  // namespace meshseg::pipeline_internal
