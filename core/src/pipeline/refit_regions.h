// Refits the regions of a remeshed CAD tessellation on the input's own
// vertices.
#ifndef MESHSEG_PIPELINE_REFIT_REGIONS_H_
#define MESHSEG_PIPELINE_REFIT_REGIONS_H_

#include <cstddef>
#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg::pipeline_internal {

// The remesh's vertices lie on the input's flat facets, a chord's sagitta
// inside a coarsely tessellated cylinder; the vertices of a CAD export lie on
// the CAD surface itself. For every region this refits its surface (same
// type, initial normals from the current surface) to the vertices of the
// input faces labelled with it, and keeps the refit where it is closer to
// those vertices than the current surface. rms/max distances are then those
// of the input vertices. A cone that widens less than `distance_tolerance`
// (th_dis) over those vertices becomes a cylinder, as in the segment stage.
// `face_labels` has one entry per face of `mesh`.
void RefitOnInputVertices(const TriMesh& mesh, std::span<const int> face_labels,
                          double distance_tolerance, std::vector<Region>* regions);

// A face of a CAD export has its corners on its own surface; its label,
// carried over from the remesh by four samples, can still be the next
// region's when the face is long and thin (a CAD tessellation with its
// coordinates moved by 1e-12: a torus face in the corner cylinder beside it,
// rms 0.04). Gives a face on a region boundary to a neighbouring face's
// region when its corners lie on that region's surface, farthest corner
// within half its distance to its own surface and its own farther than
// `exact`. Run after RefitOnInputVertices (surfaces fitted to the input's
// vertices); returns how many faces moved.
// The refit of RefitOnInputVertices on given points: points_of_region[r]
// are the points of region r (one list per region, by id); a region with
// fewer points than its type needs keeps its surface (the fit is invalid),
// with rms/max distances of its points; one without points is left as it is.
void RefitToPoints(std::span<const std::vector<Eigen::Vector3d>> points_of_region,
                   double distance_tolerance, std::vector<Region>* regions);

// Returns the points within `band` of `surface` (a NaN distance is not).
std::vector<Eigen::Vector3d> WithinBand(const Surface& surface,
                                        std::span<const Eigen::Vector3d> points, double band);

// Fewer points than this tell no type from another (the cone's fit needs 6).
inline constexpr std::size_t kMinRetypePoints = 30;

// Point clouds: the surface-type decision (ALGORITHMS.md S1) made again on each curved
// region's own points (points_of_region: all the points whose nearest face
// the region holds, the region's surface refitted to those within `band` of
// it), with the segmentation's criterion (segment/decide_type.h), near the
// noise (a candidate's rms on its own band within kScoredNearError sigmas
// of the cloud's `sigma`, or of the rms the region's own type leaves on its
// band if larger):
// - a simpler type that is a limit of the region's (a plane of any curved
//   type; a cylinder or cone of a torus; a cylinder of a cone) takes over
//   when its information score is less than kScoreMargin above the region's;
// - a sphere may become a cylinder or cone (no limit of it, nor it of
//   them) when that scores kScoreMargin below it, never the other way.
// Every type, the region's own included, is scored on all the region's
// points, each at its distance to that type's fit capped at `band`, the fit
// being the type's own: to all the points, then again to those within
// `band` of it. So no type is judged on the points another type chose.
// On a reconstructed mesh the type was decided on vertices that round every
// crease over a spacing and run on over the smooth patches that close
// unscanned areas, which bends a narrow chamfer into a torus band or a flat
// side into a cylinder, or closes a bore seen near its rim only into a
// sphere of its radius; the points are the data. A retyped region leaves
// the shared surface it was on for one of its own, and, if `band_points` is
// given, band_points[id] becomes its points within `band` of its new
// surface. Returns how many regions changed type.
int RetypeToPoints(std::span<const std::vector<Eigen::Vector3d>> points_of_region, double band,
                   double sigma, std::vector<Region>* regions, std::vector<SharedSurface>* surfaces,
                   std::vector<std::vector<Eigen::Vector3d>>* band_points = nullptr);

// After a region's type changed: the region leaves the shared surface it was
// on (whose other regions keep it) for one of its own, which takes its type,
// surface and distances; a surface it was alone on becomes that one.
void TakeOwnSurface(Region* region, std::vector<SharedSurface>* surfaces);

int RelabelFacesOffTheirSurface(const TriMesh& mesh, std::span<const Region> regions, double exact,
                                std::vector<int>* face_labels);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_REFIT_REGIONS_H_
