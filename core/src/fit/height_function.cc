// The local quadratic height function of seed 000 §2: weighted least squares
// in the frame (origin, u, w, normal) and the closest point on its graph.
#include <cmath>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "fit/fit_internal.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

// Smallest / largest eigenvalue ratio below which the 6x6 normal equations
// are treated as singular (points on a line, too few distinct points).
constexpr double kMinConditionRatio = 1e-10;

// Pivot ratio above which the pivoted LDLT alone decides. The normal
// matrix A = P^T L D L^T P is positive semidefinite and Eigen's LDLT pivots
// on the largest remaining diagonal, so |l_ij| <= 1; then
// |(L^-1)_ij| <= 2^(i-j-1) below the diagonal (Higham, Accuracy and
// Stability of Numerical Algorithms, 2002, ch. 8), so for 6x6
// ||L^-1||_2^2 <= ||L^-1||_F^2 <= 459 and ||L||_2^2 <= ||L||_F^2 <= 21.
// Hence lambda_max <= 21 max D and lambda_min >= min D / 459: a pivot ratio
// min D / max D above 9639 kMinConditionRatio guarantees the eigenvalue
// ratio passes. Conversely each pivot is a diagonal entry of a Schur
// complement, so lambda_min <= min D and lambda_max >= max D (the first
// pivot, A's largest diagonal): a pivot ratio at or below
// kMinConditionRatio guarantees it fails.
constexpr double kLdltDecidesRatio = 1e-6;
static_assert(kLdltDecidesRatio >= 21.0 * 459.0 * kMinConditionRatio);

// Solves the 6x6 normal equations `lower` x = b (lower triangle of a
// positive semidefinite matrix); false when the system is singular by the
// eigenvalue ratio test (kMinConditionRatio). Where the pivots say that
// test passes (condition number below 9639 / 1e-6 ~ 1e10), the pivoted LDLT
// solves it: backward stable like the eigen decomposition, so the two
// solutions agree to the system's rounding, at under half the cost. Where
// the pivots say it fails, the system is singular. In between, and on a
// negative pivot (only rounding of a near-singular matrix gives one), the
// eigenvalues decide and solve as before.
bool SolveNormalEquations(const Eigen::Matrix<double, 6, 6>& lower,
                          const Eigen::Matrix<double, 6, 1>& b, Eigen::Matrix<double, 6, 1>* x) {
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>, Eigen::Lower> ldlt(lower);
  if (ldlt.info() == Eigen::Success) {
    const auto d = ldlt.vectorD();
    const double max_d = d.maxCoeff();
    const double min_d = d.minCoeff();
    if (min_d > kLdltDecidesRatio * max_d) {
      *x = ldlt.solve(b);
      return x->allFinite();
    }
    if (!(min_d > kMinConditionRatio * max_d) && min_d >= 0.0) return false;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> solver(lower);
  if (solver.info() != Eigen::Success) return false;
  const auto& ev = solver.eigenvalues();
  if (!(ev(0) > kMinConditionRatio * ev(5))) return false;
  *x = solver.eigenvectors() *
       (ev.cwiseInverse().asDiagonal() * (solver.eigenvectors().transpose() * b));
  return x->allFinite();
}

double Height(const std::array<double, 6>& a, double u, double w) {
  return a[0] * u * u + a[1] * w * w + a[2] * u * w + a[3] * u + a[4] * w + a[5];
}

}  // namespace

bool HeightFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal, HeightFunction* h) {
  *h = HeightFunction{};
  h->origin = origin;
  const double nn = normal.norm();
  if (!(nn > 0.0) || !std::isfinite(nn)) return false;
  h->normal = normal / nn;
  h->u_axis = fit_internal::AnyPerpendicular(h->normal);
  h->w_axis = h->normal.cross(h->u_axis);
  return true;
}

