// WriteStep: check the input, then surfaces per region, vertices and edges
// per corner and curve, one face per region patch, sewing into a solid, and
// the STEP file. OpenCASCADE's exceptions stop here.
#include "meshseg/brep.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>

#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>

#include "absl/strings/str_cat.h"
#include "brep/assemble_shape.h"
#include "brep/boundary_edges.h"
#include "brep/occt_surface.h"
#include "brep/region_face.h"
#include "brep/region_samples.h"
#include "brep/step_file.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

using brep_internal::RegionSurface;

constexpr char kStage[] = "brep";
// A curve within this fraction of the model's diagonal of both surfaces lies
// on them (their exact intersection), and the least sewing tolerance.
constexpr double kExactGap = 1e-7;
constexpr double kMinSewing = 1e-6;
// Corners move onto their surfaces by at most this many l_avg (as the
// topology stage's corner_snap_distance) plus 3 noise sigmas.
constexpr double kCornerMove = 3.0;

absl::Status ValidateParams(const BrepParams& p) {
  if (brep_internal::StepUnitName(p.length_unit).empty()) {
    return absl::InvalidArgumentError(
        absl::StrCat("brep: length_unit \"", p.length_unit, "\" is not one of ", LengthUnitList()));
  }
  if (p.noise_sigma && !(*p.noise_sigma >= 0.0 && std::isfinite(*p.noise_sigma))) {
    return absl::InvalidArgumentError(
        absl::StrCat("brep: noise_sigma = ", *p.noise_sigma, " must be finite and >= 0"));
  }
  if (!(p.sewing_tolerance > 0.0 && std::isfinite(p.sewing_tolerance))) {
    return absl::InvalidArgumentError(
        absl::StrCat("brep: sewing_tolerance = ", p.sewing_tolerance, " must be > 0"));
  }
  if (!(p.curve_tolerance > 0.0 && std::isfinite(p.curve_tolerance))) {
    return absl::InvalidArgumentError(
        absl::StrCat("brep: curve_tolerance = ", p.curve_tolerance, " must be > 0"));
  }
  return absl::OkStatus();
}

absl::Status ValidateInput(const Mesh& mesh, std::span<const int> labels,
                           std::span<const Region> regions, const Topology& topo) {
  const std::string name = mesh.name.empty() ? "mesh" : "\"" + mesh.name + "\"";
  auto bad = [&](auto&&... parts) {
    return absl::InvalidArgumentError(absl::StrCat("brep: ", name, ": ", parts...));
  };
  if (labels.size() != mesh.tri.n_faces()) {
    return bad(labels.size(), " face labels for ", mesh.tri.n_faces(), " faces");
  }
  const int n = static_cast<int>(regions.size());
  for (int k = 0; k < n; ++k) {
    if (regions[k].id != k) return bad("region ", k, " has id ", regions[k].id);
  }
  for (size_t f = 0; f < labels.size(); ++f) {
    if (labels[f] < -1 || labels[f] >= n) {
      return bad("face ", f, " has label ", labels[f], ", outside [-1, ", n, ")");
    }
  }
  if (topo.regions.size() != regions.size()) {
    return bad("topology has ", topo.regions.size(), " regions, the result ", n);
  }
  const int vertex_count = static_cast<int>(mesh.tri.n_vertices());
  const int corner_count = static_cast<int>(topo.corners.size());
  for (const BoundaryCurve& c : topo.curves) {
    if (c.left_region < 0 || c.left_region >= n || c.right_region < -1 || c.right_region >= n) {
      return bad("curve ", c.id, " joins regions ", c.left_region, " and ", c.right_region,
                 ", outside [-1, ", n, ")");
    }
    if (c.vertices.size() < 2 || c.start_corner >= corner_count || c.end_corner >= corner_count) {
      return bad("curve ", c.id, " has ", c.vertices.size(), " vertices and corners ",
                 c.start_corner, ", ", c.end_corner, " of ", corner_count);
    }
    for (const int v : c.vertices) {
      if (v < 0 || v >= vertex_count) {
        return bad("curve ", c.id, " has vertex ", v, ", outside [0, ", vertex_count, ")");
      }
    }
  }
  for (const Loop& l : topo.loops) {
    if (l.region < 0 || l.region >= n) return bad("loop ", l.id, " has region ", l.region);
    for (const CurveUse& u : l.curves) {
      if (u.curve < 0 || u.curve >= static_cast<int>(topo.curves.size())) {
        return bad("loop ", l.id, " uses curve ", u.curve, " of ", topo.curves.size());
      }
    }
  }
  for (const Corner& c : topo.corners) {
    if (c.cluster < 0 || c.cluster >= corner_count) {
      return bad("corner ", c.id, " has cluster ", c.cluster, " of ", corner_count);
    }
    for (const int r : c.regions) {
      if (r < -1 || r >= n) return bad("corner ", c.id, " touches region ", r);
    }
  }
  return absl::OkStatus();
}

