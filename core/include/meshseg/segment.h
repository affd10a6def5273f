// File: segment.h
// -----------------------------------------------------------------------------
// The `segment` stage: splits a mesh into regions that each follow one
// analytic surface. Seed 000 (region growing with the height function then
// the quadric, type decision by the alpha test, graph merging) with seed 002's
// improvements (labelled seeds incl. torus histogram, fast linear fits from
// smoothed normals, leftover absorption with stepped thresholds, face labels).
// Our additions, for noisy scans and CAD exports: the noise and tolerances
// are estimated from the data; on a noisy mesh, flat seeds grow as planes
// before seed 000's loop; boundary vertices move to the neighbour that
// fits them best; after merging, regions the refinement shrank are released,
// regions their type misses beyond the noise are typed again, bands along
// creases the sharp test missed are dissolved into their neighbours, rows
// of neighbouring faces a curved region bent over are given back, small
// faces a curved region absorbed across a crease are split off as planes,
// curved types are checked on each region's interior (without the rows
// along its creases) and neighbours that one surface explains better than
// two are merged, the last four by an information criterion; each
// surface is reported as fitted to its region's inliers; coarse exact CAD
// meshes, and CAD exports the pipeline cannot remesh finely enough, are
// segmented facet by facet (core/src/segment/segment.cc holds the order).
//
// In: a Mesh and its CurvatureField. Out: Segmentation with a label per mesh
// face and vertex and one Region per label.
#ifndef MESHSEG_SEGMENT_H_
#define MESHSEG_SEGMENT_H_

#include <cstdint>
#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/curvature.h"
#include "meshseg/fit.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"
#include "meshseg/surface.h"

namespace meshseg {

struct SegmentParams {
  // Max vertex-to-surface distance th_dis, in l_avg. Seed 000 eq. (5).
  double distance_tolerance = 0.5;
  // Max angle th_nm between vertex normal and surface normal, degrees.
  // Seed 000 eq. (6) uses 5 for CT meshes; unset = derived from the
  // estimated noise level of the mesh.
  std::optional<double> angle_tolerance_deg;
  // Fraction alpha of region vertices that must fit for a type to be
  // accepted. Seed 000 §3 step 3.
  double alpha = 0.9;
  // Randomness (tie breaking) comes from here, never a global RNG.
  uint64_t seed = 0;
  // Segment facet by facet, as a coarse exact CAD mesh is (the pipeline
  // sets this for CAD exports too fine to remesh: remesh.h). Fails with
  // FAILED_PRECONDITION if the mesh is not an exact tessellation.
  bool exact_facets = false;
  // The mesh's vertices lie on the flat facets of a CAD tessellation (the
  // pipeline sets this for its isotropic remesh of one: remesh.h). On a
  // curved face they sit on chords under the surface, up to the facets'
  // sagitta, so no type fits them at the noise; the curved types are told
  // apart by how closely they fit all of a region's vertices instead.
  bool on_facets = false;
};

struct Region {
  int id = 0;
  SurfaceType type = SurfaceType::kQuadric;
  Surface surface;
  int64_t face_count = 0;
  int64_t vertex_count = 0;
  double area = 0.0;
  double rms_distance = 0.0;
  double max_distance = 0.0;
};

// What the stage measured of the mesh and the thresholds it derived.
struct SegmentEstimates {
  double mean_edge_length = 0.0;     // l_avg
  double noise_sigma = 0.0;          // estimated normal-direction noise, model units
  double distance_tolerance = 0.0;   // th_dis used, model units
  double angle_tolerance_deg = 0.0;  // th_nm used
  double sharp_threshold = 0.0;      // th_sv used (seed 000 §2), in l_i,avg
};

struct Segmentation {
  std::vector<int> face_labels;    // one per mesh face; region id or -1
  std::vector<int> vertex_labels;  // one per mesh vertex; region id or -1
  std::vector<Region> regions;     // regions[k].id == k
  SegmentEstimates estimates;
};

// Returns the segmentation of `mesh`.
// Errors: INVALID_ARGUMENT for bad params or a mesh without faces;
// CANCELLED when ctx requests a stop.
absl::StatusOr<Segmentation> Segment(const Mesh& mesh, const CurvatureField& curvature,
                                     const SegmentParams& params = {},
                                     const RunContext& ctx = {});

}  // namespace meshseg

#endif  // MESHSEG_SEGMENT_H_
