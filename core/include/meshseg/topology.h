// File: topology.h
// -----------------------------------------------------------------------------
// The `topology` stage: the B-rep-ready boundary structure of a segmented
// mesh. Seed 002 STB3: an edge whose two faces carry different labels is a
// boundary edge; boundary edges are chained into curves split at corners
// (vertices where three or more regions, or a region pair and the mesh
// border, meet); every curve gets its sharp/smooth and convex/concave
// character and a fitted geometry (the closed-form intersection of the two
// fitted surfaces where one exists, else a fitted line or circle, else the
// polyline); every region gets its closed loops of curves (outer, inner,
// around-the-axis); corners are snapped to the common point of their surfaces.
//
// In: a Mesh, one label per mesh face (region id or -1) and the Regions.
// Out: Topology (curves, loops, corners, region adjacency, per-region data).
#ifndef MESHSEG_TOPOLOGY_H_
#define MESHSEG_TOPOLOGY_H_

#include <span>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"
#include "meshseg/segment.h"

namespace meshseg {

struct TopologyParams {
  // A curve is sharp when the mean angle between the two surfaces' outward
  // normals along it exceeds this, degrees (tangent fillets give ~0).
  double sharp_angle_deg = 20.0;
  // Max distance of a curve's mesh vertices from its fitted line/circle (and
  // from the analytic intersection), in l_avg. Marching-cubes meshes cut sharp
  // edges by up to about one voxel, so 2 l_avg (seed 002 STB3's largest
  // absorption step th_pos = 2.0).
  double curve_tolerance = 2.0;
  // Angle within which axes/normals count as parallel or perpendicular when
  // deciding that an analytic intersection exists, degrees (seed 002 th_norm).
  double angle_tolerance_deg = 8.0;
  // A corner is snapped to the common point of its surfaces only if that
  // point is within this distance of the corner vertex, in l_avg.
  double corner_snap_distance = 3.0;
  // A curve between two corners shorter than this, in l_avg, is marked as a
  // junction artifact (labels zig-zagging where three regions meet).
  double junction_length = 2.0;
};

enum class CurveGeometryType { kPolyline, kLine, kCircle };

// "polyline", "line", "circle".
const char* CurveGeometryTypeName(CurveGeometryType type);

enum class CurveConvexity { kConvex, kConcave, kBorder };

// "convex", "concave", "border".
const char* CurveConvexityName(CurveConvexity convexity);

struct CurveGeometry {
  CurveGeometryType type = CurveGeometryType::kPolyline;
  // Line: a point on the line. Circle: its centre.
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  // Line: unit direction (along the curve's vertex order). Circle: unit normal
  // of the circle's plane, oriented so the vertex order runs counterclockwise
  // about it.
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  double radius = 0.0;  // circle only
  // True if the geometry is the closed-form intersection of the two regions'
  // surfaces; false if fitted to the curve's vertices (or a polyline).
  bool analytic = false;
  // Max distance of the curve's mesh vertices from the geometry (0 for a
  // polyline), model units.
  double max_deviation = 0.0;
};

// A chain of boundary edges between one pair of regions.
struct BoundaryCurve {
  int id = 0;
  // Ordered mesh vertex ids. A closed curve repeats its first vertex at the
  // end. Walking in this order, left_region lies on the left when seen from
  // outside (the faces' orientation).
  std::vector<int> vertices;
  int left_region = -1;   // region id (>= 0)
  int right_region = -1;  // region id, or -1 at the mesh border / unlabelled faces
  bool closed = false;
  // Corner ids at the ends (index into Topology::corners), -1 for a closed
  // curve without corners.
  int start_corner = -1;
  int end_corner = -1;
  // Mean angle between the two surfaces' outward normals along the curve,
  // degrees; 0 at a border.
  double normal_angle_deg = 0.0;
  bool sharp = false;
  CurveConvexity convexity = CurveConvexity::kBorder;
  CurveGeometry geometry;
  double length = 0.0;  // of the mesh polyline, model units
  // True for an open curve shorter than TopologyParams::junction_length
  // between two corners: the face labels zig-zag where three regions meet.
  // A B-rep builder contracts it (its corners share a cluster).
  bool junction_artifact = false;
};

enum class LoopKind {
  kOuter,  // the one outer boundary of a region patch
  kInner,  // a hole in the patch
  kAxial,  // winds once around the axis of a cylinder/cone/torus region (a
           // cylinder through a hole has two and no outer loop)
};

// "outer", "inner", "axial".
const char* LoopKindName(LoopKind kind);

// One use of a curve in a loop.
struct CurveUse {
  int curve = 0;
  bool reversed = false;  // true: the loop runs against the curve's vertex order
};

// A closed cycle of curves around a region patch, oriented counterclockwise
// about the region's outward normal for the outer loop (so the region lies
// on the left of every loop).
struct Loop {
  int id = 0;
  int region = 0;
  int patch = 0;  // patch of `region` it bounds, in [0, RegionTopology::patch_count)
  LoopKind kind = LoopKind::kOuter;
  std::vector<CurveUse> curves;
};

// A vertex where curves end.
struct Corner {
  int id = 0;
  int vertex = 0;  // mesh vertex id
  // Corners joined by junction-artifact curves form one cluster, named by
  // its smallest corner id; they stand for one B-rep vertex.
  int cluster = 0;
  // The cluster's position: snapped to the common point of the cluster's
  // regions' surfaces if they meet in one point near the cluster's mean
  // vertex, else that mean.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  bool snapped = false;
  std::vector<int> regions;  // sorted; -1 included at the mesh border
  std::vector<int> curves;   // ids of the curves ending here (a closed one twice)
};

// An arc of the region adjacency graph: two regions sharing curves.
struct Adjacency {
  int region_a = 0;  // region_a < region_b, both >= 0
  int region_b = 0;
  std::vector<int> curves;
};

struct RegionTopology {
  int region = 0;
  int patch_count = 0;     // face-connected components carrying the label
  std::vector<int> loops;  // loop ids
  // +1 if the normals Project() returns on this region's surface point out of
  // the solid (agree with the face normals), -1 if into it, 0 without faces.
  int normal_sign = 0;
};

struct Topology {
  std::vector<BoundaryCurve> curves;  // curves[k].id == k
  std::vector<Loop> loops;            // loops[k].id == k
  std::vector<Corner> corners;        // corners[k].id == k
  std::vector<Adjacency> adjacency;   // sorted by (region_a, region_b)
  std::vector<RegionTopology> regions;  // regions[k].region == k, one per Region
  double mean_edge_length = 0.0;        // l_avg of the mesh
};

// Returns the boundary structure of the segmented `mesh`.
// Inputs: `face_labels` has one entry per mesh face, a region id in
// [0, regions.size()) or -1; regions[k].id == k.
// Outputs: see Topology; every boundary edge lies on exactly one curve.
// Errors: INVALID_ARGUMENT for bad params, a mesh without faces, a label
// count different from the face count, a label out of range or regions whose
// ids are not 0..n-1; CANCELLED when ctx requests a stop.
absl::StatusOr<Topology> ExtractTopology(const Mesh& mesh, std::span<const int> face_labels,
                                         std::span<const Region> regions,
                                         const TopologyParams& params = {},
                                         const RunContext& ctx = {});

// The same, with `mean_edge_length` = MeanEdgeLength(mesh.tri) already
// measured (MeshStats::mean_edge_length of this mesh), so it is not summed
// again: the same topology bit for bit when the value is that one.
// Errors: also INVALID_ARGUMENT for a mean_edge_length not finite and > 0.
absl::StatusOr<Topology> ExtractTopology(const Mesh& mesh, std::span<const int> face_labels,
                                         std::span<const Region> regions, double mean_edge_length,
                                         const TopologyParams& params = {},
                                         const RunContext& ctx = {});

}  // namespace meshseg

#endif  // MESHSEG_TOPOLOGY_H_
