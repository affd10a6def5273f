#include "segment/fit_exclusion.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace meshseg::segment_internal {
namespace {

// Rounding margins: the bound is taken this much larger, and the matrix's
// diagonal lowered by this share of its size, so that positive definite in
// floating point is positive definite in exact numbers (forming M and its
// Cholesky factor are backward stable to a few units of 1e-16 of ||M||).
constexpr double kBoundMargin = 1e-6;
constexpr double kRoundingShare = 1e-10;
// An axis known to no better than this (sine of the angle) is not used.
constexpr double kMaxAxisSine = 0.5;
// Normals are unit to rounding: |n . a| is taken this much larger.
constexpr double kTiltRounding = 1e-12;
// The centred and scaled coordinates (|q| <= 1) round by a few units of
// 1e-16: tau is taken this much larger in that scale.
constexpr double kCoordinateRounding = 1e-15;
// The cone proof's shares of H's least and second eigenvalue (the line of
// u is verified, not assumed: these only leave room for rounding).
constexpr double kKappaShare = 1.1;
// Steps of inverse iteration for H's least and second eigenvector: each
// shrinks the others by their ratio to it (below 1/5 where a proof holds).
constexpr int kInverseIterations = 5;
constexpr double kLambdaShare = 0.9;
// Eigenvalues of a 3x3 matrix are computed within a few units of 1e-16 of
// its largest: taken this much of it wider.
constexpr double kAxisRounding = 1e-12;
// The cone proof's own rounding margin: this many units of rounding per
// term summed (fit_exclusion.cc: ExcludeAxialUncached).
constexpr double kRoundingUnits = 16.0;
constexpr double kUnitRoundoff = 0x1p-53;

// The points centred on their mean and scaled to a largest distance of 1,
// and tau in that scale; false for fewer than 5 points (a sphere's 4
// parameters fit 4 points whatever they are) or no spread.
bool Centre(std::span<const Eigen::Vector3d> points, double tau, std::vector<Eigen::Vector3d>* q,
            double* scaled_tau) {
  if (points.size() < 5) return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  double scale = 0.0;
  for (const Eigen::Vector3d& p : points) scale = std::max(scale, (p - mean).norm());
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  q->resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) (*q)[i] = (points[i] - mean) / scale;
  *scaled_tau = tau / scale + kCoordinateRounding;
  return std::isfinite(*scaled_tau);
}

// Two of `v` far apart (the farthest from the first, and the farthest from
// that one): their distance is a lower bound of the set's diameter.
std::pair<int, int> FarPair(const std::vector<Eigen::Vector3d>& v) {
  auto farthest = [&](int from) {
    int best = from;
    double best_distance = -1.0;
    for (int k = 0; k < static_cast<int>(v.size()); ++k) {
      const double d = (v[k] - v[from]).squaredNorm();
      if (d > best_distance) best_distance = d, best = k;
    }
    return best;
  };
  const int i = farthest(0);
  return {i, farthest(i)};
}

// True if M - mu B is positive definite (fit_exclusion.h), M = sum z z^T
// over z = (square_i, q_i, 1), B the form |b|^2 - 4 alpha g of Pratt's
// normalisation, mu = N eps^2 / 4: no (alpha, b, g) with x^T B x = 4 has
// |Q(q_i)| <= eps at every point.
bool PrattExcludes(const std::vector<Eigen::Vector3d>& q, const std::vector<double>& square,
                   double eps) {
  Eigen::Matrix<double, 5, 5> m = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> z;
  for (std::size_t i = 0; i < q.size(); ++i) {
    z << square[i], q[i], 1.0;
    m.noalias() += z * z.transpose();
  }
  const double mu = (1.0 + kBoundMargin) * static_cast<double>(q.size()) * eps * eps / 4.0;
  if (!std::isfinite(mu)) return false;
  m.diagonal().array() -= kRoundingShare * (m.trace() + 3.0 * mu);
  for (int k = 1; k <= 3; ++k) m(k, k) -= mu;
  m(0, 4) += 2.0 * mu;
  m(4, 0) += 2.0 * mu;
  return Eigen::LLT<Eigen::Matrix<double, 5, 5>>(m).info() == Eigen::Success;
}

using Matrix10 = Eigen::Matrix<double, 10, 10>;
using Vector10 = Eigen::Matrix<double, 10, 1>;

