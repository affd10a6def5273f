// ExtractTopology: check the input, then chain curves, give them geometry
// and character, trace and classify loops, place corners, build adjacency.
#include "meshseg/topology.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include <tbb/task_group.h>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "topology/chain_curves.h"
#include "topology/classify_loops.h"
#include "topology/curve_character.h"
#include "topology/curve_geometry.h"
#include "topology/normal_sign.h"
#include "topology/place_corners.h"
#include "topology/trace_loops.h"

namespace meshseg {
namespace {

using topology_internal::IntersectionTolerances;

constexpr char kStage[] = "topology";

absl::Status ValidateParams(const TopologyParams& p) {
  auto bad = [](const char* name, double v, const char* limit) {
    return absl::InvalidArgumentError(
        absl::StrCat("topology: ", name, " = ", v, " must be ", limit));
  };
  if (!(p.sharp_angle_deg > 0.0 && p.sharp_angle_deg < 180.0)) {
    return bad("sharp_angle_deg", p.sharp_angle_deg, "in (0, 180)");
  }
  if (!(p.curve_tolerance > 0.0) || !std::isfinite(p.curve_tolerance)) {
    return bad("curve_tolerance", p.curve_tolerance, "> 0");
  }
  if (!(p.angle_tolerance_deg > 0.0 && p.angle_tolerance_deg < 90.0)) {
    return bad("angle_tolerance_deg", p.angle_tolerance_deg, "in (0, 90)");
  }
  if (!(p.corner_snap_distance >= 0.0) || !std::isfinite(p.corner_snap_distance)) {
    return bad("corner_snap_distance", p.corner_snap_distance, ">= 0");
  }
  if (!(p.junction_length >= 0.0) || !std::isfinite(p.junction_length)) {
    return bad("junction_length", p.junction_length, ">= 0");
  }
  return absl::OkStatus();
}

absl::Status ValidateInput(const Mesh& mesh, std::span<const int> labels,
                           std::span<const Region> regions) {
  const std::string name = mesh.name.empty() ? "mesh" : "\"" + mesh.name + "\"";
  if (mesh.tri.n_faces() == 0) {
    return absl::InvalidArgumentError(absl::StrCat("topology: ", name, ": mesh has no faces"));
  }
  if (labels.size() != mesh.tri.n_faces()) {
    return absl::InvalidArgumentError(absl::StrCat("topology: ", name, ": ", labels.size(),
                                                   " face labels for ", mesh.tri.n_faces(),
                                                   " faces"));
  }
  for (size_t k = 0; k < regions.size(); ++k) {
    if (regions[k].id != static_cast<int>(k)) {
      return absl::InvalidArgumentError(absl::StrCat("topology: ", name, ": region ", k,
                                                     " has id ", regions[k].id, ", expected ", k));
    }
  }
  const int n = static_cast<int>(regions.size());
  for (size_t f = 0; f < labels.size(); ++f) {
    if (labels[f] < -1 || labels[f] >= n) {
      return absl::InvalidArgumentError(absl::StrCat("topology: ", name, ": face ", f,
                                                     " has label ", labels[f],
                                                     ", outside [-1, ", n, ")"));
    }
  }
  return absl::OkStatus();
}

std::vector<Eigen::Vector3d> PointsOf(const TriMesh& mesh, const std::vector<int>& vertices) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(vertices.size());
  for (const int v : vertices) points.push_back(ToEigen(mesh.point(OpenMesh::VertexHandle(v))));
  return points;
}

void BuildAdjacency(Topology* topo) {
  std::map<std::pair<int, int>, std::vector<int>> arcs;
  for (const BoundaryCurve& c : topo->curves) {
    if (c.left_region < 0 || c.right_region < 0) continue;
    arcs[std::minmax(c.left_region, c.right_region)].push_back(c.id);
  }
  for (auto& [pair, curves] : arcs) {
    topo->adjacency.push_back({pair.first, pair.second, std::move(curves)});
  }
}

// Length, geometry and character of each of topo->curves (chained, with
// their vertices), reporting progress over the first 0.8 of the stage.
absl::Status DescribeCurves(const TriMesh& tri, std::span<const int> face_labels,
                            std::span<const Region> regions, const TopologyParams& params,
                            const RunContext& ctx, Topology* topo) {
  const double l_avg = topo->mean_edge_length;
  const IntersectionTolerances tol{params.angle_tolerance_deg * std::numbers::pi / 180.0,
                                   params.curve_tolerance * l_avg};
  for (size_t i = 0; i < topo->curves.size(); ++i) {
    if (i % 64 == 0) {
      MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
      ctx.Progress(kStage, 0.8 * static_cast<double>(i) / static_cast<double>(topo->curves.size()));
    }
    BoundaryCurve& c = topo->curves[i];
    const std::vector<Eigen::Vector3d> points = PointsOf(tri, c.vertices);
    for (size_t j = 0; j + 1 < points.size(); ++j) c.length += (points[j + 1] - points[j]).norm();
    const Surface* left = c.left_region >= 0 ? &regions[c.left_region].surface : nullptr;
    const Surface* right = c.right_region >= 0 ? &regions[c.right_region].surface : nullptr;
    c.geometry = topology_internal::CurveGeometryOf(points, left, right, tol);
    const topology_internal::CurveCharacter character = topology_internal::CurveCharacterOf(
        tri, face_labels, regions, c, params.sharp_angle_deg);
    c.normal_angle_deg = character.normal_angle_deg;
    c.sharp = character.sharp;
    c.convexity = character.convexity;
    c.junction_artifact = !c.closed && c.start_corner >= 0 && c.end_corner >= 0 &&
                          c.length < params.junction_length * l_avg;
  }
  return ctx.CheckStop(kStage);
}

// ExtractTopology, with l_avg = MeanEdgeLength(mesh.tri) given if the
// caller already measured it (else summed here).
absl::StatusOr<Topology> ExtractTopologyWith(const Mesh& mesh, std::span<const int> face_labels,
                                             std::span<const Region> regions,
                                             const TopologyParams& params, const RunContext& ctx,
                                             std::optional<double> mean_edge_length) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  MESHSEG_RETURN_IF_ERROR(ValidateInput(mesh, face_labels, regions));
  const TriMesh& tri = mesh.tri;
  const int region_count = static_cast<int>(regions.size());
  // The patches (a union-find on both cores) and the regions' normal
  // signs read only the mesh and the labels: they are made beside the
  // curves, from the start. Each is a function of its inputs alone, so the
  // values are the same whichever thread makes them.
  topology_internal::FacePatches patches;
  std::vector<int> signs;
  tbb::task_group beside;
  beside.run([&] { patches = topology_internal::LabelPatches(tri, face_labels, region_count); });
  beside.run([&] { signs = topology_internal::RegionNormalSigns(tri, face_labels, regions); });
  Topology topo;
  topo.mean_edge_length = mean_edge_length ? *mean_edge_length : MeanEdgeLength(tri);
  topology_internal::CurveChains chains = topology_internal::ChainCurves(tri, face_labels);
  topo.curves = std::move(chains.curves);
  const absl::Status described = DescribeCurves(tri, face_labels, regions, params, ctx, &topo);
  beside.wait();  // before any return: the tasks write to this frame
  MESHSEG_RETURN_IF_ERROR(described);
  const double l_avg = topo.mean_edge_length;

