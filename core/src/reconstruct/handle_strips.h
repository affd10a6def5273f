// The handles among short loops (issue 38 item 1; our addition to the
// reconstruction of ALGORITHMS.md S3): a loop short in its ball (handle_loops.h)
// may still be a genuine thin part (a rod's meridian), which separates the
// surface. The global test is Guskov & Wood's (2001): the strip of faces
// around the loop (an annulus) is cut only if the surface stays connected
// without it (the loop is non-separating: a handle), shortest loop first,
// each cut lowering the genus by one, until the genus is spent.
#ifndef MESHSEG_RECONSTRUCT_HANDLE_STRIPS_H_
#define MESHSEG_RECONSTRUCT_HANDLE_STRIPS_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "mesh/point_index.h"
#include "meshseg/mesh.h"

namespace meshseg::reconstruct_internal {

// Short loops checked against the whole surface (each a search over it) per
// call at most, separating ones included; bounds the cost on a surface with
// many thin genuine parts.
inline constexpr int kMaxLoopChecks = 256;

// A loop's strip (the faces at its vertices) that is not an annulus is grown
// by a ring of faces at most this many times before the loop is passed over.
inline constexpr int kMaxStripGrowth = 2;

// The points a surface was made from and their index; empty: none known.
struct ScanPoints {
  const std::vector<Eigen::Vector3d>* points = nullptr;
  const mesh_internal::PointIndex* index = nullptr;
};

struct HandleStrips {
  // One per face of the mesh: 1 = on the strip of faces around a cut loop.
  std::vector<uint8_t> cut;
  int64_t cut_count = 0;    // loops cut (each a handle)
  int64_t loop_count = 0;   // short loops found not contractible in their ball
  int64_t check_count = 0;  // of those, checked against the whole surface
};

// Returns the strips of the shortest non-separating loops of `tri` (an
// oriented manifold, closed or with borders) found by ShortLoops
// (handle_loops.h) with the bounds max_loop (model units), at most `genus`
// of them (the total genus of `tri`: no more non-separating loops exist).
// Strips do not share a vertex. With `near` (one per vertex) not empty, only
// loops within max_loop of a flagged vertex are looked for (the faces a
// previous round changed).
//
// With `max_width` (one per vertex, model units) not empty, a loop found is
// a candidate only when it is no longer than π × its vertices' mean
// max_width (the loop of a round hole that wide) or the hole it goes round
// is at most that wide (HoleAtMost): a tunnel between two sheets a noise
// band apart (a slit) has a loop long for its width, and the points no more
// show a hole that narrow than a round one.
//
// With `scan` (the points the surface was made from), the hole is the one
// the points show (HoleAtMost with them): its void is where no point lies.
HandleStrips ShortHandleStrips(const TriMesh& tri, const std::vector<double>& max_loop, int genus,
                               const std::vector<uint8_t>& near = {},
                               const std::vector<double>& max_width = {},
                               const ScanPoints& scan = {});

// Samples of HoleWidth across the width tested (HoleAtMost).
inline constexpr double kWidthSteps = 16.0;

// Whether the hole the closed polygon `loop` of `tri`'s vertices goes round
// is at most `width` across: HoleWidth (hole_width.h) of the vertices'
// positions, sampled at width / kWidthSteps, is at most `width`. The
// sampling's bound is on the safe side: a hole wider than `width` is never
// taken as narrow, and one narrower by 2.24 steps (14 %) always is. A round
// hole d across reads d, a slit its gap, flat or not.
//
// With `scan`, the ball may not hold a scan point either: a hole the points
// support is a void they show, and a sample shows a surface wherever it has
// a point within half the bound (its gaps are no wider than the bound: the
// principle of the bound itself, handles.h). A hole whose least-area disc
// lies all within `width` / 2 of scan points (a tunnel through a sheet the
// points cover, between two sheets of one noisy layer) reads at most
// `width`, however wide its loop: the points do not show it.
bool HoleAtMost(const TriMesh& tri, const std::vector<int>& loop, double width,
                const ScanPoints& scan = {});

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_HANDLE_STRIPS_H_
