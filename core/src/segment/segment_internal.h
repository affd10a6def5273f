// What the steps of the segment stage share: the mesh as a vertex graph with
// per-vertex normals and areas, the derived tolerances, the (5)/(6) test of
// ALGORITHMS.md S1 step 2.2 and the per-type fit over a (sub-sampled) vertex
// set.
#ifndef MESHSEG_SRC_SEGMENT_SEGMENT_INTERNAL_H_
#define MESHSEG_SRC_SEGMENT_SEGMENT_INTERNAL_H_

#include <cmath>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "meshseg/curvature.h"
#include "meshseg/fit.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"
#include "meshseg/segment.h"
#include "meshseg/surface.h"

namespace meshseg::segment_internal {

// A region while the stage works on it.
struct RegionState {
  SurfaceType type = SurfaceType::kQuadric;
  Surface surface;
  std::vector<int> vertices;
  bool alive = true;
  // How many of its type's parameters `surface` shares with a neighbour's
  // fit, estimated from that neighbour's vertices, not this region's (a
  // cone on its bore's axis: the axis, 4 of 6). The label cost counts the
  // rest (energy.h, "Label cost"); 0 for a surface fitted free. Whatever
  // refits `surface` free sets it back to 0.
  int shared_parameters = 0;
};

// True for the curved analytic types: cylinder, sphere, cone, torus.
inline bool IsCurved(SurfaceType type) {
  return type == SurfaceType::kCylinder || type == SurfaceType::kSphere ||
         type == SurfaceType::kCone || type == SurfaceType::kTorus;
}

// Thresholds of ALGORITHMS.md S1 eqs. (5) and (6) (step 2.2).
struct Tolerance {
  double distance = 0.0;  // th_dis, model units
  double cos_angle = 1.0; // cos(th_nm)
};

struct SegmentContext {
  VertexGraph graph;                          // positions and adjacency
  const CurvatureField* curvature = nullptr;  // n_i, n'_i, kappa, sharp
  std::vector<double> vertex_area;            // a third of incident face areas
  double mean_edge_length = 0.0;              // l_avg
  double noise_sigma = 0.0;                   // estimated, model units
  Tolerance tolerance;                        // the base (5)/(6) thresholds
  double angle_tolerance_deg = 0.0;
  double alpha = 0.9;                         // ALGORITHMS.md S1 step 2.3
  bool on_facets = false;                     // SegmentParams::on_facets
  double evidence_share = 1.0;                // n_eff / n of the residuals (energy.h)
  double unit_scale = 1.0;  // (th_dis / k)^2 / u^2, u the data unit (energy.h)
  // SegmentParams::measured: per vertex, 0 where no input point supports it
  // (empty: all measured).
  std::vector<uint8_t> measured;
  const RunContext* run = nullptr;

