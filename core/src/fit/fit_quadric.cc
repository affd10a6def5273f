// General quadric fit, seed 000 eq. (8): minimise
//   E = Σ f(v_i)² + λ Σ |n_i − ∇f(v_i)|²,
// linear in the 10 coefficients. λ = total area (sum of the weights) or,
// without weights, s² with s the RMS distance of the points from their
// centroid, so that both terms have the units of length². Solved on centred
// and scaled points (pseudo-inverse: a planar region leaves (n·x + d)² free and
// gets the minimum-norm answer).
//
// Eq. (8) asks for |∇f| = 1 at every point, which only planes, spheres and
// cylinders allow, so it is biased on ellipsoids and cones. With
// params.refine the fit is solved again asking only for ∇f ∥ n:
//   min Σ f² + λ Σ |(I − n nᵀ) ∇f|²  subject to  Σ |∇f|² = const,
// a 9x9 generalised eigenproblem (the constant term eliminated), which is
// exact on noise-free samples of any quadric; the one of the two with the
// smaller geometric rms distance is kept. The result is scaled so the mean
// |∇f| over the points is 1 (f ≈ signed distance near the data) and ∇f points
// along the given normals.
#include <cmath>

#include <Eigen/Eigenvalues>

#include "fit/fit_internal.h"
#include "fit/project_quadric.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

using Vec10 = Eigen::Matrix<double, 10, 1>;
using Mat10 = Eigen::Matrix<double, 10, 10>;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;
using Grad = Eigen::Matrix<double, 3, 10>;

constexpr double kCollinearRatio = 1e-12;
constexpr double kPseudoInverseRatio = 1e-12;  // eigenvalues below (relative) are dropped
constexpr double kRegularisation = 1e-12;      // relative ridge on Σ |∇f|² (keeps it definite)

// Points in the scaled frame y = (v − centroid) / s, and λ / s².
struct Frame {
  Eigen::Vector3d centroid;
  double s = 1.0;
  double lambda = 1.0;
  Eigen::Vector3d Scaled(const Eigen::Vector3d& v) const { return (v - centroid) / s; }
};

// Monomials of seed 000 eq. (7) and their gradients.
void Monomials(const Eigen::Vector3d& p, Vec10* phi, Grad* grad) {
  const double x = p.x(), y = p.y(), z = p.z();
  *phi << x * x, y * y, z * z, x * y, y * z, z * x, x, y, z, 1.0;
  *grad << 2 * x, 0, 0, y, 0, z, 1, 0, 0, 0,
           0, 2 * y, 0, x, z, 0, 0, 1, 0, 0,
           0, 0, 2 * z, 0, y, x, 0, 0, 1, 0;
}

// Eq. (8) by pseudo-inverse of its normal equations.
Vec10 SolveUnitGradient(const FitInput& input, const Frame& f) {
  Mat10 m = Mat10::Zero();
  Vec10 rhs = Vec10::Zero();
  Vec10 phi;
  Grad grad;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    Monomials(f.Scaled(input.points[i]), &phi, &grad);
    m.noalias() += phi * phi.transpose();
    m.noalias() += f.lambda * grad.transpose() * grad;
    rhs.noalias() += f.lambda * grad.transpose() * input.normals[i];
  }
  Eigen::SelfAdjointEigenSolver<Mat10> solver(m);
  const Vec10 ev = solver.eigenvalues();
  Vec10 inv = Vec10::Zero();
  for (int k = 0; k < 10; ++k) {
    if (ev(k) > kPseudoInverseRatio * ev(9)) inv(k) = 1.0 / ev(k);
  }
  return solver.eigenvectors() * (inv.asDiagonal() * (solver.eigenvectors().transpose() * rhs));
}