// H = M - (2 t^2 K + 18 N t^4 E) (fit_exclusion.h: NoQuadricWithin) over
// the coefficients x = (a11, a22, a33, a12, a13, a23, b1, b2, b3, c) of
// Q(p) = p^T A p + b . p + c: the quadric of x passes within t of every
// point of q only if x^T H x <= 0. `size` = trace(H) + 2 trace(bound) (at
// least trace(M)) is the scale of H's rounding. False for fewer than 10
// points (a quadric fits 9 whatever they are).
bool QuadricForm(const std::vector<Eigen::Vector3d>& q, double t, Matrix10* h, double* size) {
  if (q.size() < 10) return false;
  Matrix10 m = Matrix10::Zero(), k = Matrix10::Zero();
  Vector10 z;
  // The gradient 2 A p + b by x: along axis i, 2 p_i at a_ii, 2 p_j at the
  // a_ij of each other axis j, 1 at b_i; K sums the outer products of those
  // four entries.
  constexpr int kDiagonal[3] = {0, 1, 2}, kLinear[3] = {6, 7, 8};
  constexpr int kCross[3][2] = {{3, 4}, {3, 5}, {4, 5}};  // a_ij of the other axes j
  constexpr int kOther[3][2] = {{1, 2}, {0, 2}, {0, 1}};
  for (const Eigen::Vector3d& p : q) {
    z << p.x() * p.x(), p.y() * p.y(), p.z() * p.z(), 2.0 * p.x() * p.y(), 2.0 * p.x() * p.z(),
        2.0 * p.y() * p.z(), p.x(), p.y(), p.z(), 1.0;
    m.noalias() += z * z.transpose();
    for (int i = 0; i < 3; ++i) {
      const int at[4] = {kDiagonal[i], kCross[i][0], kCross[i][1], kLinear[i]};
      const double value[4] = {2.0 * p(i), 2.0 * p(kOther[i][0]), 2.0 * p(kOther[i][1]), 1.0};
      for (int a = 0; a < 4; ++a) {
        for (int b = 0; b < 4; ++b) k(at[a], at[b]) += value[a] * value[b];
      }
    }
  }
  Vector10 frobenius;  // x^T diag(frobenius) x = |A|_F^2
  frobenius << 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 0.0, 0.0, 0.0, 0.0;
  const double n = static_cast<double>(q.size());
  Matrix10 bound = 2.0 * t * t * k;
  bound.diagonal() += 18.0 * n * t * t * t * t * frobenius;
  bound *= 1.0 + kBoundMargin;
  if (!bound.allFinite()) return false;
  *h = m - bound;
  *size = h->trace() + 2.0 * bound.trace();
  return std::isfinite(*size);
}

// True if H, its diagonal lowered by the rounding share of `size`, is
// positive definite (as NoQuadricWithin always decided).
bool PositiveWithMargin(Matrix10 h, double size) {
  h.diagonal().array() -= kRoundingShare * size;
  return Eigen::LLT<Matrix10>(h).info() == Eigen::Success;
}

// The eigenvalue of symmetric `h` nearest 0, and its unit eigenvector in
// `u`, by inverse iteration from the all-ones vector (its Rayleigh
// quotient; not exact, a choice for the proof that verifies it).
double NearestToZero(const Matrix10& h, Vector10* u) {
  const Eigen::LDLT<Matrix10> ldlt(h);
  *u = Vector10::Ones().normalized();
  for (int k = 0; k < kInverseIterations; ++k) {
    const Vector10 next = ldlt.solve(*u);
    const double length = next.norm();
    if (!(length > 0.0) || !std::isfinite(length)) break;
    *u = next / length;
  }
  return u->dot(h * *u);
}

