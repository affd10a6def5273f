// Feature lines of a dense mesh from its curvature field: the crease edges
// the control mesh keeps (ALGORITHMS.md S5 step 3).
//
// The seed thresholds the per-vertex maximum curvature (1 = sharp) and takes
// the edges between sharp vertices as feature boundaries. On a noisy or
// marching-cubes mesh the sharp vertices along a crease form a band two to
// four vertices wide, whose edges are a network of short lines and
// junctions; a dihedral-angle test sees the same band as the slivers that
// straddle the crease. Here the band is thinned to its centre line instead
// (ordered morphological thinning, Rössl, Kobbelt and Seidel 2000): border
// vertices of the sharp set are removed in order of increasing curvature
// unless that would split the set or shorten a line, so one line of edges
// remains along the curvature crest. Its edges are chained into feature
// lines between ends and junctions; spurs and isolated chains shorter than
// a minimum are dropped, and only junctions of three or more lines remain.
#ifndef MESHSEG_SUBDIV_FEATURE_LINES_H_
#define MESHSEG_SUBDIV_FEATURE_LINES_H_

#include <cstdint>
#include <vector>

#include "meshseg/curvature.h"
#include "meshseg/mesh.h"

namespace meshseg::subdiv_internal {

struct FeatureLines {
  std::vector<uint8_t> edge;  // per mesh edge: 1 = on a feature line
  std::vector<int> count;     // per vertex: feature edges at it (>= 3: a junction)
};

// RidgeVertices' contrast for the fit (with the curvature stage's pass-2
// radius W2 = 5 edges): the fitted curvature across a crease turning by 30
// degrees is about 1 / (3 h), twice that of flanks curved at a radius of
// 6 h and many times that of flat or noisy flanks; on a surface curved alike
// all around (a tube a few edges across) the ratio is about 1.
inline constexpr double kMinRidgeContrast = 2.0;

// Returns the sharp vertices of `field` (CurvatureField::sharp) whose
// |kappa_max| is at least `min_contrast` times the lower quartile of
// |kappa_max| around them (within `radius_edges` times their mean edge
// length, over mesh edges): a feature line is a curvature ridge, standing
// above the surface on both sides of it. A crease's band of sharp vertices
// covers at most half of such a disk, so the quartile is the flanks'; a
// surface curved more tightly than the sharp threshold all over (a thin
// tube sampled by a few edges around) has no such contrast.
std::vector<uint8_t> RidgeVertices(const TriMesh& mesh, const CurvatureField& field,
                                   double radius_edges, double min_contrast);

// Returns the feature lines of `mesh` from its vertices' sharp flags
// (`sharp`, e.g. CurvatureField::sharp) and curvature magnitudes
// (`strength`, e.g. |CurvatureField::kappa_max|), both indexed by vertex:
// the sharp set thinned to one-vertex-wide lines along its strength crest,
// its edges chained, spurs (a free end and a junction) and isolated chains
// or loops of fewer than `min_edges` edges dropped, repeatedly.
FeatureLines DetectFeatureLines(const TriMesh& mesh, const std::vector<uint8_t>& sharp,
                                const std::vector<double>& strength, int min_edges);

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_FEATURE_LINES_H_
