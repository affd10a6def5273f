// The energy the segmentation decides labels, types and merges by: one
// criterion in the shape of PEARL multi-model fitting (Isack & Boykov, IJCV
// 2012) with label costs (Delong et al., IJCV 2012), on the vertex graph
// and tolerances of ALGORITHMS.md S1.
//
// A labeling L gives every vertex v a region L_v (or none, -1); every
// region r has a type and a surface S_r. Its energy is
//
//   E(L) = sum_v D_v(L_v) + (lambda / f) sum_(u,v) w_uv [L_u != L_v]
//          + sum_r (p_r / (2 f)) ln (f n_r),
//
// f the share of independent samples in the residuals (1 for independent
// noise; "Correlated residuals" below).
//
// Data term. With d_v(S) the distance of v to S and th_dis the distance
// tolerance of S1 eq. (5),
//
//   D_v(r) = (a_v / a_mean) / 2 * min(k^2 (d_v(S_r) / th_dis)^2, c_out),
//
// half the squared residual in units of th_dis / k: th_dis is at least k
// noise sigmas (estimate_noise.h), so where the noise sets th_dis the unit
// is sigma and D is the negative log-likelihood of a normal residual; where
// the mesh resolution sets it, the unit is coarser and D more lenient.
// a_v / a_mean (vertex area over that of a regular triangulation of edge
// l_avg) makes sum_v D independent of the meshing's density. A vertex left
// unlabelled (-1, the outlier label of PEARL) pays c_out / 2, and so does a
// vertex farther than th_dis from its surface: rows along a crease, which
// no smooth surface meets, cost alike under either of its regions and
// cannot decide between them.
// Data unit. On a mesh reconstructed from noisy points (SegmentParams::
// point_noise) the resolution sets th_dis (0.5 l_avg, some 17 times the
// vertices' scatter), yet each vertex was projected onto a fit to the
// points: it lies off its surface by their noise averaged over the fit,
// the scatter EstimateNoise measures, the resolution bounding only the
// chord error between vertices. There D_v and c_out / 2 are in that unit u
// (never coarser than th_dis / k): times s = (th_dis / (k u))^2
// (SegmentContext::unit_scale), the cap still at th_dis; lambda and the
// label cost, in the data term's units, stay. A mesh as read, or one from
// noise-free points (only the resolution's error left), has s = 1.
// Distances only, no normal term. The smoothed normals n'_i are biased over
// the W2 window near creases and across narrow bands (they turn toward both
// neighbours of a chamfer as a sphere's would), so that an angle term in
// units of th_nm / k outweighs the distances several times and prefers the
// wrong type there. The one-ring normals n_i are unbiased on average over a
// surface (the facets of a staircase sum to the vector area of the surface
// they step along), but on a surface from binary voxels their spread
// depends on the surface's orientation to the grid: 1.3 to 2.1 times as
// wide on the rounds, cylinders and cones as on the planes along the grid,
// so that a term in one unit per mesh charges a round nearly the outlier
// cost where a plane beside it explains the rows of its treads. The
// information criterion of decide_type.h, which the label cost below
// completes, is in distances alone too.
//
// Smoothness term. Every mesh edge between two labels costs lambda w_uv,
// w_uv = 1 between non-sharp vertices and kCreaseEdgeWeight where either
// end is sharp (CurvatureField::sharp): a boundary along a crease is where
// one face meets another and costs little; one through a smooth face is
// paid for in full.
//
// Label cost. A region of type T and n_r vertices costs (p_T / 2) ln n_r,
// p_T its free parameters (ParameterCount, decide_type.h): the Bayesian
// information criterion of InformationScore with the variance known, so
// that with the data term above a type or a second surface must lower the
// residuals by more than its parameters' cost.
// Shared parameters. The BIC counts the parameters estimated from the data
// it is the likelihood of. A surface fitted with some of its parameters
// taken from a neighbour's fit (a countersink's cone on its bore's axis: the
// axis, 4 of the cone's 6, is the bore's, estimated from the bore's
// vertices; a round tangent to two planes: its axis direction and the
// bisector its centre lies on are the planes') shares them with that
// neighbour, whose own label already pays for them: the joint model of the
// two regions has them once. Region r's label then counts p_r = p_T - s_r,
// s_r its shared parameters (RegionState::shared_parameters; 0 for a
// surface fitted free). One mechanism for every such constraint: whatever
// fits a surface on a neighbour's parameters sets s_r, whatever refits it
// free sets 0. Re-estimation (Reestimated) compares the two models of the
// region by E: the free refit replaces the shared surface only if its data
// cost falls by more than the s_r parameters it adds to the label, the BIC
// of a nested model; the shared surface is not refitted on its own.
//
// Measured vertices. A vertex of a patch that closes an area no input point
// supports (SegmentParams::measured) lies where the patch's fairing put it:
// it is no evidence of any surface, so it neither pays nor proposes. D_v is
// 0 for it under every label (-1 too), n_r counts measured vertices only,
// surfaces are fitted to measured vertices (FitType), f is measured on them
// (EvidenceShare) and no seed is made on them (seeds.h). It still takes a
// label: the boundary term gives it its neighbours'.
//
// Correlated residuals. The data term and the BIC count every vertex as an
// independent sample of the noise. Where the residuals are correlated
// along the surface they are not: on a surface from binary voxels
// (thresholded CT, ALGORITHMS.md S4) the residual is the staircase of the
// voxel grid, nearly the same at neighbouring vertices, and the vertices of
// a noise-free tessellation share the chord error of their facet. n
// vertices then carry the evidence of only n_eff = f n independent ones:
// the data term, a sum over vertices, overstates the evidence by 1 / f,
// and a surface that follows the correlated error (a plane on a terrace of
// a staircase cylinder, a cone over two of its steps) seems to buy 1 / f
// times what its extra label is worth. The evidence is f sum_v D_v, the
// BIC on n_eff samples is (p / 2) ln (f n), and the boundary term, a prior
// in the data term's units, stays; E above is that energy divided by f, so
// that D_v keeps its units and f = 1 gives PEARL's energy unchanged. f
// comes from the lag-1 autocorrelation rho of the residuals over mesh
// edges, through the first-order (AR(1)) effective sample size n_eff / n =
// (1 - rho) / (1 + rho), measured once per mesh on the regions grown
// (EvidenceShare). Independent noise (a CT-like scan) has rho near 0 and f
// near 1; negative rho is taken as 0 (f = 1: correlation never makes a
// label cheaper). The residuals of a surface from binary voxels have rho
// 0.4 to 0.6 (f 0.24 to 0.42 on the generated parts). One rule for every
// input: nothing in it knows where the mesh came from.
// Only residuals the data term resolves carry evidence to overstate: D
// knows a residual to its resolution delta, a fixed fraction of its unit
// th_dis / k, and rho is the correlation of the residuals each with an
// independent term of variance delta^2 added (sum d_u d_v over
// sum ((d_u^2 + d_v^2) / 2 + delta^2)). Residuals far above delta (noise,
// staircases) keep their rho; far below it (exact vertices with the fit's
// smooth error of 1e-10, which alone would give rho near 1 and f near 0,
// so that lambda / f and the label cost grow without bound) give rho near
// 0 and f near 1: residuals D cannot see prove no correlation. As residuals
// within th_dis are kept, f >= delta^2 / (2 th_dis^2 + delta^2) > 0.
//
// A local move (merge two regions, retype one, drop one) is accepted iff it
// lowers E; MergeDelta, RetypeDelta and DropDelta below price one without
// touching the rest.
//
// Exact vertices (a CAD tessellation, exact_facets.h). The same E, with the
// data term in its limit: a modeller computed each vertex on its surface,
// so the residuals are the rounding of the file's numbers, far below any
// noise unit, and a facet either lies on a surface or does not. With tau
// that rounding (exact_tolerance.h), the labels are on facets and
//
//   D_f(S) = 0 if f lies on S within tau (facet_on_surface.h), else inf,
//
// (ExactFacetCost): th_dis -> tau and k d / th_dis -> 0 or inf. The
// residuals, below the data term's resolution, carry no correlation to
// discount (f = 1, "Correlated residuals" above), and the boundary term,
// a prior against the ragged boundaries noise makes, has nothing to
// smooth: a facet on one surface only is that surface's, whatever its
// neighbours. What remains of E is the label cost, (p_T / 2) ln n_r with
// n_r the distinct corners of region r's facets (ExactLabelCost), and the
// outlier cost c_out / 2 of each corner no analytic surface explains
// (kExactOutlierCost; such facets are reported as FREEFORM pieces).
// Minimising label costs under a hard data term is uncapacitated facility
// location (Delong et al. 2012, label costs without smoothness), and the
// cover of exact_facets.h is a greedy for it. The label cost is concave in
// n: a corner costs least, (p / 2) / n at the margin, in the label with the
// most corners, so E falls most by giving facets several surfaces explain
// to the one explaining the most; and every surface holding evidence is
// worth its label, its cost per corner (ExactPricePerCorner, at most
// 7 / (2 e)) being below the outlier cost c_out / 2. (The textbook greedy
// for facility location, least label cost per new corner first, Hochbaum
// 1982, opens small labels first: a strip of a coarsely tessellated round
// lies in its own plane, 5 corners at 0.48 each, and goes before the
// round's dozen at 0.54, though the round, opened anyway, explains the
// strip at no data cost and at less label cost than a plane of its own,
// ln being concave.) On a tie the type order of exact_hypotheses.h
// decides, a rule: exact corners can leave the type undetermined (the two
// rims of a cylinder tessellated without inner vertices lie on a sphere
// too, every facet of it a chord of both), and the label cost, counting
// parameters, would take the sphere.
// Regions on one surface are one label (PEARL's label is the model): joined
// when the joint fit keeps the data term 0, which lowers E by
// h(a) + h(b) - h(a + b) > 0 (ExactJoinDelta).
#ifndef MESHSEG_SRC_SEGMENT_ENERGY_H_
#define MESHSEG_SRC_SEGMENT_ENERGY_H_

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "segment/facet_mesh.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// The constants of E, each with its meaning.
// k: th_dis in units of the data term's scale (estimate_noise.h puts th_dis
// at 3 noise sigmas or more).
inline constexpr double kToleranceSigmas = 3.0;
// c_out: the truncation of k^2 (d / th_dis)^2, a vertex outside the
// distance tolerance (d = th_dis) being an outlier: k^2.
inline constexpr double kOutlierMismatch = kToleranceSigmas * kToleranceSigmas;
// lambda: the cost of one mesh edge between two labels through a smooth
// face, that of a vertex one data unit (one sigma) off its surface, twice
// (divided by f in E, as the label cost is).
inline constexpr double kBoundaryCost = 1.0;
// w_uv for an edge with a sharp end, relative to a smooth one.
inline constexpr double kCreaseEdgeWeight = 0.1;
// delta / (th_dis / k): the resolution of the data term in its unit. A
// residual of delta costs delta^2 / 2 = 0.005 units, so a region of a
// hundred vertices all within delta of its surface moves E by less than one
// boundary edge through a smooth face (lambda = 1).
inline constexpr double kResidualResolution = 0.1;

