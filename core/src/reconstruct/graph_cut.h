// Inside/outside labels of the tetrahedralization's vertices by a minimum
// s-t cut (Boykov–Kolmogorov max-flow). Seed 001 §2.2.2, eqs. (7)-(10).
#ifndef MESHSEG_RECONSTRUCT_GRAPH_CUT_H_
#define MESHSEG_RECONSTRUCT_GRAPH_CUT_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "reconstruct/regular_triangulation.h"

namespace meshseg::reconstruct_internal {

// Returns 1 (inside, source side) or 0 (outside) per tet vertex. Terminal
// weights k|f(v)|/ave(v) tie v to the source if f(v) ≥ 0, else to the sink
// (eqs. 8-9); an edge weighs |f(v_i) + f(v_j)| / |v_i v_j| (eq. 10). Hull
// vertices are tied to the sink with a weight no cut can pay, so the inside
// is enclosed by the tetrahedralization and the surface is closed.
// Vertices flagged in `resolved` (empty: none) are tied to the source as
// firmly (our addition, issue 38): the cut repairs f where the points leave
// its sign open (sparse supports, |f| within the fit's error, isolated
// clumps), not where they decide it. Eqs. (8)-(10) price an inside region
// by its boundary against the |f| of its vertices, so without the tie a
// region a few vertices thick whose |f| is small (a plate near its sampled
// face, where f is the distance below it) costs more to keep than to drop,
// and a cut that must close an unseen region reaching the hull (a scan's
// underside, where f continues the seen planes) goes through it.
// Vertices flagged in `seen_outside` (empty: none) are tied to the sink as
// firmly, whatever f or `resolved` says (SeenFromOutside below).
// `position` and `f` have one entry per tet vertex.
// Errors: CANCELLED when ctx requests a stop.
absl::StatusOr<std::vector<uint8_t>> GraphCutLabels(const TetMesh& tets,
                                                    const std::vector<Eigen::Vector3d>& position,
                                                    const std::vector<double>& f, double k,
                                                    const std::vector<uint8_t>& resolved,
                                                    const std::vector<uint8_t>& seen_outside,
                                                    const RunContext& ctx);

// True if the points resolve tet vertex v inside on their own (the test
// ResolvedInside applies before keeping the largest set): not on the hull, a
// support of at least the sparse count of points, and f >= epsilon.
inline bool ResolvedAt(const TetMesh& tets, const std::vector<double>& f,
                       const std::vector<uint8_t>& sparse, double epsilon, int v) {
  return !tets.on_hull[v] && !sparse[v] && f[v] >= epsilon;
}

// Returns 1 at the vertices whose inside the points resolve: not on the hull,
// a support holding at least the sparse count of points (`sparse` 0), and
// f ≥ ε: the points in the ball lie within ε of its fitted plane (eq. 6), so
// a centre farther inside than that is inside whatever the noise. Only the
// largest set of such vertices joined by tet edges counts: a small clump of
// stray points with consistent normals (a ghost sheet) resolves a few
// vertices of its own, and the cut must stay free to drop that bubble.
std::vector<uint8_t> ResolvedInside(const TetMesh& tets, const std::vector<double>& f,
                                    const std::vector<uint8_t>& sparse, double epsilon);

// Returns 1 at the vertices off the hull where f > 0 although every input
// point in their support ball sees them from outside (our addition, issue
// 38): the vertex lies in front of each point's tangent plane, (c − p) · n_p
// < −ε with n_p the point's inward normal and ε the fit's error. A point
// stands for solid only behind its tangent plane, so the points a vertex
// reads give no evidence of solid there, and its f > 0 is the planes of
// other, larger balls carried on past their points. That is the empty space
// beyond an unseen face: below the mouth of a bore whose lower wall and far
// end the scan did not see, a ball grows until it holds the lowest seen
// rows of the wall round it, which all face its centre from outside, while
// the balls grown under the part read the walls' planes extended down past
// their points (f > 0). Labelled inside, such a vertex joins the solid on
// either side under the mouth and the tets close the bore there, a plug
// the closing cannot tell from a blind end. Where f ≤ 0 the fits and the
// points agree, and the cut keeps its freedom. `supports` are the tet
// vertices' balls (tets.support indexes them); `f` has one entry per tet
// vertex.
std::vector<uint8_t> SeenFromOutside(const TetMesh& tets, const std::vector<Support>& supports,
                                     const std::vector<double>& f, const FitInput& in);

// Returns 1 where f ≥ 0 and 0 elsewhere, with hull vertices outside: the
// labels of the partition of unity alone.
std::vector<uint8_t> SignLabels(const TetMesh& tets, const std::vector<double>& f);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_GRAPH_CUT_H_
