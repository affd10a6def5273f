// A SegmentContext over a parametric sheet (u, v) -> (point, unit normal),
// triangulated as a grid, with exact normals as n_i and n'_i and no sharp
// vertices: for tests of single segment steps without a curvature stage.
#ifndef MESHSEG_TESTS_CORE_SEGMENT_SHEET_CONTEXT_H_
#define MESHSEG_TESTS_CORE_SEGMENT_SHEET_CONTEXT_H_

#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "meshseg/curvature.h"
#include "meshseg/mesh.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal::testing {

using SheetPoint = std::function<std::pair<Eigen::Vector3d, Eigen::Vector3d>(double u, double v)>;

struct Sheet {
  TriMesh mesh;
  CurvatureField field;
  SegmentContext c;
  RunContext run;  // never stopped
  std::vector<double> u;  // parameters per vertex
  std::vector<double> v;
};

// `nu` x `nv` vertices over [u0, u1] x [v0, v1]; th_dis `distance`, th_nm
// `angle_deg`, alpha 0.9, noise 0.
inline void BuildSheet(const SheetPoint& f, double u0, double u1, int nu, double v0, double v1,
                       int nv, double distance, double angle_deg, Sheet* s) {
  std::vector<TriMesh::VertexHandle> handles;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const double u = u0 + (u1 - u0) * i / (nu - 1);
      const double v = v0 + (v1 - v0) * j / (nv - 1);
      const auto [p, n] = f(u, v);
      handles.push_back(s->mesh.add_vertex(TriMesh::Point(p.x(), p.y(), p.z())));
      s->field.normal.push_back(n.normalized());
      s->field.smooth_normal.push_back(n.normalized());
      s->u.push_back(u);
      s->v.push_back(v);
    }
  }
  for (int j = 0; j + 1 < nv; ++j) {
    for (int i = 0; i + 1 < nu; ++i) {
      const auto a = handles[j * nu + i], b = handles[j * nu + i + 1];
      const auto c = handles[(j + 1) * nu + i], d = handles[(j + 1) * nu + i + 1];
      s->mesh.add_face(a, b, d);
      s->mesh.add_face(a, d, c);
    }
  }
  const std::size_t n = handles.size();
  s->field.sharp.assign(n, 0);
  // No principal curvatures: zero, with no direction.
  s->field.kappa_max.assign(n, 0.0);
  s->field.kappa_min.assign(n, 0.0);
  s->field.dir_max.assign(n, Eigen::Vector3d::Zero());
  s->field.dir_min.assign(n, Eigen::Vector3d::Zero());
  s->c.graph = BuildVertexGraph(s->mesh);
  s->c.curvature = &s->field;
  s->c.run = &s->run;
  s->c.vertex_area.assign(n, 1.0);
  s->c.mean_edge_length = MeanEdgeLength(s->mesh);
  s->c.noise_sigma = 0.0;
  s->c.tolerance.distance = distance;
  s->c.tolerance.cos_angle = std::cos(angle_deg * 3.14159265358979323846 / 180.0);
  s->c.angle_tolerance_deg = angle_deg;
  s->c.alpha = 0.9;
}

// A flat side 60 long (x) and 10 high (z) in the plane y = 0, vertices 1
// apart; th_dis 0.225 (3 sigma at 0.15 h), th_nm 10 degrees.
inline void BuildFlatSide(Sheet* s) {
  BuildSheet(
      [](double x, double z) {
        return std::pair{Eigen::Vector3d(x, 0.0, z), Eigen::Vector3d::UnitY()};
      },
      -30.0, 30.0, 61, -5.0, 5.0, 11, /*distance=*/0.225, /*angle_deg=*/10.0, s);
}

// The plane z = 0 for u <= `crease` and, beyond it, a plane rising at 45
// degrees; v runs along the crease.
inline SheetPoint Fold45(double crease) {
  return [crease](double u, double v) {
    if (u <= crease) return std::pair{Eigen::Vector3d(u, v, 0.0), Eigen::Vector3d(0, 0, 1)};
    return std::pair{Eigen::Vector3d(u, v, u - crease), Eigen::Vector3d(-1, 0, 1).normalized()};
  };
}