// The median rms distance of the regions from their surfaces.
double MedianRms(std::span<const Region> regions) {
  std::vector<double> rms;
  for (const Region& r : regions) rms.push_back(r.rms_distance);
  if (rms.empty()) return 0.0;
  std::nth_element(rms.begin(), rms.begin() + rms.size() / 2, rms.end());
  return rms[rms.size() / 2];
}

double Diagonal(const TriMesh& mesh) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (OpenMesh::VertexHandle v : mesh.vertices()) {
    lo = lo.cwiseMin(ToEigen(mesh.point(v)));
    hi = hi.cwiseMax(ToEigen(mesh.point(v)));
  }
  return mesh.n_vertices() > 0 ? (hi - lo).norm() : 0.0;
}

absl::StatusOr<BrepReport> Build(const Mesh& mesh, std::span<const int> face_labels,
                                 std::span<const Region> regions, const Topology& topology,
                                 const std::string& path, const BrepParams& params,
                                 const RunContext& ctx) {
  const TriMesh& tri = mesh.tri;
  const int n = static_cast<int>(regions.size());
  const double l_avg = topology.mean_edge_length > 0.0 ? topology.mean_edge_length
                                                       : MeanEdgeLength(tri);
  const double sigma = params.noise_sigma.value_or(MedianRms(regions));
  const double diagonal = Diagonal(tri);
  BrepReport report;
  report.region_count = n;
  report.sewing_tolerance = std::max(params.sewing_tolerance * sigma, kMinSewing * diagonal);
  const double curve_tolerance = params.curve_tolerance * l_avg + 3.0 * sigma;

  ctx.Progress(kStage, 0.0);
  const std::vector<brep_internal::RegionSamples> samples =
      brep_internal::SampleRegions(tri, face_labels, n);
  std::vector<RegionSurface> surfaces(n);
  std::vector<Handle(Geom_Surface)> geoms(n);
  std::map<const Geom_Surface*, int> region_of;
  for (int r = 0; r < n; ++r) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
    surfaces[r] = brep_internal::MakeRegionSurface(regions[r], samples[r], l_avg, sigma);
    geoms[r] = surfaces[r].surface;
    if (!geoms[r].IsNull()) region_of[geoms[r].get()] = r;
  }
  ctx.Progress(kStage, 0.3);
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  // How far apart exact surfaces may leave a shared edge, floored at OCCT's
  // confusion distance.
  const double exact_gap = std::max(kExactGap * diagonal, Precision::Confusion());
  const brep_internal::BoundaryEdges edges = brep_internal::MakeBoundaryEdges(
      tri, topology, geoms,
      {.curve = curve_tolerance,
       .exact_gap = exact_gap,
       .corner_move = kCornerMove * l_avg + 3.0 * sigma,
       .l_avg = l_avg,
       .surface_offset = 3.0 * sigma});
  report.exact_edge_count = edges.exact_count;
  report.fitted_edge_count = edges.fitted_count;
  report.edge_count = edges.exact_count + edges.fitted_count;
  ctx.Progress(kStage, 0.6);

  std::vector<TopoDS_Face> faces;
  for (int r = 0; r < n; ++r) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
    for (int patch = 0; patch < topology.regions[r].patch_count; ++patch) {
      ++report.patch_count;
      if (geoms[r].IsNull()) {
        report.failures.push_back({r, patch, surfaces[r].failure});
        continue;
      }
      brep_internal::RegionFace face = brep_internal::MakeRegionFace(
          topology, r, patch, geoms[r], surfaces[r].sign, edges, exact_gap, curve_tolerance,
          std::max(3.0 * sigma, kExactGap * diagonal));
      if (face.contracted) {
        --report.patch_count;
        ++report.contracted_patch_count;
      } else if (face.face.IsNull()) {
        report.failures.push_back({r, patch, face.failure});
      } else {
        faces.push_back(face.face);
      }
    }
  }
  if (faces.empty()) {
    return absl::FailedPreconditionError(absl::StrCat(
        "brep: no face of the ", report.patch_count, " region patches could be built",
        report.failures.empty() ? "" : absl::StrCat(" (region ", report.failures[0].region,
                                                    ": ", report.failures[0].reason, ")")));
  }
  ctx.Progress(kStage, 0.8);
  const brep_internal::AssembledShape shape =
      brep_internal::AssembleShape(faces, report.sewing_tolerance);
  report.face_count = shape.face_count;
  report.closed = shape.closed;
  report.solid = shape.solid;
  report.solid_count = shape.solid_count;
  report.valid = shape.valid;
  report.volume = shape.volume;
  report.max_tolerance = shape.max_tolerance;

  auto face_name = [&](const TopoDS_Face& face) -> std::string {
    const auto it = region_of.find(BRep_Tool::Surface(face).get());
    if (it == region_of.end()) return "";
    return absl::StrCat("region ", it->second, " ", SurfaceTypeName(regions[it->second].type));
  };
  const std::string product = params.product_name.empty() ? mesh.name : params.product_name;
  MESHSEG_RETURN_IF_ERROR(
      brep_internal::WriteStepFile(shape.shape, face_name, params.length_unit, product, path));
  report.length_unit = params.length_unit;
  // What was written is what a reader sees: the file read back must be as
  // valid, closed and solid as the shape in memory (the reader rebuilds the
  // edges' parameter-plane curves, where a wire can come out
  // self-intersecting), and its solids must enclose positive volume (a
  // solid's orientation is not in the file: its faces must face outward).
  MESHSEG_ASSIGN_OR_RETURN(const brep_internal::ReadBackFacts back,
                           brep_internal::ReadBack(path, params.length_unit));
  report.valid = report.valid && back.valid && back.faces == report.face_count &&
                 (back.solids == 0 || back.volume > 0.0);
  report.closed = report.closed && back.free_edges == 0;
  report.solid = report.solid && back.solids == report.solid_count;
  report.solid_count = back.solids;
  report.volume = back.volume;
  std::error_code error;
  report.step_size = static_cast<int64_t>(std::filesystem::file_size(path, error));
  ctx.Progress(kStage, 1.0);
  return report;
}

}  // namespace

absl::StatusOr<BrepReport> WriteStep(const Mesh& mesh, std::span<const int> face_labels,
                                     std::span<const Region> regions, const Topology& topology,
                                     const std::string& path, const BrepParams& params,
                                     const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  MESHSEG_RETURN_IF_ERROR(ValidateInput(mesh, face_labels, regions, topology));
  try {
    return Build(mesh, face_labels, regions, topology, path, params, ctx);
  } catch (const Standard_Failure& e) {
    return absl::InternalError(absl::StrCat("brep: OpenCASCADE failed: ", e.GetMessageString()));
  }
}

std::string CanonicalLengthUnit(std::string_view unit) {
  std::string lower(unit);
  if (brep_internal::StepUnitName(lower).empty()) return "";
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

std::string LengthUnitList() { return brep_internal::StepUnitList(); }

}  // namespace meshseg
