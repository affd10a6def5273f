#include "brep/bspline_surface_fit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <BSplCLib.hxx>
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <math_Matrix.hxx>

#include "absl/strings/str_cat.h"
#include "brep/surface_query.h"
#include "meshseg/fit.h"

namespace meshseg::brep_internal {
namespace {

using Eigen::Vector3d;

constexpr int kDegree = 3;
// Knot spacing: at least this many l_avg (a span holds enough vertices to
// fix its control heights) and at most 1/kMaxSpans of the region's extent.
constexpr double kMinSpacing = 3.0;
constexpr int kMaxSpans = 24;
// The grid reaches this fraction of the extent (plus kMarginEdges l_avg)
// past the region.
constexpr double kMarginFraction = 0.1;
constexpr double kMarginEdges = 2.0;
// Share of face normals that must lie on the plane's outer side (cos > 0.1,
// i.e. within 84 degrees of its normal) for a height field.
constexpr double kHeightFieldShare = 0.95;
// Weight of the second-difference penalty relative to the data per control
// point.
constexpr double kSmoothing = 1e-3;

// One clamped uniform knot vector over [lo, hi] with `spans` spans.
struct Knots {
  double lo = 0.0;
  double hi = 1.0;
  int spans = 1;
  int count() const { return spans + kDegree; }  // control points
  double step() const { return (hi - lo) / spans; }
  TColStd_Array1OfReal Flat() const {
    TColStd_Array1OfReal flat(1, spans + 1 + 2 * kDegree);
    for (int i = 1; i <= flat.Length(); ++i) {
      const int k = std::clamp(i - 1 - kDegree, 0, spans);
      flat(i) = lo + k * step();
    }
    return flat;
  }
  // Greville abscissa of control point i (0-based): where it acts most.
  double Greville(int i) const {
    double sum = 0.0;
    for (int k = i + 1; k <= i + kDegree; ++k) sum += std::clamp(k - kDegree, 0, spans) * step();
    return lo + sum / kDegree;
  }
};

// The nonzero basis values at t: first index (0-based) and 4 values.
struct Basis {
  int first = 0;
  double value[kDegree + 1] = {};
};

Basis Evaluate(const TColStd_Array1OfReal& flat, double t) {
  math_Matrix m(1, 1, 1, kDegree + 1);
  int first = 0;
  BSplCLib::EvalBsplineBasis(0, kDegree + 1, flat, t, first, m);
  Basis b;
  b.first = first - 1;
  for (int k = 0; k <= kDegree; ++k) b.value[k] = m(1, k + 1);
  return b;
}

Knots KnotsOver(double lo, double hi, double spacing) {
  Knots k;
  k.lo = lo;
  k.hi = hi;
  k.spans = std::clamp(static_cast<int>(std::ceil((hi - lo) / spacing)), 1, kMaxSpans);
  return k;
}

}  // namespace

BsplineSurfaceFit FitBsplineSurface(const Region& region, const RegionSamples& samples,
                                    double l_avg, double noise_sigma) {
  BsplineSurfaceFit out;
  const std::vector<Vector3d>& raw = samples.points;
  if (raw.size() < 16) {
    out.failure = absl::StrCat("too few vertices (", raw.size(), ") for a B-spline surface");
    return out;
  }
  std::vector<Vector3d> points = raw;
  if (region.type == SurfaceType::kQuadric) {
    for (Vector3d& p : points) {
      const Projection q = Project(region.surface, p);
      if (std::abs(q.distance) <= 3.0 * noise_sigma + l_avg) p = q.point;
    }
  }
  Vector3d c = Vector3d::Zero();
  for (const Vector3d& p : points) c += p;
  c /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vector3d& p : points) cov += (p - c) * (p - c).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Vector3d n = eig.eigenvectors().col(0);
  Vector3d mean_normal = Vector3d::Zero();
  for (const Vector3d& fn : samples.face_normals) mean_normal += fn;
  if (n.dot(mean_normal) < 0.0) n = -n;
  int facing = 0;
  for (const Vector3d& fn : samples.face_normals) facing += fn.dot(n) > 0.1;
  if (facing < kHeightFieldShare * static_cast<double>(samples.face_normals.size())) {
    out.failure = "region turns by 90 degrees or more: not a height field over its plane";
    return out;
  }
  const Vector3d e1 = eig.eigenvectors().col(2);
  const Vector3d e2 = n.cross(e1);  // (e1, e2, n) right-handed: D1U x D1V = n

