#include "subdiv/fit_control_points.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "subdiv/control_topology.h"
#include "subdiv/footpoints.h"
#include "subdiv/normal_equations.h"

namespace meshseg::subdiv_internal {
namespace {

using ColMatrix = Eigen::SparseMatrix<double>;

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

// Conjugate gradients stop at this residual relative to the right-hand side
// (about 25 iterations per decade on a 10,000-vertex control mesh; at 1e-6
// the rms per round already agrees with a direct solve to four digits).
constexpr double kSolveTolerance = 1e-8;
constexpr int kMaxSolveIterations = 2000;

// Returns the solution of normal * p = rhs: conjugate gradients with a
// diagonal (Jacobi) preconditioner started from the current control
// vertices, which the previous round (or the quasi-interpolation) left close
// to the solution: a few dozen products with the matrix instead of a
// Cholesky factorisation whose fill-in grows with the control mesh. A system
// that does not converge in kMaxSolveIterations is factored (SimplicialLDLT).
absl::StatusOr<Eigen::VectorXd> Solve(const ColMatrix& normal, const Eigen::VectorXd& rhs,
                                      const std::vector<Eigen::Vector3d>& start, int round) {
  Eigen::VectorXd guess(3 * start.size());
  for (size_t v = 0; v < start.size(); ++v) guess.segment<3>(3 * v) = start[v];
  Eigen::ConjugateGradient<ColMatrix, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(kSolveTolerance);
  cg.setMaxIterations(kMaxSolveIterations);
  cg.compute(normal);
  Eigen::VectorXd p = cg.solveWithGuess(rhs, guess);
  if (cg.info() != Eigen::Success || !p.allFinite()) {
    Eigen::SimplicialLDLT<ColMatrix> ldlt(normal);
    if (ldlt.info() != Eigen::Success) {
      return absl::InternalError(absl::StrCat("subdiv: the least-squares system of ", start.size(),
                                              " control vertices cannot be factored"));
    }
    p = ldlt.solve(rhs);
  }
  if (!p.allFinite()) {
    return absl::InternalError(
        absl::StrCat("subdiv: the least-squares solve failed in round ", round + 1));
  }
  return p;
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
  const NormalAssembler assembler(fit.limit);
  std::vector<FootPoint> feet = FootPoints(fit.limit.mesh.vertices, fit.limit.mesh.faces, data);
  Distances dist = Measure(feet);
  fit.rms_per_round.push_back(dist.rms);
  for (int round = 0; round < rounds; ++round) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("subdiv"));
    const NormalEquations eq = assembler.Assemble(fit.limit, feet, data, tangent_weight);
    const ColMatrix normal = data_weight * eq.ata + membrane;
    MESHSEG_ASSIGN_OR_RETURN(const Eigen::VectorXd p,
                             Solve(normal, data_weight * eq.atb, fit.vertices, round));
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