AxialExclusion ExcludeAxialUncached(std::span<const Eigen::Vector3d> points, double tau) {
  std::vector<Eigen::Vector3d> q;
  double t = 0.0;
  Matrix10 h;
  double size = 0.0;
  if (!Centre(points, tau, &q, &t) || !QuadricForm(q, t, &h, &size)) return {};
  if (PositiveWithMargin(h, size)) return {.cylinder = true, .cone = true};
  // Rounding of forming H (each entry a sum of N terms of size at most
  // trace(M)'s share, error gamma_N) and of a 10 x 10 Cholesky: a margin of
  // its size, far below the 1e-10 share above, which would drown H's least
  // eigenvalue (the pair of planes, t^2 small).
  const double rounding =
      kRoundingUnits * static_cast<double>(q.size() + 20) * kUnitRoundoff * size;
  // (1) Every fitting x lies near the line of u, H's least eigenvector: if
  // H - lambda (I - u u^T) + kappa u u^T is positive definite, x = s u + y
  // (y across u) with x^T H x <= 0 has lambda |y|^2 < kappa s^2.
  // u and the two eigenvalues by inverse iteration (H is nearly singular
  // along u, and then, u moved away, along the second): only choices, the
  // Cholesky below decides.
  Vector10 u;
  const double least = NearestToZero(h, &u);
  Vector10 v;
  const double second = NearestToZero(h + std::abs(h.trace()) * u * u.transpose(), &v);
  if (!(second > 0.0) || !std::isfinite(least)) return {};  // two quadrics come near
  const double kappa = kKappaShare * std::abs(least) + 2.0 * rounding;
  const double lambda = kLambdaShare * second;
  Matrix10 g = h + (kappa + lambda) * u * u.transpose();
  g.diagonal().array() -= lambda + rounding;
  if (Eigen::LLT<Matrix10>(g).info() != Eigen::Success) return {};
  // With s = 1: |y| <= sqrt(kappa / lambda), and x's A differs from u's
  // by at most sqrt(2) |y| (|A|_F^2 <= 2 |x_A|^2) in the 2-norm.
  const double e = (1.0 + kBoundMargin) * std::sqrt(2.0 * kappa / lambda);
  Eigen::Matrix3d a;
  a << u(0), u(3), u(4), u(3), u(1), u(5), u(4), u(5), u(2);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(a);
  Eigen::Vector3d mu = axes.eigenvalues();  // ascending
  int big = 2;
  if (std::abs(mu(0)) > std::abs(mu(2))) mu = -mu, big = 0;  // x and -x are one quadric
  const Eigen::Vector3d n = axes.eigenvectors().col(big);
  const double top = (1.0 - kAxisRounding) * mu(big);
  const double eta = std::max(std::abs(mu(1)), std::abs(mu(2 - big))) + kAxisRounding * top;
  // (2) Weyl: x's A has eigenvalues within e of u's (top, and two within eta
  // of 0). A cone's A is sigma (I - k a a^T), k = 1 / cos^2(half angle),
  // eigenvalues sigma, sigma, sigma (1 - k); a cylinder's has k = 1. With
  // sigma >= 0 the double eigenvalue would be within e of both top and
  // eta: no such A when top > eta + 2 e.
  if (!(top > eta + 2.0 * e)) return {};
  // With sigma < 0: |sigma| <= eta + e and |sigma| (k - 1) >= top - e, so
  // a cylinder (k = 1) is excluded, and a cone has cot^2(half angle) =
  // 1 / (k - 1) <= (eta + e) / (top - e): nearly flat. Its axis is the
  // eigenvector of |sigma| (k - 1), within angle w of n with sin w <= e /
  // (top - e - eta) (Davis-Kahan: u's other eigenvalues are at least that
  // far from it).
  const double flat = std::sqrt((eta + e) / (top - e));
  const double sine = e / (top - e - eta) + kAxisRounding;
  if (!(sine < 1.0)) return {.cylinder = true};
  // (3) One nappe of a cone of axis a and cot(half angle) = delta is a graph
  // h = delta rho over the plane across a (h along a, rho from the axis),
  // with |h(f) - h(g)| <= delta |f - g| for any two of its points f, g.
  // Two points within t of it then have |a . (p - q)| <= delta |p - q| + 2
  // t (1 + delta). The two points farthest apart along n break that when a
  // is within angle w of n: a nearly flat cone about n reaches no two
  // parallel rims (a double cone does, one nappe each).
  const auto [lo, hi] = std::minmax_element(
      q.begin(), q.end(),
      [&](const Eigen::Vector3d& x, const Eigen::Vector3d& y) { return x.dot(n) < y.dot(n); });
  const Eigen::Vector3d d = *hi - *lo;
  const double along = std::abs(d.dot(n));
  const double across = (d - d.dot(n) * n).norm();
  const double least_along = along * std::sqrt(1.0 - sine * sine) - across * sine;
  const double most_along = (1.0 + kBoundMargin) * (flat * d.norm() + 2.0 * t * (1.0 + flat));
  return {.cylinder = true, .cone = least_along > most_along};
}

}  // namespace

bool NoQuadricWithin(std::span<const Eigen::Vector3d> points, double tau) {
  std::vector<Eigen::Vector3d> q;
  double t = 0.0;
  Matrix10 h;
  double size = 0.0;
  return Centre(points, tau, &q, &t) && QuadricForm(q, t, &h, &size) && PositiveWithMargin(h, size);
}