// The torus with axis z through the origin, major radius `major`, tube
// radius `minor`: u is the tube angle, v the angle around the axis.
inline SheetPoint TorusPoint(double major, double minor) {
  return [major, minor](double t, double phi) {
    const Eigen::Vector3d n(std::cos(t) * std::cos(phi), std::cos(t) * std::sin(phi), std::sin(t));
    const Eigen::Vector3d p =
        Eigen::Vector3d(major * std::cos(phi), major * std::sin(phi), 0.0) + minor * n;
    return std::pair{p, n};
  };
}

// plate_boss's boss top as a region grown into its edge round: a disc of
// radius 6 in z = 0 (25 rows out from the centre) and the first 25 degrees
// of a round of radius 2 turning down from its rim (6 rows), 48 vertices
// around. th_nm 5 degrees.
inline void BuildDiscWithRoundStart(double distance, Sheet* s) {
  constexpr double kDisc = 6.0, kRound = 2.0, kRoundDeg = 25.0;
  constexpr int kDiscRows = 25, kRoundRows = 6, kAround = 48;
  constexpr double kPi = 3.14159265358979323846;
  const double step = kDisc / (kDiscRows - 1);
  BuildSheet(
      [&](double row, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        if (row <= kDiscRows - 1) {
          return std::pair{Eigen::Vector3d(row * step * radial), Eigen::Vector3d(0, 0, 1)};
        }
        const double t = (row - (kDiscRows - 1)) / kRoundRows * kRoundDeg * kPi / 180.0;
        const Eigen::Vector3d n = std::sin(t) * radial + std::cos(t) * Eigen::Vector3d::UnitZ();
        return std::pair{
            Eigen::Vector3d(kDisc * radial - kRound * Eigen::Vector3d::UnitZ() + kRound * n), n};
      },
      0.0, kDiscRows - 1 + kRoundRows, kDiscRows + kRoundRows, 0.0,
      2.0 * kPi * (kAround - 1) / kAround, kAround, distance, /*angle_deg=*/5.0, s);
}

// stepped_shaft's chamfer in profile: a cylinder of radius 5 up to row
// kChamferConeStart, a 45-degree cone band up to radius 3.5 at row
// kChamferConeEnd, and a flat top from there on (rows 0.25 apart on the
// cylinder and the top, 0.236 on the band), three quarters of a turn around
// the z axis, kChamferAround vertices around; noise sigma `sigma` (none
// added), th_dis 5 sigma, th_nm 10 degrees. `ripple`: the band's radius
// varies by that much around (8 waves), a stand-in for the meshing error of
// a CT part.
inline constexpr int kChamferConeStart = 10;
inline constexpr int kChamferConeEnd = 19;
inline constexpr int kChamferRows = 32;
inline constexpr int kChamferAround = 48;

inline void BuildChamfer(double sigma, double ripple, Sheet* s) {
  constexpr double kPi = 3.14159265358979323846;
  const double band_step = 1.5 * std::sqrt(2.0) / (kChamferConeEnd - kChamferConeStart);
  BuildSheet(
      [&](double row, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
        if (row <= kChamferConeStart) {
          return std::pair{Eigen::Vector3d(5.0 * radial + (66.0 + 0.25 * row) * z), radial};
        }
        if (row <= kChamferConeEnd) {
          const double t = (row - kChamferConeStart) * band_step / std::sqrt(2.0);
          const double wave = ripple * std::sin(8.0 * phi);
          return std::pair{Eigen::Vector3d((5.0 - t + wave) * radial + (68.5 + t) * z),
                           Eigen::Vector3d((radial + z).normalized())};
        }
        return std::pair{
            Eigen::Vector3d((3.5 - 0.25 * (row - kChamferConeEnd)) * radial + 70.0 * z), z};
      },
      0.0, kChamferRows - 1, kChamferRows, 0.0, 1.5 * kPi, kChamferAround, 5.0 * sigma,
      /*angle_deg=*/10.0, s);
  s->c.noise_sigma = sigma;
}

