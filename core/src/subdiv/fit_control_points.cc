#include "subdiv/fit_control_points.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "subdiv/control_topology.h"
#include "subdiv/footpoints.h"

namespace meshseg::subdiv_internal {
namespace {

using ColMatrix = Eigen::SparseMatrix<double>;

// The least-squares rows of one round, in the 3m unknowns (x, y, z of each
// control vertex in turn). Per data point d with footpoint row r (the
// barycentric combination of the limit operator's rows of its face) and the
// face's unit normal n: the normal distance n . (r P - d), and sqrt(alpha)
// times the full offset r P - d. Minimising squared normal distances
// (point-to-plane) lets the surface slide along itself, so the footpoint
// rounds converge in a few steps where point-to-point needs dozens; the
// small tangential term keeps the system definite (Pottmann et al. 2006,
// squared-distance minimisation).
struct Rows {
  ColMatrix a;
  Eigen::VectorXd rhs;
};

// Rows of the data points [begin, end).
Rows FootpointRows(const LimitSurface& limit, const std::vector<FootPoint>& feet,
                   const std::vector<Eigen::Vector3d>& data, double alpha, size_t begin,
                   size_t end) {
  std::vector<Eigen::Triplet<double>> w;
  w.reserve((end - begin) * 36 * 6);
  Rows rows;
  rows.rhs.resize(4 * (end - begin));
  const double ta = std::sqrt(alpha);
  for (size_t i = begin; i < end; ++i) {
    const auto& t = limit.mesh.faces[feet[i].face];
    const auto& x = limit.mesh.vertices;
    Eigen::Vector3d normal = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
    const double area2 = normal.norm();
    normal = area2 > 0.0 ? Eigen::Vector3d(normal / area2) : Eigen::Vector3d::Zero();
    const double tw = area2 > 0.0 ? ta : 1.0;  // a degenerate face: point-to-point
    const int row = static_cast<int>(4 * (i - begin));
    for (int c = 0; c < 3; ++c) {
      for (SparseMatrix::InnerIterator it(limit.from_control, t[c]); it; ++it) {
        const double r = feet[i].barycentric[c] * it.value();
        const int col = 3 * static_cast<int>(it.col());
        for (int k = 0; k < 3; ++k) {
          if (normal[k] != 0.0) w.emplace_back(row, col + k, r * normal[k]);
          w.emplace_back(row + 1 + k, col + k, tw * r);
        }
      }
    }
    rows.rhs[row] = normal.dot(data[i]);
    for (int k = 0; k < 3; ++k) rows.rhs[row + 1 + k] = tw * data[i][k];
  }
  rows.a.resize(4 * (end - begin), 3 * limit.from_control.cols());
  rows.a.setFromTriplets(w.begin(), w.end());
  return rows;
}

// The normal equations A^T A, A^T b of all footpoint rows, summed over
// chunks of data points: the tall A (4 rows and about 150 non-zeros per
// point) of a million points would take gigabytes, its products with
// itself only the size of the control mesh's 2-ring stencil.
struct NormalEquations {
  ColMatrix ata;
  Eigen::VectorXd atb;
};

NormalEquations Normal(const LimitSurface& limit, const std::vector<FootPoint>& feet,
                       const std::vector<Eigen::Vector3d>& data, double alpha) {
  constexpr size_t kChunk = size_t{1} << 15;
  const Eigen::Index unknowns = 3 * limit.from_control.cols();
  NormalEquations out{ColMatrix(unknowns, unknowns), Eigen::VectorXd::Zero(unknowns)};
  for (size_t begin = 0; begin < feet.size(); begin += kChunk) {
    const Rows rows =
        FootpointRows(limit, feet, data, alpha, begin, std::min(feet.size(), begin + kChunk));
    const ColMatrix at = rows.a.transpose();
    out.ata += ColMatrix(at * rows.a);
    out.atb += at * rows.rhs;
  }
  return out;
}

// The membrane term's edge-difference operator of the control mesh, per
// coordinate.
ColMatrix EdgeDifferences(const ControlTopology& topo, int n) {
  std::vector<Eigen::Triplet<double>> w;
  for (size_t e = 0; e < topo.edges.size(); ++e) {
    for (int k = 0; k < 3; ++k) {
      w.emplace_back(static_cast<int>(3 * e + k), 3 * topo.edges[e][0] + k, 1.0);
      w.emplace_back(static_cast<int>(3 * e + k), 3 * topo.edges[e][1] + k, -1.0);
    }
  }
  ColMatrix g(3 * topo.edges.size(), 3 * n);
  g.setFromTriplets(w.begin(), w.end());
  return g;
}

struct Distances {
  double rms = 0.0;
  double max = 0.0;
};

Distances Measure(const std::vector<FootPoint>& feet) {
  Distances d;
  for (const FootPoint& f : feet) {
    d.rms += f.distance * f.distance;
    d.max = std::max(d.max, f.distance);
  }
  d.rms = std::sqrt(d.rms / std::max<size_t>(1, feet.size()));
  return d;
}

}  // namespace

std::vector<Eigen::Vector3d> QuasiInterpolate(const ControlMesh& control,
                                              const ControlTopology& topo) {
  const std::vector<Eigen::Vector3d> limit = Apply(LimitMasks(topo), control.vertices);
  std::vector<Eigen::Vector3d> out(control.vertices.size());
  for (size_t v = 0; v < out.size(); ++v) out[v] = 2.0 * control.vertices[v] - limit[v];
  return out;
}

absl::StatusOr<ControlFit> FitControlPoints(const ControlMesh& control,
                                            const std::vector<Eigen::Vector3d>& data, int level,
                                            int rounds, double smoothing_weight,
                                            double tangent_weight, const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(const ControlTopology topo, BuildControlTopology(control));
  ControlFit fit;
  MESHSEG_ASSIGN_OR_RETURN(fit.limit, SampleLimitSurface(control, level));
  const int n = static_cast<int>(control.vertices.size());
  const ColMatrix g = EdgeDifferences(topo, n);
  const ColMatrix membrane =
      (smoothing_weight / std::max<size_t>(1, topo.edges.size())) * ColMatrix(g.transpose() * g);
  const double data_weight = 1.0 / std::max<size_t>(1, data.size());
  fit.vertices = control.vertices;
  std::vector<FootPoint> feet = FootPoints(fit.limit.mesh.vertices, fit.limit.mesh.faces, data);
  Distances dist = Measure(feet);
  fit.rms_per_round.push_back(dist.rms);
  for (int round = 0; round < rounds; ++round) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("subdiv"));
    const NormalEquations eq = Normal(fit.limit, feet, data, tangent_weight);
    const ColMatrix normal = data_weight * eq.ata + membrane;
    Eigen::SimplicialLDLT<ColMatrix> solver(normal);
    if (solver.info() != Eigen::Success) {
      return absl::InternalError(absl::StrCat("subdiv: the least-squares system of ", n,
                                              " control vertices cannot be factored"));
    }
    const Eigen::VectorXd p = solver.solve(data_weight * eq.atb);
    if (solver.info() != Eigen::Success || !p.allFinite()) {
      return absl::InternalError(
          absl::StrCat("subdiv: the least-squares solve failed in round ", round + 1));
    }
    for (int v = 0; v < n; ++v) fit.vertices[v] = p.segment<3>(3 * v);
    fit.limit.mesh.vertices = Apply(fit.limit.from_control, fit.vertices);
    feet = FootPoints(fit.limit.mesh.vertices, fit.limit.mesh.faces, data);
    dist = Measure(feet);
    fit.rms_per_round.push_back(dist.rms);
    ctx.Progress("subdiv", 0.5 + 0.5 * (round + 1) / rounds);
  }
  fit.rms_distance = dist.rms;
  fit.max_distance = dist.max;
  return fit;
}

}  // namespace meshseg::subdiv_internal