// D_v(S) for vertex v on `surface`. Only the distance enters D_v, so it
// is taken with SignedDistance (fit.h), Project's distance to the bit
// without the foot point and normal; a caller pricing many vertices on one
// surface passes its SurfaceDistance, made once.
double VertexCost(const SegmentContext& c, int v, const Surface& surface);
double VertexCost(const SegmentContext& c, int v, const SurfaceDistance& distance_to);
// D_v of an unlabelled vertex.
double OutlierCost(const SegmentContext& c, int v);
// sum of D_v(S) over `vertices`.
double DataCost(const SegmentContext& c, const Surface& surface, std::span<const int> vertices);
// (p_T / (2 f)) ln (f n), f = c.evidence_share (0 for f n <= 1), n the
// region's measured vertices (MeasuredCount).
double LabelCost(const SegmentContext& c, SurfaceType type, std::size_t measured_count);
// The same for evidence share `f` (0 < f <= 1), without a mesh.
double LabelCost(SurfaceType type, std::size_t vertex_count, double f);
// p_r = p_T - s_r: the parameters of region `r`'s surface estimated from
// its own vertices ("Shared parameters" above).
int FreeParameters(const RegionState& r);
// (p_r / (2 f)) ln (f n) of region `r` on `measured_count` measured
// vertices (its own by default).
double LabelCost(const SegmentContext& c, const RegionState& r);
double LabelCost(const SegmentContext& c, const RegionState& r, std::size_t measured_count);