  int vertex_count() const { return graph.vertex_count(); }
  // True if vertex v is evidence of its surface (SegmentParams::measured).
  bool Measured(int v) const { return measured.empty() || measured[v] != 0; }
  const Eigen::Vector3d& position(int v) const { return graph.positions[v]; }
  const Eigen::Vector3d& normal(int v) const { return curvature->smooth_normal[v]; }
};

// The context Segment() works in on `mesh` with `curvature` (which must
// outlive it, as must `run`): the vertex graph and areas, and the l_avg and
// tolerances of `estimates`.
SegmentContext MakeSegmentContext(const TriMesh& mesh, const CurvatureField& curvature,
                                  const SegmentEstimates& estimates, double alpha,
                                  const RunContext& run);

// True if vertex v with projection `pr` meets (5) and (6). Surfaces fitted
// to a region may face either way, so the normal test ignores orientation.
// Test (6) passes if either n'_i (robust to noise and marching-cubes
// triangulation) or n_i (exact where a small fillet makes the W2 fit of n'_i
// too wide) is within th_nm.
inline bool Fits(const SegmentContext& c, int v, const Projection& pr, const Tolerance& tol) {
  if (!(std::abs(pr.distance) < tol.distance)) return false;
  return std::abs(pr.normal.dot(c.curvature->smooth_normal[v])) > tol.cos_angle ||
         std::abs(pr.normal.dot(c.curvature->normal[v])) > tol.cos_angle;
}

// At most this many vertices enter a fit or a fraction count; larger sets
// are sub-sampled with a fixed stride (deterministic).
constexpr std::size_t kMaxSample = 3000;

// How many of `vertices` are measured (SegmentContext::Measured).
std::size_t MeasuredCount(const SegmentContext& c, std::span<const int> vertices);

// The measured vertices of `vertices`, in order (all of them when every
// vertex is measured).
std::vector<int> MeasuredVertices(const SegmentContext& c, std::span<const int> vertices);

// Every k-th vertex of `vertices` so that at most kMaxSample remain.
std::vector<int> Sample(std::span<const int> vertices, std::size_t max_count = kMaxSample);

// Fits a surface of `type` to the measured ones of `vertices` (sub-sampled)
// with smoothed normals and area weights: a vertex on a patch that closes an
// unscanned area lies where the patch's fairing put it, not on a surface.
// (Where none of them is measured, to all of them: the patch's own shape is
// all there is.)
FitResult FitType(const SegmentContext& c, SurfaceType type, std::span<const int> vertices);

// Fraction of the measured ones of `vertices` (sub-sampled; all of them if
// none is measured) that meet (5) and (6) for `surface`.
double FitFraction(const SegmentContext& c, const Surface& surface, std::span<const int> vertices,
                   const Tolerance& tol);

// The `vertices` (all of them, in order) that meet (5) and (6) for
// `surface` with the base tolerances.
std::vector<int> FittingVertices(const SegmentContext& c, const Surface& surface,
                                 std::span<const int> vertices);

// Vertices outside a set that a piece of it may step over (noise holes).
inline constexpr int kPieceBridge = 2;

// The piece of `vertices` that holds the most of `seed`, in the order of
// `vertices`: connected over mesh edges within the set and the seed, and
// across up to kPieceBridge vertices outside both. A fit's vertices can lie
// in pieces: on a CAD tessellation (jittered by 1e-12) a cone tangent to
// two plane sides along lines through their corner fitted both sides'
// strips, and not the corner round between them, 24 rows wide. The seed is
// walked over as part of the set, as a fit need not explain the seed itself
// (a seed trial's fit on a small plane disc at sigma = 0.15 h held 5 of its
// 11 seed vertices); empty when no vertex of the set is in the seed's piece.
std::vector<int> PieceHoldingSeed(const SegmentContext& c, std::span<const int> vertices,
                                  std::span<const int> seed);

// Sum of the squared distances of `vertices` (all of them) to `surface`.
double SquaredDistances(const SegmentContext& c, const Surface& surface,
                        std::span<const int> vertices);

// True if the principal curvatures over `vertices` are a curved face's:
// kappa_max has one sign at kCurvedSignShare of them, and its direction is
// shared (the largest eigenvalue of the mean d d^T is at least
// kCurvedDirection; 1/2 for directions spread in the tangent plane). A strip
// of a round that a plane fits within the tolerances (a 60-degree round of
// r 11 h at sigma = 0.15 h) scores 0.96-1.0 and 0.92-0.97; flat faces have
// direction 0.5-0.76 (the noise biases kappa on them to one sign at 60-95 %
// of the vertices).
bool CurvedField(const SegmentContext& c, std::span<const int> vertices);
inline constexpr double kCurvedSignShare = 0.9;
inline constexpr double kCurvedDirection = 0.85;

// Rebuilds every region's vertex list from `labels` (dead regions: empty).
void RebuildVertexLists(const std::vector<int>& labels, std::vector<RegionState>* regions);

// The regions other than `id` that a mesh edge from `id`'s vertices leads
// to, sorted.
std::vector<int> RegionsAround(const SegmentContext& c, const std::vector<int>& labels,
                               const std::vector<RegionState>& regions, int id);

// Releases (labels -1, vertices cleared, alive = false) every alive region
// r with id `id` for which release(id, r) holds, all decided on the labels
// before any is released. Returns how many.
int ReleaseRegions(const std::function<bool(int id, const RegionState& r)>& release,
                   std::vector<int>* labels, std::vector<RegionState>* regions);

// Moves every vertex of region `from` into region `into`.
void MergeInto(int into, int from, std::vector<int>* labels, std::vector<RegionState>* regions);

// Projection of vertex v onto `surface` (the quadric starts along n_i).
inline Projection ProjectVertex(const SegmentContext& c, const Surface& surface, int v) {
  return Project(surface, c.position(v), c.normal(v));
}

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_SEGMENT_INTERNAL_H_