  topology_internal::TracedLoops traced = topology_internal::TraceLoops(
      tri, face_labels, chains.halfedge_curve, std::move(patches));
  topology_internal::ClassifyLoops(tri, face_labels, regions, &traced);
  topo.loops = std::move(traced.loops);

  topology_internal::PlaceCorners(tri, face_labels, regions, chains.corner_vertices,
                                 params.corner_snap_distance * l_avg, &topo);
  BuildAdjacency(&topo);

  topo.regions.resize(regions.size());
  for (size_t k = 0; k < regions.size(); ++k) {
    topo.regions[k].region = static_cast<int>(k);
    topo.regions[k].patch_count = traced.patch_count[k];
    topo.regions[k].normal_sign = signs[k];
  }
  for (const Loop& loop : topo.loops) topo.regions[loop.region].loops.push_back(loop.id);
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  ctx.Progress(kStage, 1.0);
  return topo;
}

}  // namespace

absl::StatusOr<Topology> ExtractTopology(const Mesh& mesh, std::span<const int> face_labels,
                                         std::span<const Region> regions,
                                         const TopologyParams& params, const RunContext& ctx) {
  return ExtractTopologyWith(mesh, face_labels, regions, params, ctx, std::nullopt);
}

absl::StatusOr<Topology> ExtractTopology(const Mesh& mesh, std::span<const int> face_labels,
                                         std::span<const Region> regions, double mean_edge_length,
                                         const TopologyParams& params, const RunContext& ctx) {
  if (!(mean_edge_length > 0.0) || !std::isfinite(mean_edge_length)) {
    const std::string name = mesh.name.empty() ? "mesh" : "\"" + mesh.name + "\"";
    return absl::InvalidArgumentError(absl::StrCat("topology: ", name, ": mean edge length ",
                                                   mean_edge_length, ", must be finite and > 0"));
  }
  return ExtractTopologyWith(mesh, face_labels, regions, params, ctx, mean_edge_length);
}

}  // namespace meshseg
