// Strips of faces between two loops of a hole mesh (issue 38 item 1): the
// building block of the tube between an unseen annulus's rims (close_tube.h)
// and of the split at the cap (split_at_cap.h).
//
// The strip of least total rung length between two loops is the optimal
// strip between two contours (Fuchs, Kedem & Uselton 1977) with rung length
// as the cost (Christiansen & Sederberg 1978), found by dynamic programming
// over loop vertices × loop vertices.
#ifndef MESHSEG_RECONSTRUCT_TUBE_STRIP_H_
#define MESHSEG_RECONSTRUCT_TUBE_STRIP_H_

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "reconstruct/close_hole.h"

namespace meshseg::reconstruct_internal {

// Rows along a strip's rungs at most.
inline constexpr int kMaxRows = 256;

// The position of vertex `v` of `sm`.
Eigen::Vector3d PointOf(const HoleMesh& sm, HoleMesh::Vertex_index v);

// The positions of the vertices of `loop`.
std::vector<Eigen::Vector3d> Points(const HoleMesh& sm,
                                    const std::vector<HoleMesh::Vertex_index>& loop);

// The mean edge length of the two closed loops `pa` and `pb` together.
double MeanEdge(const std::vector<Eigen::Vector3d>& pa, const std::vector<Eigen::Vector3d>& pb);

// The index of the point of `p` nearest `q` (the first of equals).
size_t Nearest(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3d& q);

// The strip of least total rung length between loops `a` and `b` (both
// starting at their first vertex): pairs (i, j), from (0, 0) to (m, n), each
// step advancing one of them by one.
std::vector<std::pair<size_t, size_t>> ShortestStrip(const std::vector<Eigen::Vector3d>& a,
                                                     const std::vector<Eigen::Vector3d>& b);

// The faces and vertices a strip added, to take them back.
struct Added {
  std::vector<HoleMesh::Face_index> faces;
  std::vector<HoleMesh::Vertex_index> vertices;
};

// Removes what `added` holds from `sm`, faces last added first.
void TakeBack(const Added& added, HoleMesh* sm);

// Adds the strip whose rung r joins side_a[strip[r].first] to
// side_b[strip[r].second] (indices modulo the sides' sizes; the last pair is
// the first again) through rows[r] − 1 new vertices at(r, k / rows[r]).
// Neighbouring rungs with different rows are zipped by their parameters
// (each step advances the rung whose next vertex lies nearer its start).
// side_a runs along its border, side_b against its own. False when CGAL
// refuses a face.
bool AddStrip(const std::vector<HoleMesh::Vertex_index>& side_a,
              const std::vector<HoleMesh::Vertex_index>& side_b,
              const std::vector<std::pair<size_t, size_t>>& strip,
              const std::function<Eigen::Vector3d(size_t, double)>& at,
              const std::vector<int>& rows, HoleMesh* sm, Added* added);

// Adds the straight strip between side_a (points pa, along its border) and
// side_b (points pb, against its own; both starting at their first vertex)
// as contours: rings at even steps of the rungs of the shortest strip
// between them (about `edge` apart along a rung of mean length), each
// resampled by its own length to `edge` spacing, consecutive rings joined by
// their own shortest strip (Fuchs, Kedem & Uselton 1977, between each pair).
// Where the rungs fan in onto the shorter side, rows taken along the rungs
// would crowd there; the rings keep the strip as dense as a mesh of that
// edge. False when CGAL refuses a face.
bool AddContourStrip(const std::vector<HoleMesh::Vertex_index>& side_a,
                     const std::vector<Eigen::Vector3d>& pa,
                     const std::vector<HoleMesh::Vertex_index>& side_b,
                     const std::vector<Eigen::Vector3d>& pb, double edge, HoleMesh* sm,
                     Added* added);

// As above along the rungs of `strip` (between pa and pb, as ShortestStrip
// gives it): ring k of `steps` through at(r, k / steps) on each rung r.
bool AddContourStrip(const std::vector<HoleMesh::Vertex_index>& side_a,
                     const std::vector<Eigen::Vector3d>& pa,
                     const std::vector<HoleMesh::Vertex_index>& side_b,
                     const std::vector<Eigen::Vector3d>& pb,
                     const std::vector<std::pair<size_t, size_t>>& strip,
                     const std::function<Eigen::Vector3d(size_t, double)>& at, int steps,
                     double edge, HoleMesh* sm, Added* added);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_TUBE_STRIP_H_