// The ∇f ∥ n variant; false if the eigenproblem fails.
bool SolveParallelGradient(const FitInput& input, const Frame& f, Vec10* k) {
  const double count = static_cast<double>(input.points.size());
  Vec10 phi;
  Grad grad;
  Vec9 mean_phi = Vec9::Zero();
  for (const Eigen::Vector3d& p : input.points) {
    Monomials(f.Scaled(p), &phi, &grad);
    mean_phi += phi.head<9>();
  }
  mean_phi /= count;
  Mat9 value = Mat9::Zero();  // Σ f² with the optimal constant term
  Mat9 norm = Mat9::Zero();   // Σ |∇f|²
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    Monomials(f.Scaled(input.points[i]), &phi, &grad);
    const Vec9 d = phi.head<9>() - mean_phi;
    const Eigen::Matrix<double, 3, 9> g = grad.leftCols<9>();
    const Eigen::Vector3d& n = input.normals[i];
    const Eigen::Matrix3d tangential = Eigen::Matrix3d::Identity() - n * n.transpose();
    value.noalias() += d * d.transpose();
    value.noalias() += f.lambda * g.transpose() * tangential * g;
    norm.noalias() += g.transpose() * g;
  }
  norm.diagonal().array() += kRegularisation * norm.trace() / 9.0;
  Eigen::GeneralizedSelfAdjointEigenSolver<Mat9> solver(value, norm);
  if (solver.info() != Eigen::Success) return false;
  const Vec9 c = solver.eigenvectors().col(0);
  *k << c, -mean_phi.dot(c);
  return k->allFinite();
}

// The world-frame quadric f(x) = s f̃((x − c) / s), scaled to mean |∇f| = 1
// over the points and oriented along the normals; false if not finite.
bool ToWorld(const Vec10& k, const Frame& f, const FitInput& input, Quadric* q) {
  Eigen::Matrix3d a;
  a << k(0), 0.5 * k(3), 0.5 * k(5),
       0.5 * k(3), k(1), 0.5 * k(4),
       0.5 * k(5), 0.5 * k(4), k(2);
  const Eigen::Vector3d b(k(6), k(7), k(8));
  const Eigen::Matrix3d aw = a / f.s;
  const Eigen::Vector3d bw = b - 2.0 * aw * f.centroid;
  const double cw = f.centroid.dot(aw * f.centroid) - b.dot(f.centroid) + f.s * k(9);
  q->c = {aw(0, 0), aw(1, 1), aw(2, 2), 2 * aw(0, 1), 2 * aw(1, 2), 2 * aw(0, 2),
          bw.x(), bw.y(), bw.z(), cw};
  double sum_norm = 0.0;
  double sum_along = 0.0;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    const Eigen::Vector3d g = fit_internal::QuadricGradient(*q, input.points[i]);
    sum_norm += g.norm();
    sum_along += g.dot(input.normals[i]);
  }
  const double scale = (sum_along < 0.0 ? -1.0 : 1.0) * static_cast<double>(input.points.size()) / sum_norm;
  if (!std::isfinite(scale) || !(sum_norm > 0.0)) return false;
  for (double& c : q->c) c *= scale;
  for (double c : q->c) {
    if (!std::isfinite(c)) return false;
  }
  return true;
}

}  // namespace

FitResult FitQuadric(const FitInput& input, const FitParams& params) {
  using namespace fit_internal;
  if (input.points.size() < 10 || !HasNormals(input)) return InvalidResult(Quadric{});
  const Moments m = PointMoments(input);
  if (!(m.weight_sum > 0.0)) return InvalidResult(Quadric{});
  const Eigen3 pca = SymmetricEigen(m.scatter);
  if (!(pca.values(1) > kCollinearRatio * pca.values(2))) return InvalidResult(Quadric{});
  Frame frame;
  frame.centroid = m.centroid;
  frame.s = std::sqrt(pca.values.sum() / m.weight_sum);
  frame.lambda = input.weights.empty() ? 1.0 : m.weight_sum / (frame.s * frame.s);

  FitResult r;
  Quadric q;
  if (!ToWorld(SolveUnitGradient(input, frame), frame, input, &q)) return InvalidResult(Quadric{});
  r.surface = q;
  r.valid = true;
  SetDistanceErrors(input, &r);
  Vec10 k;
  if (params.refine && SolveParallelGradient(input, frame, &k) && ToWorld(k, frame, input, &q)) {
    FitResult refined;
    refined.surface = q;
    refined.valid = true;
    refined.iterations = 1;
    SetDistanceErrors(input, &refined);
    if (refined.rms_distance <= r.rms_distance) r = refined;
  }
  return r;
}

}  // namespace meshseg
