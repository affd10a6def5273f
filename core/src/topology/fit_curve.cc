#include "topology/fit_curve.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace meshseg::topology_internal {
namespace {

struct PointFrame {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes;           // columns by ascending spread
  Eigen::Vector3d spread;         // eigenvalues of the scatter, ascending
};

PointFrame FrameOf(std::span<const Eigen::Vector3d> points) {
  PointFrame f;
  for (const Eigen::Vector3d& p : points) f.centroid += p;
  f.centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points) scatter += (p - f.centroid) * (p - f.centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  f.axes = eig.eigenvectors();
  f.spread = eig.eigenvalues();
  return f;
}

}  // namespace

std::optional<CurveGeometry> FitLine(std::span<const Eigen::Vector3d> points) {
  if (points.size() < 2) return std::nullopt;
  const PointFrame f = FrameOf(points);
  if (f.spread(2) <= 0.0) return std::nullopt;
  CurveGeometry g;
  g.type = CurveGeometryType::kLine;
  g.point = f.centroid;
  g.direction = f.axes.col(2);
  return g;
}

std::optional<CurveGeometry> FitCircle(std::span<const Eigen::Vector3d> points) {
  if (points.size() < 3) return std::nullopt;
  const PointFrame f = FrameOf(points);
  // Collinear points have no circle; 1e-6 relative spread is a straight line.
  if (f.spread(1) <= 1e-6 * f.spread(2)) return std::nullopt;
  const Eigen::Vector3d u = f.axes.col(2);
  const Eigen::Vector3d w = f.axes.col(1);
  // Kåsa: x² + y² + a x + b y + c = 0, linear least squares in (a, b, c).
  Eigen::MatrixXd m(points.size(), 3);
  Eigen::VectorXd rhs(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d q = points[i] - f.centroid;
    const double x = q.dot(u);
    const double y = q.dot(w);
    m.row(static_cast<Eigen::Index>(i)) << x, y, 1.0;
    rhs(static_cast<Eigen::Index>(i)) = -(x * x + y * y);
  }
  const Eigen::Vector3d abc = m.colPivHouseholderQr().solve(rhs);
  const double cx = -0.5 * abc(0);
  const double cy = -0.5 * abc(1);
  const double r2 = cx * cx + cy * cy - abc(2);
  if (!(r2 > 0.0) || !std::isfinite(r2)) return std::nullopt;
  CurveGeometry g;
  g.type = CurveGeometryType::kCircle;
  g.point = f.centroid + cx * u + cy * w;
  g.direction = f.axes.col(0);
  g.radius = std::sqrt(r2);
  return g;
}

double MaxDeviation(const CurveGeometry& g, std::span<const Eigen::Vector3d> points) {
  double worst = 0.0;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d v = p - g.point;
    const double along = v.dot(g.direction);
    const double off_axis = (v - along * g.direction).norm();
    double d = 0.0;
    if (g.type == CurveGeometryType::kLine) d = off_axis;
    if (g.type == CurveGeometryType::kCircle) d = std::hypot(off_axis - g.radius, along);
    worst = std::max(worst, d);
  }
  return worst;
}

}  // namespace meshseg::topology_internal
