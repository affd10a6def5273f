#include "subdiv/fit_control_points.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "meshseg/status_macros.h"
#include "subdiv/control_topology.h"
#include "subdiv/data_guard.h"
#include "subdiv/footpoints.h"
#include "subdiv/normal_equations.h"
#include "subdiv/solve_normal_equations.h"

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
                                            double tangent_weight, double guard_fraction,
                                            const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(const ControlTopology topo, BuildControlTopology(control));
  ControlFit fit;
  MESHSEG_ASSIGN_OR_RETURN(fit.limit, SampleLimitSurface(control, level));
  const int n = static_cast<int>(control.vertices.size());
  const ColMatrix g = EdgeDifferences(topo, n);
  const ColMatrix membrane =
      (smoothing_weight / std::max<size_t>(1, topo.edges.size())) * ColMatrix(g.transpose() * g);
  const double data_weight = 1.0 / std::max<size_t>(1, data.size());
  fit.vertices = control.vertices;
  const ColMatrix umbrella = UmbrellaOperator(topo, n);
  Eigen::VectorXd prior(3 * n);
  for (int v = 0; v < n; ++v) prior.segment<3>(3 * v) = control.vertices[v];
  const NormalAssembler assembler(fit.limit);
  std::vector<FootPoint> feet = FootPoints(fit.limit.mesh.vertices, fit.limit.mesh.faces, data);
  Distances dist = Measure(feet);
  fit.rms_per_round.push_back(dist.rms);
  for (int round = 0; round < rounds; ++round) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("subdiv"));
    const NormalEquations eq = assembler.Assemble(fit.limit, feet, data, tangent_weight);
    const ColMatrix data_normal = data_weight * eq.ata;
    const GuardTerm guard = DataGuard(umbrella, data_normal, prior, guard_fraction);
    fit.guarded_per_round.push_back(guard.guarded);
    const ColMatrix normal = data_normal + membrane + guard.matrix;
    Eigen::VectorXd guess(3 * n);
    for (int v = 0; v < n; ++v) guess.segment<3>(3 * v) = fit.vertices[v];
    MESHSEG_ASSIGN_OR_RETURN(
        const NormalSolution solution,
        SolveNormalEquations(normal, data_weight * eq.atb + guard.rhs, guess, round));
    for (int v = 0; v < n; ++v) fit.vertices[v] = solution.p.segment<3>(3 * v);
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