// test_piece's boss in profile: an annular top (z = 0) out to radius 5 with
// `top_rows` rows 0.25 apart, and, below its rim, `side_rows` rows (0.25
// apart) of the boss cone widening at 20.6 degrees from the axis (atan
// 3/8), 69.4 degrees from the top; 64 vertices around (one short of a full
// turn). Noise sigma `sigma` (none added), th_dis 5 sigma, th_nm 10 degrees.
inline void BuildBoss(int top_rows, int side_rows, double sigma, Sheet* s) {
  constexpr double kPi = 3.14159265358979323846;
  constexpr double kStep = 0.25;
  constexpr int kAround = 64;
  const double half_angle = std::atan(3.0 / 8.0);
  const double inner = 5.0 - kStep * (top_rows - 1);
  BuildSheet(
      [&](double row, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
        if (row < top_rows) return std::pair{Eigen::Vector3d((inner + kStep * row) * radial), z};
        const double t = kStep * (row - (top_rows - 1));
        return std::pair{Eigen::Vector3d((5.0 + t * std::sin(half_angle)) * radial -
                                         t * std::cos(half_angle) * z),
                         Eigen::Vector3d(std::cos(half_angle) * radial + std::sin(half_angle) * z)};
      },
      0.0, top_rows + side_rows - 1, top_rows + side_rows, 0.0, 2.0 * kPi * (kAround - 1) / kAround,
      kAround, /*distance=*/5.0 * sigma, /*angle_deg=*/10.0, s);
  s->c.noise_sigma = sigma;
}

// Every vertex of `s`.
inline std::vector<int> AllVertices(const Sheet& s) {
  std::vector<int> v(s.u.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<int>(i);
  return v;
}

// Regions from a label per vertex (-1: none), fitted with `types[label]`.
inline std::vector<RegionState> RegionsFromLabels(const SegmentContext& c,
                                                  const std::vector<int>& labels,
                                                  const std::vector<SurfaceType>& types) {
  std::vector<RegionState> regions(types.size());
  for (std::size_t r = 0; r < types.size(); ++r) regions[r].type = types[r];
  RebuildVertexLists(labels, &regions);
  for (RegionState& r : regions) r.surface = FitType(c, r.type, r.vertices).surface;
  return regions;
}

// Gives every vertex of `s` its true area, a third of its faces' (the
// sheets give every vertex area 1), which the data term of E weighs it by.
inline void TrueAreas(Sheet* s) {
  s->c.vertex_area.assign(s->u.size(), 0.0);
  for (const auto fh : s->mesh.faces()) {
    const double third = s->mesh.calc_face_area(fh) / 3.0;
    for (auto it = s->mesh.cfv_iter(fh); it.is_valid(); ++it) s->c.vertex_area[it->idx()] += third;
  }
}

// One region of type `type`, no surface set, holding every vertex of `s`;
// `labels` (all 0) to match.
inline std::vector<RegionState> OneRegion(const Sheet& s, SurfaceType type,
                                          std::vector<int>* labels) {
  labels->assign(s.u.size(), 0);
  std::vector<RegionState> regions(1);
  regions[0].type = type;
  RebuildVertexLists(*labels, &regions);
  return regions;
}

// A sheet over u in [0, 12], v in [0, 20] folded by 45 degrees at u = 5.5
// (Fold45), with a ripple of amplitude `sigma` along z (the least-squares
// planes of its pieces differ), noise sigma `sigma`, th_dis 5 sigma; labelled 0 for u < 5, 1
// for u > 6, and 2 for the two rows u = 5 and 6 either side of the fold
// (42 vertices).
inline std::vector<RegionState> RippledFoldWithStrip(double sigma, Sheet* s,
                                                     std::vector<int>* labels) {
  BuildSheet(
      [sigma](double u, double v) {
        auto [p, n] = Fold45(5.5)(u, v);
        p.z() += sigma * std::sin(1.3 * u + 0.7 * v);
        return std::pair{p, n};
      },
      0.0, 12.0, 13, 0.0, 20.0, 21, /*distance=*/5.0 * sigma, /*angle_deg=*/8.0, s);
  s->c.noise_sigma = sigma;
  labels->resize(s->u.size());
  for (std::size_t v = 0; v < labels->size(); ++v) {
    (*labels)[v] = s->u[v] < 5.0 ? 0 : s->u[v] <= 6.0 ? 2 : 1;
  }
  return RegionsFromLabels(s->c, *labels,
                           {SurfaceType::kPlane, SurfaceType::kPlane, SurfaceType::kPlane});
}

}  // namespace meshseg::segment_internal::testing

#endif  // MESHSEG_TESTS_CORE_SEGMENT_SHEET_CONTEXT_H_
