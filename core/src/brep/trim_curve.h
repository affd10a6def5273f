// A candidate edge curve laid along a mesh boundary curve: oriented like the
// boundary's vertex order, trimmed at the parameters of its end vertices (a
// closed boundary takes one whole period), and measured against the
// boundary (two-sided distance) and against the surfaces it should lie on.
#ifndef MESHSEG_SRC_BREP_TRIM_CURVE_H_
#define MESHSEG_SRC_BREP_TRIM_CURVE_H_

#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>

namespace meshseg::brep_internal {

struct TrimmedCurve {
  Handle(Geom_Curve) curve;  // oriented along the boundary
  double first = 0.0;
  double last = 0.0;
  // Hausdorff distance between the trimmed curve and the boundary polyline.
  double deviation = 0.0;
  // Max distance of the trimmed curve from the surfaces it joins.
  double gap = 0.0;
};

// Returns `curve` trimmed along `polyline` (>= 2 points; a closed boundary
// repeats its first point at the end and has no `start`/`end`), or nullopt
// when the curve cannot follow it (runs the wrong way between the ends, or
// is too short for them).
std::optional<TrimmedCurve> TrimAlong(const Handle(Geom_Curve) & curve,
                                      std::span<const Eigen::Vector3d> polyline,
                                      const std::optional<Eigen::Vector3d>& start,
                                      const std::optional<Eigen::Vector3d>& end);

// Sets `c->gap` to the max distance of samples of `c` from the surfaces
// (null handles skipped).
void MeasureGap(std::span<const Handle(Geom_Surface)> surfaces, TrimmedCurve* c);

// Returns the distance from `p` to the polyline through `points`.
double DistanceToPolyline(const Eigen::Vector3d& p, std::span<const Eigen::Vector3d> points);

// Returns `count` points of `polyline` spread evenly by arc length, both
// ends included (a polyline of fewer points gains points on its segments,
// so that parameters taken at consecutive samples of a periodic curve stay
// within half a period). Fewer than 2 points or `count` < 2: the input.
std::vector<Eigen::Vector3d> Resample(std::span<const Eigen::Vector3d> polyline, int count);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_TRIM_CURVE_H_