// E with exact vertices (above). D_f(S): 0 if facet f of `fm` lies on
// `surface` within `tau` (FacetOnSurface), else infinity.
double ExactFacetCost(const FacetMesh& fm, int f, const Surface& surface, double tau);
// The label cost of a region of `type` on `corner_count` distinct corners:
// LabelCost with f = 1.
double ExactLabelCost(SurfaceType type, std::size_t corner_count);
// The outlier cost of a corner no analytic surface explains: c_out / 2 (a
// vertex of mean area unlabelled, OutlierCost).
inline constexpr double kExactOutlierCost = kOutlierMismatch / 2.0;
// The greedy cover's price of a surface of `type` that newly explains
// `corner_count` corners: ExactLabelCost per corner (infinite for none).
double ExactPricePerCorner(SurfaceType type, std::size_t corner_count);
// The change of E from joining two regions of `type` on `a_corners` and
// `b_corners` corners (a region's corners are its own; shared corners are
// counted in each) onto one surface whose data cost on both is
// `joint_data_cost` (0 or infinity).
double ExactJoinDelta(SurfaceType type, std::size_t a_corners, std::size_t b_corners,
                      double joint_data_cost);
// The same for joining regions of `type` on `corner_counts` corners each.
double ExactJoinDelta(SurfaceType type, std::span<const std::size_t> corner_counts,
                      double joint_data_cost);

