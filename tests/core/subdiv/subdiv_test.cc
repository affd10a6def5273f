#include "meshseg/subdiv.h"

#include <optional>

#include "shapes.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

struct Distances {
  double rms = 0.0;
  double max = 0.0;
};

template <class Distance>
Distances LimitToTruth(const SubdivFit& fit, Distance distance) {
  Distances d;
  for (const Eigen::Vector3d& p : fit.limit_vertices) {
    const double e = std::abs(distance(p));
    d.rms += e * e;
    d.max = std::max(d.max, e);
  }
  d.rms = std::sqrt(d.rms / fit.limit_vertices.size());
  return d;
}

// Fits `t` (a smooth body with noise sigma) with the default params and
// expects issue #35's bar: a control mesh of at most 5 % of the input's
// faces, no creases, and the limit surface within rms 1.2 sigma + 0.05 h of
// the true surface (`distance`, signed). Returns the fit (nullopt if none).
template <class Distance>
std::optional<SubdivFit> FitSmoothWithinNoiseBound(const testing::Triangles& t, double sigma,
                                                   Distance distance) {
  const double h = testing::MeanEdge(t);
  absl::StatusOr<Mesh> mesh = testing::ToMesh(t, "smooth body");
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  if (!mesh.ok()) return std::nullopt;
  absl::StatusOr<SubdivFit> fit = FitSubdivisionSurface(*mesh);
  EXPECT_TRUE(fit.ok()) << fit.status();
  if (!fit.ok()) return std::nullopt;
  EXPECT_LE(fit->control.faces.size(), 0.05 * t.faces.size() + 2);
  EXPECT_TRUE(fit->control.creases.empty());
  const Distances d = LimitToTruth(*fit, distance);
  EXPECT_LE(d.rms, 1.2 * sigma + 0.05 * h) << "h " << h << " max " << d.max;
  return *std::move(fit);
}

TEST(FitSubdivisionSurface, SuperellipsoidWithinNoiseBound) {
  // A freeform body without creases: |x|^3 + |y|^3 + |z|^3 = 10^3, 5120
  // faces, noise 0.05 h along the normal. Issue #35's bar: the limit surface
  // within rms 1.2 sigma + 0.05 h of the true surface, with a control mesh of
  // at most 5 % of the input's faces.
  const testing::Superellipsoid shape;
  const testing::NoisySample sample = testing::NoisySuperellipsoid(shape, 4, 0.05, 7);
  const std::optional<SubdivFit> fit = FitSmoothWithinNoiseBound(
      sample.mesh, sample.sigma, [&](const Eigen::Vector3d& p) { return shape.Distance(p); });
  ASSERT_TRUE(fit.has_value());
  // The rounds improve on quasi-interpolation alone.
  ASSERT_EQ(fit->rms_per_round.size(), 4u);
  EXPECT_LT(fit->rms_per_round.back(), fit->rms_per_round.front());
}

TEST(FitSubdivisionSurface, CubeKeepsSharpEdges) {
  // A cube: every edge a crease, every corner a corner. Crease curves of
  // straight control polygons are straight, so the limit surface stays on the
  // cube's faces and edges; rounding would show as limit points inside the
  // cube near its edges.
  constexpr double kS = 5.0;
  testing::Triangles t = testing::Cube(kS, 16);
  const double h = testing::MeanEdge(t);
  const double sigma = 0.05 * h;
  testing::AddNoise(
      t, sigma,
      [](const Eigen::Vector3d& p) {
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        Eigen::Index axis;
        p.cwiseAbs().maxCoeff(&axis);
        n[axis] = p[axis] > 0 ? 1.0 : -1.0;
        return n;
      },
      11);
  auto mesh = testing::ToMesh(t, "cube");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto fit = FitSubdivisionSurface(*mesh);
  ASSERT_TRUE(fit.ok()) << fit.status();
  EXPECT_LE(fit->control.faces.size(), 0.05 * t.faces.size() + 2);
  EXPECT_EQ(fit->control.corners.size(), 8u);
  const Distances d =
      LimitToTruth(*fit, [&](const Eigen::Vector3d& p) { return testing::CubeDistance(p, kS); });
  EXPECT_LE(d.rms, 1.2 * sigma + 0.05 * h) << "h " << h;
  EXPECT_LE(d.max, h) << "rounding wider than 1 h";
}