void FitHeightInFrame(std::span<const Eigen::Vector3d> local, std::span<const double> weights,
                      HeightFunction* h) {
  h->a = {};
  h->valid = false;
  if (local.size() < 6) return;
  const bool weighted = weights.size() == local.size();

  // Scale u, w to unit RMS so the normal equations are well conditioned.
  double sum_w = 0.0;
  double sum_r2 = 0.0;
  for (std::size_t i = 0; i < local.size(); ++i) {
    const double wt = weighted ? weights[i] : 1.0;
    sum_w += wt;
    sum_r2 += wt * (local[i].x() * local[i].x() + local[i].y() * local[i].y());
  }
  if (!(sum_w > 0.0) || !(sum_r2 > 0.0)) return;
  const double s = std::sqrt(sum_r2 / sum_w);

  // Normal equations: only the lower triangle, which is all the solver
  // reads; each entry sums (wt phi_i) phi_j in point order. The entries are
  // summed two at a time in the lanes of a two-double vector (phi in pairs
  // (u^2, w^2), (uw, u), (w, 1)): a lane multiplies and adds exactly as a
  // scalar would, so every entry is the same sum, about a fifth faster
  // than one entry at a time.
  using Pair = double __attribute__((vector_size(16)));
  const Pair scale = {s, s};
  // Row i of the lower triangle in pairs: acc[i][p] holds entries
  // (i, 2p), (i, 2p + 1); the lane past the diagonal is never read.
  Pair acc[6][3] = {};
  Pair rhs[3] = {};
  for (std::size_t k = 0; k < local.size(); ++k) {
    const double wt = weighted ? weights[k] : 1.0;
    const Pair uw = Pair{local[k].x(), local[k].y()} / scale;
    const double u = uw[0];
    const double w = uw[1];
    const Pair phi[3] = {{u * u, w * w}, {u * w, u}, {w, 1.0}};
    const Pair weight = {wt, wt};
    const Pair wp[3] = {weight * phi[0], weight * phi[1], weight * phi[2]};
    const double wz = wt * local[k].z();
    const Pair z = {wz, wz};
    for (int i = 0; i < 6; ++i) {
      const double wpi = wp[i / 2][i % 2];
      const Pair row = {wpi, wpi};
      for (int p = 0; p <= i / 2; ++p) acc[i][p] += row * phi[p];
    }
    for (int p = 0; p < 3; ++p) rhs[p] += z * phi[p];
  }
  Eigen::Matrix<double, 6, 6> lower = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> b;
  for (int i = 0; i < 6; ++i) {
    b(i) = rhs[i / 2][i % 2];
    for (int j = 0; j <= i; ++j) lower(i, j) = acc[i][j / 2][j % 2];
  }
  Eigen::Matrix<double, 6, 1> x;
  if (!SolveNormalEquations(lower, b, &x)) return;
  const double s2 = s * s;
  h->a = {x(0) / s2, x(1) / s2, x(2) / s2, x(3) / s, x(4) / s, x(5)};
  h->valid = true;
}

HeightFunction FitHeightFunction(std::span<const Eigen::Vector3d> points,
                                 const Eigen::Vector3d& origin, const Eigen::Vector3d& normal,
                                 std::span<const double> weights) {
  HeightFunction h;
  h.origin = origin;
  if (points.size() < 6 || !HeightFrame(origin, normal, &h)) return h;
  std::vector<Eigen::Vector3d> local(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d d = points[i] - origin;
    local[i] = Eigen::Vector3d(d.dot(h.u_axis), d.dot(h.w_axis), d.dot(h.normal));
  }
  FitHeightInFrame(local, weights.size() == points.size() ? weights : std::span<const double>{},
                   &h);
  return h;
}

Projection Project(const HeightFunction& h, const Eigen::Vector3d& p) {
  constexpr int kCorrections = 2;
  const auto& a = h.a;
  const Eigen::Vector3d d = p - h.origin;
  const Eigen::Vector3d q(d.dot(h.u_axis), d.dot(h.w_axis), d.dot(h.normal));
  double u = q.x();
  double w = q.y();
  Eigen::Vector3d foot(u, w, Height(a, u, w));
  Eigen::Vector3d n_local = Eigen::Vector3d::UnitZ();
  for (int k = 0; k <= kCorrections; ++k) {
    const double hu = 2.0 * a[0] * u + a[2] * w + a[3];
    const double hw = 2.0 * a[1] * w + a[2] * u + a[4];
    n_local = Eigen::Vector3d(-hu, -hw, 1.0).normalized();
    if (k == kCorrections) break;
    // Project p onto the tangent plane at the foot, then back onto the graph.
    const Eigen::Vector3d on_tangent = q - (q - foot).dot(n_local) * n_local;
    u = on_tangent.x();
    w = on_tangent.y();
    foot = Eigen::Vector3d(u, w, Height(a, u, w));
  }
  Projection r;
  r.point = h.origin + foot.x() * h.u_axis + foot.y() * h.w_axis + foot.z() * h.normal;
  r.normal = n_local.x() * h.u_axis + n_local.y() * h.w_axis + n_local.z() * h.normal;
  r.distance = (q - foot).dot(n_local);
  return r;
}

}  // namespace meshseg