// f = n_eff / n = (1 - rho) / (1 + rho) of the residuals of `labels` to
// their regions' surfaces (1 if rho <= 0 or nothing to measure): rho the
// correlation of the residuals at the two ends of a mesh edge, each known
// to the resolution kResidualResolution th_dis / k (see above), over the
// edges inside a region with both ends non-sharp and within th_dis of its
// surface (rows along creases are the model's error, not the meshing's),
// from a fixed-stride sample of at most kMaxSample vertices.
double EvidenceShare(const SegmentContext& c, const std::vector<int>& labels,
                     const std::vector<RegionState>& regions);
// (lambda / f) w_uv of the edge (u, v).
double EdgeCost(const SegmentContext& c, int u, int v);
// The smoothness cost of the edges between regions `a` and `b`, from the
// vertices of `a`.
double BoundaryCost(const SegmentContext& c, const std::vector<int>& labels,
                    std::span<const int> a_vertices, int b);

// E of `labels` with `regions` (the vertex lists must match the labels).
double TotalEnergy(const SegmentContext& c, const std::vector<int>& labels,
                   const std::vector<RegionState>& regions);

// A priced move: its change of E and, for a merge or retype, the new
// region's type and surface.
struct Move {
  double delta = 0.0;
  SurfaceType type = SurfaceType::kQuadric;
  Surface surface;
};

// The data cost of `vertices` under a surface of `type` fitted to them for
// least energy (FitForEnergy), with the surface (infinite cost if none is
// valid). A cost at or above `stop` is of no interest to the caller and may
// be reported as any value at or above it.
struct PricedFit {
  double cost = std::numeric_limits<double>::infinity();
  std::optional<Surface> surface;
};
PricedFit PriceFit(const SegmentContext& c, SurfaceType type, std::span<const int> vertices,
                   double stop = std::numeric_limits<double>::infinity());

// The surface of `type` that fits `vertices` at least cost: the least
// squares fit, then (if it costs less) the fit to the vertices within th_dis
// of that fit (the re-estimation of PEARL, on inliers). nullopt
// if no valid fit.
std::optional<Surface> FitForEnergy(const SegmentContext& c, SurfaceType type,
                                    std::span<const int> vertices);

// Region `r` re-estimated (PEARL's step between expansions): refitted with
// its own type (FitForEnergy) if that costs less than its current surface,
// and for a surface sharing parameters with a neighbour's fit, less by more
// than the label cost those parameters add when freed (s_r = 0 then).
// A region keeps its surface from before absorption and refinement changed
// its vertices; priced with that stale surface, any move that refits it
// looks a gain.
RegionState Reestimated(const SegmentContext& c, const RegionState& r);