AxialExclusion ExcludeAxial(std::span<const Eigen::Vector3d> points, double tau) {
  // One analysis per point set and thread: a seed group's corners are
  // asked about as a cylinder, then as a cone.
  thread_local std::vector<Eigen::Vector3d> last_points;
  thread_local double last_tau = 0.0;
  thread_local AxialExclusion last;
  if (tau == last_tau &&
      std::equal(points.begin(), points.end(), last_points.begin(), last_points.end())) {
    return last;
  }
  last = ExcludeAxialUncached(points, tau);
  last_points.assign(points.begin(), points.end());
  last_tau = tau;
  return last;
}

bool NoSphereWithin(std::span<const Eigen::Vector3d> points, double tau) {
  std::vector<Eigen::Vector3d> q;
  double t = 0.0;
  if (!Centre(points, tau, &q, &t)) return false;
  // Every point lies within R + t of the centre: R >= (diameter) / 2 - t.
  const auto [i, j] = FarPair(q);
  const double r_min = 0.5 * (q[i] - q[j]).norm() - t;
  if (!(r_min > 0.0)) return false;
  std::vector<double> square(q.size());
  for (std::size_t k = 0; k < q.size(); ++k) square[k] = q[k].squaredNorm();
  return PrattExcludes(q, square, 2.0 * t + t * t / r_min);
}

bool NoCylinderWithin(std::span<const Eigen::Vector3d> points,
                      std::span<const Eigen::Vector3d> normals, double max_tilt, double tau) {
  // The axis a is within angle w of e = n1 x n2 for two normals n1, n2 of
  // `normals` as far apart as they go: its part b across e lies in their
  // plane with |n1 . b|, |n2 . b| <= max_tilt, so sin(w) = |b| <=
  // max_tilt sqrt(2 / (1 - |n1 . n2|)) (the least eigenvalue of their Gram
  // matrix is 1 - |n1 . n2|).
  auto first = std::find_if(normals.begin(), normals.end(),
                            [](const Eigen::Vector3d& n) { return n.norm() > 0.5; });
  if (first == normals.end()) return false;
  const Eigen::Vector3d n1 = first->normalized();
  Eigen::Vector3d n2 = n1;
  double widest = 0.0;
  for (const Eigen::Vector3d& n : normals) {
    if (!(n.norm() > 0.5)) continue;
    const double across = n1.cross(n.normalized()).norm();
    if (across > widest) widest = across, n2 = n.normalized();
  }
  const double gram = 1.0 - std::abs(n1.dot(n2));
  if (!(gram > 0.0)) return false;
  const double tilt = (max_tilt + kTiltRounding) / (1.0 - kTiltRounding);
  const double sine = tilt * std::sqrt(2.0 / gram);
  if (!(sine < kMaxAxisSine)) return false;
  const Eigen::Vector3d e = n1.cross(n2).normalized();

  std::vector<Eigen::Vector3d> q;
  double t = 0.0;
  if (!Centre(points, tau, &q, &t)) return false;
  std::vector<Eigen::Vector3d> across(q.size());
  std::vector<double> square(q.size());
  // The largest | |P_e q|^2 - |P_a q|^2 | over the points (fit_exclusion.h).
  // With sin w <= sine: 1 - cos w <= sine^2 / (1 + sqrt(1 - sine^2)), 1 + cos w <= 2.
  const double versine = sine * sine / (1.0 + std::sqrt(1.0 - sine * sine));
  double turn = 0.0;
  for (std::size_t k = 0; k < q.size(); ++k) {
    const double along = std::abs(q[k].dot(e));
    across[k] = q[k] - q[k].dot(e) * e;
    square[k] = across[k].squaredNorm();
    const double off = sine * across[k].norm();
    turn = std::max(turn, (versine * along + off) * (2.0 * along + off));
  }
  // Every point lies within R + t of the axis; across e, distances grow by
  // at most sin(w) of the points' own: R >= (|P_e (q_i - q_j)| - sin(w)
  // |q_i - q_j|) / 2 - t.
  const auto [i, j] = FarPair(across);
  const double r_min = 0.5 * ((across[i] - across[j]).norm() - sine * (q[i] - q[j]).norm()) - t;
  if (!(r_min > 0.0)) return false;
  return PrattExcludes(q, square, 2.0 * t + (t * t + turn) / r_min);
}

}  // namespace meshseg::segment_internal