TEST(FitSubdivisionSurface, KnotTubeWithinNoiseBound) {
  // A tube of radius 1 around a trefoil (bending at radii >= 2.9, strands
  // >= 3.3 apart), 200 x 20 vertices, noise 0.05 h along the normal: issue
  // #35's bar, limit surface within rms 1.2 sigma + 0.05 h of the true tube
  // with a control mesh of at most 5 % of the input's faces.
  const testing::KnotTube tube;
  const double h0 = testing::MeanEdge(tube.Mesh(200, 20, 0.0, 1));
  const double sigma = 0.05 * h0;
  EXPECT_TRUE(FitSmoothWithinNoiseBound(tube.Mesh(200, 20, sigma, 3), sigma,
                                        [&](const Eigen::Vector3d& p) { return tube.Distance(p); })
                  .has_value());
}

TEST(FitSubdivisionSurface, BlendedBodyResolvesItsCreasesWithinOneH) {
  // A superellipsoid unioned with a cylinder standing out of it (marching
  // cubes, vertices on the surface, noise 0.05 h along the normal). Issue
  // #35's bar: limit surface within rms 1.2 sigma + 0.05 h of the true
  // surface, no rounding of the creases wider than 1 h, control mesh <= 5 %.
  // A round of width w at an edge turning by 90 degrees (the cylinder's rim)
  // leaves the sharp edge by (sqrt 2 - 1) w, so "no rounding wider than 1 h"
  // is a deviation of at most 0.41 h there; at the concave crease where the
  // bodies meet (turning by less) the same bound is looser.
  // Default params: the creases come from the curvature-based feature lines
  // (thinned bands of sharp vertices), which follow both creases as closed
  // lines without junctions, so no corner locks the simplification.
  const testing::BlendedBody body;
  const double h0 = testing::MeanEdge(body.Mesh(0.6, 0.0, 1));
  const double sigma = 0.05 * h0;
  const testing::Triangles t = body.Mesh(0.6, sigma, 9);
  const double h = testing::MeanEdge(t);
  auto mesh = testing::ToMesh(t, "blended");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto fit = FitSubdivisionSurface(*mesh);
  ASSERT_TRUE(fit.ok()) << fit.status();
  EXPECT_FALSE(fit->control.creases.empty());
  EXPECT_TRUE(fit->control.corners.empty());
  EXPECT_LE(fit->control.faces.size(), 0.05 * t.faces.size() + 2);
  const Distances d =
      LimitToTruth(*fit, [&](const Eigen::Vector3d& p) { return body.Distance(p); });
  EXPECT_LE(d.rms, 1.2 * sigma + 0.05 * h) << "h " << h << " max " << d.max;
  double crease_max = 0.0, rim_max = 0.0;
  int crease_points = 0, rim_points = 0;
  for (const Eigen::Vector3d& p : fit->limit_vertices) {
    const double e = std::abs(body.Distance(p));
    const double radial = std::hypot(p.x(), p.y());
    if (std::abs(body.body.Distance(p)) < 2 * h && std::abs(radial - body.rho) < 2 * h) {
      crease_max = std::max(crease_max, e);
      ++crease_points;
    }
    if (p.z() > body.top - 2 * h && radial > body.rho - 2 * h) {
      rim_max = std::max(rim_max, e);
      ++rim_points;
    }
  }
  EXPECT_GT(crease_points, 50);
  EXPECT_GT(rim_points, 50);
  EXPECT_LE(crease_max, 0.41 * h);
  EXPECT_LE(rim_max, 0.41 * h);
}