// Reestimated regions of `regions` by id and vertex count, each computed
// once, with the data cost of its vertices on its surface: within a merge
// or drop step a region changes only by growing. With `reestimate` false,
// each region as given.
class ReestimatedRegions {
 public:
  ReestimatedRegions(const SegmentContext& c, const std::vector<RegionState>& regions,
                     bool reestimate = true)
      : c_(c), regions_(regions), reestimate_(reestimate) {}
  const RegionState& operator()(int id) { return Get(id).region; }
  // DataCost of region `id`'s vertices on its surface, as operator() gives it.
  double Cost(int id) { return Get(id).cost; }
  // (energyspeed2: re-estimations kept across steps, kept_prices.h.)
  // Whether regions are re-estimated (the constructor's `reestimate`), and
  // whether region `id` at its vertex count is made already.
  bool reestimates() const { return reestimate_; }
  bool Has(int id) const { return cache_.contains({id, regions_[id].vertices.size()}); }
  // Gives `region` with data cost `cost` for region `id` at its vertex
  // count, without refitting: what operator() and Cost made for the same
  // region, bit for bit, in an earlier step.
  void Keep(int id, const RegionState& region, double cost) {
    cache_.try_emplace({id, regions_[id].vertices.size()}, Priced{.region = region, .cost = cost});
  }

 private:
  struct Priced {
    RegionState region;
    double cost = 0.0;
  };
  const Priced& Get(int id);
  const SegmentContext& c_;
  const std::vector<RegionState>& regions_;
  bool reestimate_ = true;
  std::map<std::pair<int, std::size_t>, Priced> cache_;
};

// The change of E from merging regions `a` and `b` into one surface of the
// type among `types` that lowers E most (nullopt: no type fits the union).
std::optional<Move> MergeDelta(const SegmentContext& c, const std::vector<int>& labels,
                               const std::vector<RegionState>& regions, int a, int b,
                               std::span<const SurfaceType> types);
// The same for regions `x` (id `a` in `labels`) and `y` (id `b`) as given,
// e.g. re-estimated (their surfaces may differ from the labeling's).
std::optional<Move> MergeDelta(const SegmentContext& c, const std::vector<int>& labels,
                               const RegionState& x, int a, const RegionState& y, int b,
                               std::span<const SurfaceType> types);
// The same for regions `a` and `b` as `region` gives them, for a caller to
// whom only a move that lowers E below `below` matters: the best move is
// the same if it does; if it does not, the move returned (if any) does not
// either (a type's union fit is summed only until it cannot do better).
std::optional<Move> MergeDelta(const SegmentContext& c, const std::vector<int>& labels,
                               ReestimatedRegions& region, int a, int b,
                               std::span<const SurfaceType> types, double below);

// The change of E from refitting region `r` as `type` (nullopt: no valid fit).
std::optional<Move> RetypeDelta(const SegmentContext& c, const RegionState& r, SurfaceType type);

// A priced drop of one region: its change of E, the label each of its
// vertices goes to (in the order of its vertex list; -1: none), and the
// regions that take vertices with their surfaces refitted to what they then
// hold.
struct DropMove {
  double delta = 0.0;
  std::vector<int> next;
  std::vector<int> takers;  // sorted
  std::vector<Surface> surfaces;  // of `takers`, in their order
};

// The change of E from dropping region `id` (the label removal of PEARL,
// Isack & Boykov 2012; Delong et al. 2012): each of its vertices within
// th_dis of the surface of a region next to `id` goes to the one it costs
// least on; the rest, outliers to every such surface and so of one data
// cost under any label, go to the label most of their mesh neighbours have
// (fewest boundary edges), spreading from those placed; a vertex no label
// reaches stays unlabelled. Each region that takes vertices is then refitted
// with its type to all it holds (FitForEnergy), kept where that costs less
// than its surface.
DropMove DropDelta(const SegmentContext& c, const std::vector<int>& labels,
                   const std::vector<RegionState>& regions, int id);
// The same with each region as `region(id)` gives it (re-estimated: its
// surface may differ from the labeling's, its vertices may not).
DropMove DropDelta(const SegmentContext& c, const std::vector<int>& labels,
                   ReestimatedRegions& region, int id);

// The types a merge of regions of types `a` and `b` may take: each member's
// own type, every analytic type that generalises neither member within its
// family (IsLimitOf: a cylinder is a cone of half-angle 0, both are tori of
// infinite tube radius), and every type with the quadric if either is a
// general quadric. Where the meshing's residuals are correlated (a surface
// from binary voxels) a torus bent along a cylinder's axis fits that error
// better than the label cost charges for its two parameters; the simpler
// member's type stands, and the retype steps may still generalise it. A
// member's own type is no such new generalisation: a cone grown in two
// pieces, one of them a band narrow enough to read as a cylinder within the
// noise, is joined by the cone the other piece already is.
std::vector<SurfaceType> MergeTypes(SurfaceType a, SurfaceType b);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ENERGY_H_
