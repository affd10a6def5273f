// The four steps of isotropic remeshing (Botsch & Kobbelt, "A remeshing
// approach to multiresolution modeling", SGP 2004), on an OpenMesh TriMesh in
// place: split edges longer than 4/3 L, collapse edges shorter than 4/5 L,
// flip edges towards valence 6, relax vertices tangentially. Used by
// refine.h to turn the marching-tetrahedra surface into near-equilateral
// triangles of edge L. Each step keeps a closed 2-manifold a closed
// 2-manifold of the same genus: splits always do, collapses are taken only
// when OpenMesh's link condition holds (is_collapse_ok), flips only when the
// new edge does not exist yet (is_flip_ok); none makes a face fold over
// (its normal turning by more than kMaxFoldDeg) or collapse to zero area.
#ifndef MESHSEG_RECONSTRUCT_ISOTROPIC_STEPS_H_
#define MESHSEG_RECONSTRUCT_ISOTROPIC_STEPS_H_

#include <cstdint>
#include <vector>

#include "meshseg/mesh.h"

namespace meshseg::reconstruct_internal {

// A collapse or flip that turns an adjacent face's normal by more than this
// is refused: it would fold the surface over a crease or a thin wall.
inline constexpr double kMaxFoldDeg = 60.0;

// Splits every edge longer than 4/3 × target at its midpoint; returns the
// number of splits. Needs the mesh's status attributes.
int64_t SplitLongEdges(double target, TriMesh* mesh);

// Collapses edges shorter than 4/5 × target into their midpoint where the
// collapse is topologically safe, makes no edge longer than 4/3 × target and
// folds no face. Returns the number of collapses. Leaves deleted elements for
// garbage_collection().
int64_t CollapseShortEdges(double target, TriMesh* mesh);

// Flips edges whose flip brings the valences of their four vertices closer
// to 6 without folding a face; returns the number of flips.
int64_t EqualizeValences(TriMesh* mesh);

// Moves every vertex towards the mean of its neighbours, within its tangent
// plane (the plane of its area-weighted normal); in parallel.
void RelaxTangentially(TriMesh* mesh);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_ISOTROPIC_STEPS_H_
