// A narrow band on the axis of a turned face, on a binary-occupancy surface:
// cone or sphere, decided again on the original vertices with the axis the
// band shares with the face beside it (the segment stage's
// RetypeCoaxialBands, which needs a noise estimate, on unbiased vertices).
//
// A 45-degree chamfer a few voxels wide fits a sphere about as well as a
// free cone. Measured on one 6 voxels wide, on a shaft of radius 14 h (346
// interior vertices, terraced; h = 0.35): sphere rms 0.0707, free cone 0.0688,
// a Bayesian information criterion only 7 in the cone's favour once its 6
// parameters are paid for, short of the margin of 10; the binary samples do
// not tell them apart either (each separates all but a few). But a chamfer or
// countersink shares the axis of its shaft or bore: on that axis the cone has
// 2 free parameters (apex along the axis, half angle), the sphere 4. There:
// coaxial cone rms 0.0695, criterion 23 below the sphere's.
#ifndef MESHSEG_PIPELINE_BINARY_TYPES_H_
#define MESHSEG_PIPELINE_BINARY_TYPES_H_

#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg::pipeline_internal {

// For every sphere region of `mesh` (labels one per face) with at least 30
// interior vertices (two rings inside) and a cylinder or cone neighbour
// whose axis passes within a tenth of the sphere's radius of its centre:
// fits a cone to the interior vertices and the neighbour's on the
// neighbour's axis (FitCoaxial) and retypes the region as that cone when its
// criterion m ln rms^2 + 2 ln m is at least 10 below the sphere's
// m ln rms^2 + 4 ln m on the same vertices. Run before RefitOnInputVertices.
void RetypeCoaxialSpheresOnInputVertices(const TriMesh& mesh, std::span<const int> face_labels,
                                         std::vector<Region>* regions);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_BINARY_TYPES_H_