TEST(FitSubdivisionSurface, ToleranceRefinesTheControlMesh) {
  // Asking for half the rms of the default size must double the control
  // mesh until the fit is within it: the approximation error of a smooth
  // surface falls with the control edge length.
  const testing::Superellipsoid shape;
  testing::Triangles t = testing::UnitIcosphere(3);
  for (auto& v : t.vertices) v = shape.Project(v);
  auto mesh = testing::ToMesh(t, "superellipsoid");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto coarse = FitSubdivisionSurface(*mesh);
  ASSERT_TRUE(coarse.ok()) << coarse.status();
  SubdivParams params;
  params.tolerance = 0.5 * coarse->rms_distance;
  auto fine = FitSubdivisionSurface(*mesh, params);
  ASSERT_TRUE(fine.ok()) << fine.status();
  ASSERT_GE(fine->tried_faces.size(), 2u);
  EXPECT_EQ(fine->tried_faces.front(), static_cast<int64_t>(coarse->control.faces.size()));
  for (size_t i = 1; i < fine->tried_faces.size(); ++i) {
    EXPECT_GT(fine->tried_faces[i], fine->tried_faces[i - 1]);
  }
  EXPECT_LE(fine->rms_distance, *params.tolerance);
  EXPECT_EQ(fine->control.faces.size(), fine->tried_faces.back());
}

TEST(FitSubdivisionSurface, RejectsBadParamsAndTinyMeshes) {
  testing::Triangles t = testing::UnitIcosphere(1);
  auto mesh = testing::ToMesh(t, "ico80");
  ASSERT_TRUE(mesh.ok());
  SubdivParams tiny;
  tiny.target_faces = 2;
  auto r = FitSubdivisionSurface(*mesh, tiny);
  EXPECT_EQ(r.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(r.status().message(), HasSubstr("target_faces 2 is below 4"));
  // The message of the fit with the default params changed by `set`.
  auto message = [&](auto set) {
    SubdivParams params;
    set(params);
    return std::string(FitSubdivisionSurface(*mesh, params).status().message());
  };
  EXPECT_THAT(message([](SubdivParams& p) { p.target_faces = 81; }),
              HasSubstr("target_faces 81 exceeds the 80 faces of \"ico80\""));
  EXPECT_THAT(message([](SubdivParams& p) { p.limit_level = 9; }),
              HasSubstr("limit_level 9 must be in [0, 5]"));
  EXPECT_THAT(message([](SubdivParams& p) { p.smoothing_weight = std::nan(""); }),
              HasSubstr("smoothing_weight nan"));
  EXPECT_THAT(message([](SubdivParams& p) { p.sharp_threshold = 0.0; }),
              HasSubstr("sharp_threshold 0 must be finite and > 0"));
  EXPECT_THAT(message([](SubdivParams& p) { p.data_guard_fraction = 2.0; }),
              HasSubstr("data_guard_fraction 2 must be in [0, 1]"));
  EXPECT_THAT(message([](SubdivParams& p) { p.tolerance = -1.0; }),
              HasSubstr("tolerance -1 must be finite and > 0"));
  testing::Triangles tri;
  tri.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.faces = {{0, 1, 2}};
  auto one = testing::ToMesh(tri, "one_triangle");
  ASSERT_TRUE(one.ok());
  r = FitSubdivisionSurface(*one);
  EXPECT_THAT(r.status().message(), HasSubstr("\"one_triangle\" has 1 faces, fewer than 4"));
}

TEST(FitSubdivisionSurface, StopsWhenCancelled) {
  auto mesh = testing::ToMesh(testing::UnitIcosphere(3), "ico");
  ASSERT_TRUE(mesh.ok());
  std::stop_source stop;
  stop.request_stop();
  RunContext ctx;
  ctx.stop = stop.get_token();
  auto r = FitSubdivisionSurface(*mesh, {}, ctx);
  EXPECT_EQ(r.status().code(), absl::StatusCode::kCancelled);
}

}  // namespace
}  // namespace meshseg
