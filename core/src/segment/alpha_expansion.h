// Boundary placement by the segmentation energy (energy.h): alternating
// alpha-expansion (Boykov, Veksler & Zabih, "Fast approximate energy
// minimization via graph cuts", PAMI 2001) and re-estimation of each
// surface, as PEARL does (Isack & Boykov, IJCV 2012), restricted to bands
// around the current boundaries.
//
// An expansion of region alpha offers every vertex of its band (below) the
// choice of keeping its label or taking alpha. With the surfaces fixed, E's
// data and smoothness terms over that binary choice are a graph-
// representable function (the smoothness term is a Potts metric, so every
// pairwise term is submodular, BVZ 2001 sec. 4), and a minimum s-t cut
// (Boykov-Kolmogorov max-flow) gives the choice of least data + smoothness
// cost: never more than keeping every label, so an expansion cannot raise
// those two terms. The label cost (p_T / 2) ln n_r, not pairwise, is added
// when the move is priced; the move is made iff E falls.
//
// After a sweep of expansions (every region in turn) each region that
// changed is re-estimated (energy.h Reestimated: refitted with its type
// where that costs less), which can only lower E; sweeps repeat until one
// moves no vertex.
//
// The band: only the vertices within kBandRings mesh edges of a vertex of
// alpha (not labelled alpha) may take alpha in its expansion, so a sweep
// moves a boundary by at most kBandRings rows, and the graph cuts stay the
// size of the boundaries, not of the mesh (the bands are found from the
// boundaries too, expansion_band.h). A surface grown bent over rows
// of a neighbour's face gives them back over successive sweeps: once some
// rows go, its re-estimated surface unbends and fits the next rows worse.
#ifndef MESHSEG_SRC_SEGMENT_ALPHA_EXPANSION_H_
#define MESHSEG_SRC_SEGMENT_ALPHA_EXPANSION_H_

#include <vector>

#include "absl/status/statusor.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// The band's width in mesh edges (rings) outside each region (default 3),
// and the most sweeps one call makes (each moves a boundary by at most
// kBandRings rows; default 8).
inline constexpr int kBandRings = 3;
inline constexpr int kMaxExpansionSweeps = 8;

// One expansion of region `alpha` over the vertices within `rings` edges of
// it: each takes alpha or keeps its label, whichever the minimum cut of
// data + smoothness cost picks (surfaces as given). The result, not applied.
struct Expansion {
  std::vector<int> taken;          // the vertices that take alpha, sorted
  double smooth_data_delta = 0.0;  // change of data + smoothness terms (<= 0)
  double delta = 0.0;              // change of E, label costs included
};
Expansion ExpandRegion(const SegmentContext& c, const std::vector<int>& labels,
                       const std::vector<RegionState>& regions, int alpha, int rings = kBandRings);

// Sweeps of expansions of every alive region with vertices, in id order,
// each made iff it lowers E, then the re-estimation of the regions that
// changed, until a sweep moves no vertex or kMaxExpansionSweeps. Updates
// labels, vertex lists and surfaces (types stay; a region may end with no
// vertices). An expansion not made is not made again while nothing it
// reads has changed (it would be the same). Returns the number of vertices
// moved. Errors: CANCELLED on stop.
absl::StatusOr<int> ExpandRegions(const SegmentContext& c, std::vector<int>* labels,
                                  std::vector<RegionState>* regions, int rings = kBandRings);

// A labelling, its regions and their E.
struct Placed {
  std::vector<int> labels;
  std::vector<RegionState> regions;
  double energy = 0.0;
};

// A move priced with the expansion it enables (PEARL compares models from
// labellings placed for each): on copies, region `id` set to `state`, then
// ExpandRegions, and E of what that leaves. The caller keeps it iff its
// energy is below E as it stands. Errors: as ExpandRegions.
absl::StatusOr<Placed> PlacedByExpansion(const SegmentContext& c, const std::vector<int>& labels,
                                         const std::vector<RegionState>& regions, int id,
                                         RegionState state);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ALPHA_EXPANSION_H_
