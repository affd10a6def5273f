#include "generate/marching_cubes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/fit.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"

namespace meshseg::generate_internal {
namespace {

constexpr int kTile = 8;

// Samples slice k into f (nx * ny values, row-major in j). A tile whose
// centre value exceeds its half-diagonal plus 1.5 h keeps that value at every
// point: the sign is right, and no edge at such a point can cross.
void SampleSlice(const Csg& solid, const Grid& g, int k, std::vector<double>& f) {
  const int tiles_x = (g.nx + kTile - 1) / kTile;
  const int tiles_y = (g.ny + kTile - 1) / kTile;
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles_y), [&](const tbb::blocked_range<int>& r) {
    for (int tj = r.begin(); tj < r.end(); ++tj) {
      const int j0 = tj * kTile, j1 = std::min(g.ny, j0 + kTile);
      for (int ti = 0; ti < tiles_x; ++ti) {
        const int i0 = ti * kTile, i1 = std::min(g.nx, i0 + kTile);
        const double ci = 0.5 * (i0 + i1 - 1), cj = 0.5 * (j0 + j1 - 1);
        const double fc = solid.Eval(g.Point(ci, cj, k)).f;
        const double reach = g.h * (std::hypot(0.5 * (i1 - i0 - 1), 0.5 * (j1 - j0 - 1)) + 1.5);
        const bool far = std::abs(fc) > reach;
        for (int j = j0; j < j1; ++j) {
          for (int i = i0; i < i1; ++i) {
            f[static_cast<size_t>(j) * g.nx + i] = far ? fc : solid.Eval(g.Point(i, j, k)).f;
          }
        }
      }
    }
  });
}

// The vertex on the edge a -> b whose ends have values fa, fb of opposite
// sign: Illinois root finding, then kept off the ends and projected.
SampledField::Vertex EdgeVertex(const Csg& solid, const Eigen::Vector3d& a, double fa,
                                const Eigen::Vector3d& b, double fb, double h) {
  const double tol = 1e-10 * h;
  double t0 = 0.0, f0 = fa, t1 = 1.0, f1 = fb, t = 0.5;
  int side = 0;
  Csg::Value v;
  for (int it = 0; it < 60; ++it) {
    t = (t0 * f1 - t1 * f0) / (f1 - f0);
    v = solid.Eval(a + t * (b - a));
    if (std::abs(v.f) <= tol || t1 - t0 < 1e-13) break;
    if ((v.f < 0.0) == (f0 < 0.0)) {
      t0 = t, f0 = v.f;
      if (side == -1) f1 *= 0.5;
      side = -1;
    } else {
      t1 = t, f1 = v.f;
      if (side == 1) f0 *= 0.5;
      side = 1;
    }
  }
  const double kept = std::clamp(t, kMinEdgeFraction, 1.0 - kMinEdgeFraction);
  if (kept != t) v = solid.Eval(a + kept * (b - a));
  const Eigen::Vector3d p = a + kept * (b - a);
  return {Project(solid.leaves()[v.leaf].surface, p).point, v.leaf};
}

}  // namespace

absl::StatusOr<RawSurface> MarchingCubes(const Csg& solid, const Grid& g, const RunContext& ctx) {
  SampledField field;
  field.dims = {g.nx, g.ny, g.nz};
  field.slice = [&](int k, std::vector<double>& f) {
    SampleSlice(solid, g, k, f);
    return absl::OkStatus();
  };
  field.edge_vertex = [&](int i, int j, int k, int axis, double fa, double fb) {
    Eigen::Vector3d step = Eigen::Vector3d::Zero();
    step[axis] = 1.0;
    return EdgeVertex(solid, g.Point(i, j, k), fa, g.Point(i + step.x(), j + step.y(), k + step.z()),
                      fb, g.h);
  };
  MESHSEG_ASSIGN_OR_RETURN(IsoSurface iso, meshseg::MarchingCubes(field, ctx, "generate"));
  RawSurface out;
  out.vertices = std::move(iso.vertices);
  out.vertex_leaf = std::move(iso.vertex_tag);
  out.triangles = std::move(iso.triangles);
  return out;
}

}  // namespace meshseg::generate_internal
