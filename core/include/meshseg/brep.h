// File: brep.h
// -----------------------------------------------------------------------------
// The `brep` stage: a segmented mesh as a boundary representation, written as
// a STEP AP214 file (OpenCASCADE). Every patch of a region becomes one face on
// the region's surface (plane, cylinder, cone, sphere, torus as OCCT analytic
// surfaces; quadric and freeform regions as a B-spline fitted to the region's
// vertices). Between two regions an edge is the exact intersection of their
// surfaces nearest the mesh boundary curve, trimmed at the corners (each
// corner is the point nearest the mesh corner that lies on all its regions'
// surfaces); where the surfaces are tangent or miss each other (fillets) it
// is a curve fitted to the boundary curve drawn onto both surfaces, its
// tolerance covering the gap. Loops give the wires; the faces are sewn with a
// tolerance from the noise level and a closed shell becomes a solid.
//
// In: the Mesh, one label per mesh face, the Regions and their Topology.
// Out: the STEP file and a BrepReport (what was built, what was not and why).
#ifndef MESHSEG_BREP_H_
#define MESHSEG_BREP_H_

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"
#include "meshseg/segment.h"
#include "meshseg/topology.h"

namespace meshseg {

struct BrepParams {
  // Length unit of the mesh coordinates, declared in the STEP file (values
  // are written as they are): "mm", "cm", "m", "km", "in", "ft", "mi",
  // "mil", "um", "uin". CAD meshes are millimetres by convention.
  std::string length_unit = "mm";
  // Normal-direction noise of the mesh, model units (the `segment` stage's
  // estimate, SegmentEstimates::noise_sigma). Unset = the median rms
  // distance of the regions from their surfaces.
  std::optional<double> noise_sigma = std::nullopt;
  // Sewing tolerance, in noise sigmas: edges of two faces closer than this
  // are one edge. 3 sigma holds 99.7 % of Gaussian noise.
  double sewing_tolerance = 3.0;
  // The exact intersection of two surfaces is taken as their edge when the
  // mesh boundary curve stays within this of it, in l_avg (as the topology
  // stage's TopologyParams::curve_tolerance: marching cubes cuts sharp edges
  // by up to about one voxel).
  double curve_tolerance = 2.0;
  // Name written into the STEP product (e.g. the input file name); empty =
  // the mesh's name.
  std::string product_name = {};
};

// A face that could not be built.
struct BrepFaceFailure {
  int region = 0;
  int patch = 0;  // face-connected piece of the region (RegionTopology::patch_count)
  std::string reason;
};

struct BrepReport {
  int region_count = 0;
  int patch_count = 0;  // faces asked for: one per region patch
  // Patches bounded by junction artifacts only (a few faces where regions
  // meet, topology.h): contracted into a vertex, not faces.
  int contracted_patch_count = 0;
  int face_count = 0;   // faces written
  int edge_count = 0;   // boundary curves made edges (junction artifacts contracted)
  // Edges on the exact intersection of their two surfaces, and edges fitted
  // to the mesh boundary curve (tangent or missing intersections, borders).
  int exact_edge_count = 0;
  int fitted_edge_count = 0;
  // The faces form closed shells (no free edges), in memory and in the file
  // read back.
  bool closed = false;
  bool solid = false;   // written as solids (else as a shell or shells)
  // Solids in the file read back: one per body (closed shell not inside
  // another; a shell inside one whose faces face the other way is a void of
  // it, one whose faces face the same way a body of its own).
  int solid_count = 0;
  // BRepCheck_Analyzer finds the shape valid both in memory and as the file
  // reads back (STEPControl_Reader), with every face, and its solids enclose
  // positive volume.
  bool valid = false;
  double volume = 0.0;  // of the solids read back, model units³; 0 when not a solid
  double sewing_tolerance = 0.0;  // model units
  double max_tolerance = 0.0;     // largest edge or vertex tolerance, model units
  std::vector<BrepFaceFailure> failures;
  std::string length_unit;  // declared in the file (BrepParams::length_unit)
  int64_t step_size = 0;    // bytes written
};

// Returns `unit` as BrepParams::length_unit names it (lowercase) when it is
// one of the length units a STEP file can declare, in any case ("MM" ->
// "mm"); "" for any other string.
std::string CanonicalLengthUnit(std::string_view unit);

// The units CanonicalLengthUnit knows, for messages: "mm, cm, m, ...".
std::string LengthUnitList();

// Writes the B-rep of the segmented `mesh` to `path` (STEP AP214, faces named
// "region <id> <type>") and returns what was built.
// Inputs: `face_labels` one per mesh face (region id or -1); regions[k].id ==
// k; `topology` is ExtractTopology's of the same mesh, labels and regions.
// A face that cannot be built is left out and listed in failures; the rest is
// written (a solid when the shell closes, else the shell).
// Errors: INVALID_ARGUMENT for bad params, a label count different from the
// face count, labels or topology ids out of range; FAILED_PRECONDITION when
// no face can be built; INTERNAL when the file cannot be written or
// OpenCASCADE fails outside a face; CANCELLED when ctx requests a stop.
absl::StatusOr<BrepReport> WriteStep(const Mesh& mesh, std::span<const int> face_labels,
                                     std::span<const Region> regions, const Topology& topology,
                                     const std::string& path, const BrepParams& params = {},
                                     const RunContext& ctx = {});

}  // namespace meshseg

#endif  // MESHSEG_BREP_H_
