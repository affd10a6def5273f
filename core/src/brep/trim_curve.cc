#include "brep/trim_curve.h"

#include <algorithm>
#include <cmath>

#include <Geom_Line.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Precision.hxx>

#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

using Eigen::Vector3d;

constexpr int kBoundarySamples = 32;  // boundary points that fix orientation and period
constexpr int kCurveSamples = 64;     // points of the trimmed curve measured
constexpr int kGapSamples = 16;       // points of the trimmed curve checked on the surfaces
// End points closer than this fraction of the boundary's length are one vertex.
constexpr double kSameVertex = 1e-6;

double Length(std::span<const Vector3d> polyline) {
  double length = 0.0;
  for (size_t i = 1; i < polyline.size(); ++i) length += (polyline[i] - polyline[i - 1]).norm();
  return length;
}

double Parameter(const Handle(Geom_Curve) & c, const Vector3d& p) {
  return ClosestParameter(c, p, c->FirstParameter(), c->LastParameter());
}

// The parameters of `points` on `c`, unwrapped along the list on a periodic
// curve (each within half a period of the one before).
std::vector<double> UnwrappedParameters(const Handle(Geom_Curve) & c,
                                        const std::vector<Vector3d>& points) {
  std::vector<double> t;
  for (const Vector3d& p : points) {
    double ti = Parameter(c, p);
    if (c->IsPeriodic() && !t.empty()) {
      const double period = c->Period();
      ti += std::round((t.back() - ti) / period) * period;
    }
    t.push_back(ti);
  }
  return t;
}

// The curve a trimmed line or periodic curve was cut from: the trimming here
// starts from the whole curve.
Handle(Geom_Curve) Untrimmed(Handle(Geom_Curve) c) {
  for (;;) {
    const Handle(Geom_TrimmedCurve) t = Handle(Geom_TrimmedCurve)::DownCast(c);
    if (t.IsNull()) return c;
    const Handle(Geom_Curve) basis = t->BasisCurve();
    if (!basis->IsPeriodic() && !basis->IsKind(STANDARD_TYPE(Geom_Line))) return c;
    c = basis;
  }
}

// True if `c` runs against the samples' order: their parameters mostly
// decrease. Steps longer than half the parameter range of a closed curve
// that is not periodic are the jump across its closure (where the first
// samples of a closed boundary lie), not a direction.
bool RunsBackwards(const Handle(Geom_Curve) & c, const std::vector<double>& t) {
  const double range = c->LastParameter() - c->FirstParameter();
  const bool jumps = !c->IsPeriodic() && c->IsClosed() && !Precision::IsInfinite(range);
  double sum = 0.0;
  for (size_t i = 1; i < t.size(); ++i) {
    const double step = t[i] - t[i - 1];
    if (!jumps || std::abs(step) < 0.5 * range) sum += step;
  }
  return sum < 0.0;
}

// `t` moved by whole periods to lie nearest `target`.
double Nearest(double t, double target, double period) {
  return t + std::round((target - t) / period) * period;
}

}  // namespace

double DistanceToPolyline(const Vector3d& p, std::span<const Vector3d> points) {
  if (points.size() == 1) return (p - points[0]).norm();
  double best = INFINITY;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const Vector3d ab = points[i + 1] - points[i];
    const double len2 = ab.squaredNorm();
    const double s = len2 > 0.0 ? std::clamp((p - points[i]).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (points[i] + s * ab - p).squaredNorm());
  }
  return std::sqrt(best);
}

std::vector<Vector3d> Resample(std::span<const Vector3d> polyline, int count) {
  if (polyline.size() < 2 || count < 2) return {polyline.begin(), polyline.end()};
  std::vector<double> length(polyline.size(), 0.0);
  for (size_t i = 1; i < polyline.size(); ++i) {
    length[i] = length[i - 1] + (polyline[i] - polyline[i - 1]).norm();
  }
  std::vector<Vector3d> out;
  size_t seg = 0;
  for (int k = 0; k < count; ++k) {
    const double s = length.back() * k / (count - 1);
    while (seg + 2 < polyline.size() && length[seg + 1] < s) ++seg;
    const double span = length[seg + 1] - length[seg];
    const double f = span > 0.0 ? std::clamp((s - length[seg]) / span, 0.0, 1.0) : 0.0;
    out.push_back(polyline[seg] + f * (polyline[seg + 1] - polyline[seg]));
  }
  return out;
}

std::optional<TrimmedCurve> TrimAlong(const Handle(Geom_Curve) & curve,
                                      std::span<const Vector3d> polyline,
                                      const std::optional<Vector3d>& start,
                                      const std::optional<Vector3d>& end) {
  if (polyline.size() < 2 || start.has_value() != end.has_value()) return std::nullopt;
  const std::vector<Vector3d> samples = Resample(polyline, kBoundarySamples);
  TrimmedCurve out;
  out.curve = Untrimmed(curve);
  std::vector<double> t = UnwrappedParameters(out.curve, samples);
  if (RunsBackwards(out.curve, t)) {
    out.curve = out.curve->Reversed();
    t = UnwrappedParameters(out.curve, samples);
  }
  const Handle(Geom_Curve) & c = out.curve;
  const bool periodic = c->IsPeriodic();
  // A boundary whose ends share a vertex goes once round a closed curve
  // from that vertex.
  const bool round = !start || (*start - *end).norm() <= kSameVertex * Length(polyline);
  if (round) {
    if (periodic) {
      out.first = start ? Nearest(Parameter(c, *start), t.front(), c->Period()) : t.front();
      out.last = out.first + c->Period();
    } else if (c->IsClosed()) {
      out.first = c->FirstParameter();
      out.last = c->LastParameter();
    } else {
      return std::nullopt;
    }
  } else {
    out.first = Parameter(c, *start);
    out.last = Parameter(c, *end);
    if (periodic) {
      out.first = Nearest(out.first, t.front(), c->Period());
      out.last = Nearest(out.last, out.first + (t.back() - t.front()), c->Period());
    }
    if (!(out.last > out.first)) return std::nullopt;
  }
  if (Precision::IsInfinite(out.first) || Precision::IsInfinite(out.last)) return std::nullopt;

  std::vector<Vector3d> q(kCurveSamples);
  for (int j = 0; j < kCurveSamples; ++j) {
    q[j] = ToEigen(c->Value(out.first + (out.last - out.first) * j / (kCurveSamples - 1)));
  }
  double deviation = 0.0;
  for (const Vector3d& p : samples) deviation = std::max(deviation, DistanceToPolyline(p, q));
  for (const Vector3d& p : q) deviation = std::max(deviation, DistanceToPolyline(p, polyline));
  out.deviation = deviation;
  return out;
}

void MeasureGap(std::span<const Handle(Geom_Surface)> surfaces, TrimmedCurve* c) {
  c->gap = 0.0;
  for (int j = 0; j < kGapSamples; ++j) {
    const double t = c->first + (c->last - c->first) * (j + 0.5) / kGapSamples;
    const Vector3d p = ToEigen(c->curve->Value(t));
    for (const Handle(Geom_Surface) & s : surfaces) {
      if (s.IsNull()) continue;
      const std::optional<SurfacePoint> q = ClosestPoint(s, p);
      c->gap = std::max(c->gap, q ? std::abs(q->distance) : INFINITY);
    }
  }
}

}  // namespace meshseg::brep_internal