  double u_lo = 1e300, u_hi = -1e300, v_lo = 1e300, v_hi = -1e300;
  for (const Vector3d& p : points) {
    u_lo = std::min(u_lo, (p - c).dot(e1));
    u_hi = std::max(u_hi, (p - c).dot(e1));
    v_lo = std::min(v_lo, (p - c).dot(e2));
    v_hi = std::max(v_hi, (p - c).dot(e2));
  }
  const double extent = std::max(u_hi - u_lo, v_hi - v_lo);
  const double margin = kMarginFraction * extent + kMarginEdges * l_avg;
  const double spacing = std::max(kMinSpacing * l_avg, extent / kMaxSpans);
  const Knots ku = KnotsOver(u_lo - margin, u_hi + margin, spacing);
  const Knots kv = KnotsOver(v_lo - margin, v_hi + margin, spacing);
  const TColStd_Array1OfReal flat_u = ku.Flat();
  const TColStd_Array1OfReal flat_v = kv.Flat();
  const int nu = ku.count();
  const int nv = kv.count();
  const int unknowns = nu * nv;

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(points.size() * 16);
  Eigen::VectorXd heights(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Vector3d d = points[i] - c;
    const Basis bu = Evaluate(flat_u, d.dot(e1));
    const Basis bv = Evaluate(flat_v, d.dot(e2));
    for (int a = 0; a <= kDegree; ++a) {
      for (int b = 0; b <= kDegree; ++b) {
        entries.emplace_back(static_cast<int>(i), (bu.first + a) * nv + bv.first + b,
                             bu.value[a] * bv.value[b]);
      }
    }
    heights(static_cast<Eigen::Index>(i)) = d.dot(n);
  }
  Eigen::SparseMatrix<double> a(static_cast<Eigen::Index>(points.size()), unknowns);
  a.setFromTriplets(entries.begin(), entries.end());
  // Second differences along u and along v of the control heights.
  std::vector<Eigen::Triplet<double>> diff;
  int row = 0;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      if (i + 2 < nu) {
        diff.emplace_back(row, i * nv + j, 1.0);
        diff.emplace_back(row, (i + 1) * nv + j, -2.0);
        diff.emplace_back(row++, (i + 2) * nv + j, 1.0);
      }
      if (j + 2 < nv) {
        diff.emplace_back(row, i * nv + j, 1.0);
        diff.emplace_back(row, i * nv + j + 1, -2.0);
        diff.emplace_back(row++, i * nv + j + 2, 1.0);
      }
    }
  }
  Eigen::SparseMatrix<double> d2(row, unknowns);
  d2.setFromTriplets(diff.begin(), diff.end());
  const double lambda = kSmoothing * static_cast<double>(points.size()) / unknowns;
  const Eigen::SparseMatrix<double> normal =
      Eigen::SparseMatrix<double>(a.transpose() * a) + lambda * d2.transpose() * d2;
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) {
    out.failure = "B-spline least squares is singular";
    return out;
  }
  const Eigen::VectorXd control = solver.solve(a.transpose() * heights);
  const Eigen::VectorXd residual = a * control - heights;
  out.rms_distance = std::sqrt(residual.squaredNorm() / static_cast<double>(points.size()));
  const double limit = 3.0 * std::max(region.rms_distance, noise_sigma) + 0.1 * l_avg;
  if (!std::isfinite(out.rms_distance) || out.rms_distance > limit) {
    out.failure = absl::StrCat("B-spline misses the region's vertices by rms ",
                               out.rms_distance, " > ", limit);
    return out;
  }

  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      poles(i + 1, j + 1) =
          ToPnt(c + ku.Greville(i) * e1 + kv.Greville(j) * e2 + control(i * nv + j) * n);
    }
  }
  auto knots = [](const Knots& k, TColStd_Array1OfReal* values, TColStd_Array1OfInteger* mults) {
    for (int i = 0; i <= k.spans; ++i) {
      (*values)(i + 1) = k.lo + i * k.step();
      (*mults)(i + 1) = (i == 0 || i == k.spans) ? kDegree + 1 : 1;
    }
  };
  TColStd_Array1OfReal u_knots(1, ku.spans + 1), v_knots(1, kv.spans + 1);
  TColStd_Array1OfInteger u_mults(1, ku.spans + 1), v_mults(1, kv.spans + 1);
  knots(ku, &u_knots, &u_mults);
  knots(kv, &v_knots, &v_mults);
  out.surface =
      new Geom_BSplineSurface(poles, u_knots, v_knots, u_mults, v_mults, kDegree, kDegree);
  return out;
}

}  // namespace meshseg::brep_internal
