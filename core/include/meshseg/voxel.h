// File: voxel.h
// -----------------------------------------------------------------------------
// The `voxel` stage: CT volumes in, surfaces out, and feature-preserving
// simplification (seed 003, ALGORITHMS.md S4).
//
// - Volumes: NRRD (raw and gzip encodings, attached or detached data),
//   MetaImage (.mha, .mhd + data file) and headerless .raw samples with the
//   layout given by the caller; uint8 / uint16 / int16 / float32. Samples are
//   streamed slice by slice: extraction holds two slices and the growing
//   surface, never the volume (binary volumes also keep one occupancy byte
//   per voxel of the material's bounding box for seed 003's morphology).
// - Iso-surfaces by marching cubes (the one implementation, shared with the
//   generator): grey volumes at a given iso value or Otsu's threshold, with
//   vertices interpolated between samples; binary volumes (two values) at the
//   mid value, with seed 003's feature voxels marking the vertices QEM keeps.
// - Simplify: Garland-Heckbert QEM edge collapse on OpenMesh's mesh, with
//   the binary-volume method's rules for feature vertices (ALGORITHMS.md S4;
//   creases of plain meshes are feature lines), and the Hausdorff distance
//   of the result to the input.
// - Binary-occupancy meshes (terraced marching-cubes output of a thresholded
//   scan): detected from their vertex lattice and turned back into voxels.
//
// In: a file path (or a mesh). Out: Mesh, per-vertex feature flags, stats.
// Errors name the file, the bad value and the limit.
#ifndef MESHSEG_VOXEL_H_
#define MESHSEG_VOXEL_H_

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"

namespace meshseg {

// ---------------------------------------------------------------- volumes

enum class VoxelType { kUint8, kUint16, kInt16, kFloat32 };

// "uint8", "uint16", "int16", "float32".
const char* VoxelTypeName(VoxelType type);
// Bytes per sample.
int VoxelTypeSize(VoxelType type);

// Sample (i, j, k) sits at origin + i axes[0] + j axes[1] + k axes[2] (model
// units; the axes carry the spacing and the direction cosines).
struct VolumeGeometry {
  std::array<int64_t, 3> dims = {0, 0, 0};
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, 3> axes = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                         Eigen::Vector3d::UnitZ()};

  Eigen::Vector3d Point(double i, double j, double k) const {
    return origin + i * axes[0] + j * axes[1] + k * axes[2];
  }
  int64_t VoxelCount() const { return dims[0] * dims[1] * dims[2]; }
  // Length of the axes (the spacing).
  Eigen::Vector3d Spacing() const { return {axes[0].norm(), axes[1].norm(), axes[2].norm()}; }
};

// The layout of a headerless .raw file (or of an upload without header).
struct RawVolumeLayout {
  std::array<int64_t, 3> dims = {0, 0, 0};
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  VoxelType type = VoxelType::kUint16;
  bool big_endian = false;
};

// Where and how a volume's samples are stored.
struct VolumeInfo {
  std::string name;  // file name, for messages
  FileFormat format = FileFormat::kUnknown;
  VolumeGeometry geometry;
  VoxelType type = VoxelType::kUint8;
  bool big_endian = false;
  bool gzip = false;        // gzip-compressed samples (NRRD encoding gzip)
  std::string data_path;    // the file holding the samples
  int64_t data_offset = 0;  // byte offset of the first sample in data_path
};

struct VolumeReadOptions {
  // Overrides detection by extension and content.
  std::optional<FileFormat> format;
  // Layout of a .raw file; required for kRaw.
  std::optional<RawVolumeLayout> raw;
  // Upper bound on the declared voxel count (8 Gi voxels: 2048^3; 1024^3
  // uint16 is 1 Gi), checked before anything is allocated.
  int64_t max_voxels = int64_t{1} << 33;
  // Upper bound on one slice (dims[0] * dims[1]).
  int64_t max_slice_voxels = int64_t{1} << 26;
  // Refuse a header whose samples are in another file (.mhd + data file, NRRD
  // `data file:`): set where only the one given file may be read (the
  // service receives one file, and a header must not name server files).
  bool attached_data_only = false;
};

// Returns the header of the volume in `path`: geometry, type and where the
// samples are. Checks that the data file holds exactly the declared samples
// (raw encodings; gzip data is checked while streaming).
// Errors (INVALID_ARGUMENT unless noted), naming the file: NOT_FOUND for a
// missing file; a malformed header line, a missing or non-positive size,
// dimension other than 3, an unknown type or encoding, multi-channel data,
// sizes over the limits, a data file of the wrong size, a separate data file
// when `attached_data_only`.
absl::StatusOr<VolumeInfo> ReadVolumeInfo(const std::string& path,
                                          const VolumeReadOptions& options = {});

// Reads a volume's samples slice by slice (k = 0, 1, ...), converted to
// double. Holds one compressed stream and no more than one slice.
class VolumeSlices {
 public:
  // Errors: NOT_FOUND / INVALID_ARGUMENT if the data cannot be opened.
  static absl::StatusOr<VolumeSlices> Open(const VolumeInfo& info);
  VolumeSlices(VolumeSlices&&) noexcept;
  VolumeSlices& operator=(VolumeSlices&&) noexcept;
  ~VolumeSlices();

  // Fills `values` (dims[0] * dims[1], i fastest) with the next slice.
  // Errors (INVALID_ARGUMENT): truncated or corrupt data, naming the slice;
  // OUT_OF_RANGE past the last slice.
  absl::Status Next(std::vector<double>& values);
  int64_t next_slice() const { return next_; }

 private:
  struct Stream;
  explicit VolumeSlices(const VolumeInfo& info);
  VolumeInfo info_;
  Stream* stream_ = nullptr;
  int64_t next_ = 0;
  std::vector<unsigned char> bytes_;
};

// Samples of a whole volume in memory (tests, the generator's output).
struct VolumeData {
  VolumeGeometry geometry;
  VoxelType type = VoxelType::kUint16;
  std::vector<double> values;  // i fastest, then j, then k
};

// Writes `volume` as NRRD (attached data, little endian, raw or gzip).
// Values are rounded and clamped to the type's range. Errors: INVALID_ARGUMENT
// if values.size() does not match dims; INTERNAL if the file cannot be written.
absl::Status WriteNrrd(const VolumeData& volume, const std::string& path, bool gzip = false);

// ---------------------------------------------------------------- marching cubes

// A scalar field on a grid of dims points, delivered slice by slice.
struct SampledField {
  std::array<int, 3> dims = {0, 0, 0};
  // Fills `values` (dims[0] * dims[1], i fastest) with slice k; negative =
  // inside the solid. Called with k = 0, 1, ... in order.
  std::function<absl::Status(int k, std::vector<double>& values)> slice;
  struct Vertex {
    Eigen::Vector3d point;
    int tag = -1;  // carried to IsoSurface::vertex_tag
  };
  // The vertex on the grid edge from point (i, j, k) one step along `axis`
  // (0, 1, 2), whose end values fa, fb have opposite signs. Called
  // concurrently.
  std::function<Vertex(int i, int j, int k, int axis, double fa, double fb)> edge_vertex;
};

struct IsoSurface {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<int> vertex_tag;
  // The grid edge of each vertex: the lower end's index i + d0 (j + d1 k)
  // times 3 plus the axis.
  std::vector<int64_t> vertex_edge;
  std::vector<std::array<int, 3>> triangles;  // normals point out of the solid
};

// Returns the boundary of {field < 0} by marching cubes, slab by slab (two
// slices in memory). Vertices are shared per grid edge: closed and manifold
// where the field is inside-free on the grid's outer layer. Reports progress
// as `stage`. Errors: those of field.slice; CANCELLED on stop.
absl::StatusOr<IsoSurface> MarchingCubes(const SampledField& field, const RunContext& ctx = {},
                                         std::string_view stage = "marching cubes");

// ---------------------------------------------------------------- volume -> surface

enum class VolumeMode {
  kAuto,    // binary if the volume holds two distinct values, else grey
  kGrey,    // iso-surface with interpolated vertices
  kBinary,  // occupancy above the iso value; seed 003's feature voxels
};

struct VolumeParams {
  VolumeReadOptions read;
  VolumeMode mode = VolumeMode::kAuto;
  // Iso value in sample units; unset = Otsu's threshold between air and
  // material (grey), the mid value of the two values (binary).
  std::optional<double> iso;
  // Seed 003 section 2.1: structuring balls of the opening (convex features)
  // and the closing (concave features), radii in voxels.
  int opening_radius = 3;
  int closing_radius = 2;
};

struct VolumeSurface {
  Mesh mesh;  // in model units; face_of_input indexes the mesh's own faces
  VolumeInfo info;
  bool binary = false;
  double iso = 0.0;  // the iso value used, sample units
  // Binary volumes: one per mesh vertex, 1 if the vertex lies on a feature
  // voxel (seed 003 section 2.1); empty for grey volumes.
  std::vector<uint8_t> feature_vertex;
  // Binary volumes: one per mesh vertex, the positions of the material and
  // the air sample at the ends of its grid edge; empty for grey volumes.
  std::vector<Eigen::Vector3d> edge_inside, edge_outside;
};

// Returns the surface of the volume in `path` (see VolumeParams). Reports
// progress as "volume". Errors: those of ReadVolumeInfo and VolumeSlices;
// INVALID_ARGUMENT for a constant volume, an iso value outside the samples'
// range or a surface with no triangles; CANCELLED on stop.
absl::StatusOr<VolumeSurface> ExtractSurface(const std::string& path,
                                             const VolumeParams& params = {},
                                             const RunContext& ctx = {});

// Returns Otsu's threshold of `histogram` (bin b covers [lo + b w, lo + (b+1) w),
// w = (hi - lo) / bins): the value maximising the between-class variance.
double OtsuThreshold(std::span<const int64_t> histogram, double lo, double hi);

// ---------------------------------------------------------------- feature voxels

// Occupancy of a box of voxels, 1 = material, i fastest.
struct Occupancy {
  std::array<int, 3> dims = {0, 0, 0};
  std::vector<uint8_t> inside;
  size_t Index(int i, int j, int k) const {
    return static_cast<size_t>(i) +
           static_cast<size_t>(dims[0]) * (j + static_cast<size_t>(dims[1]) * k);
  }
};

// Returns seed 003's feature voxels of `occupancy` (1 = feature; always a
// material voxel): the tips of what an opening by a ball of `opening_radius`
// removes (local maxima of the distance from the opened shape), and the
// material voxels next to the tips of what a closing by `closing_radius` adds.
std::vector<uint8_t> FeatureVoxels(const Occupancy& occupancy, int opening_radius,
                                   int closing_radius);

// ---------------------------------------------------------------- binary meshes

// The voxel lattice of a binary-occupancy mesh: every vertex at the midpoint
// of a lattice edge.
struct BinaryLattice {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // a lattice point
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();
};

// Returns the lattice if `mesh` is marching-cubes output of binary occupancy
// (each vertex has two coordinates on lattice planes and the third midway
// between two), else nullopt. Seed 003 states why such meshes need their own
// path: their dihedral angles take a handful of values only.
std::optional<BinaryLattice> DetectBinaryLattice(const TriMesh& mesh);

// Per vertex of a binary-occupancy surface: whether it lies on a seed 003
// feature voxel, and the material and air samples at the ends of its edge.
struct BinaryVertices {
  std::vector<uint8_t> feature;
  std::vector<Eigen::Vector3d> inside, outside;
};

// Returns the BinaryVertices of `mesh` (a binary-occupancy mesh on `lattice`)
// from the occupancy the mesh bounds.
// Errors: INVALID_ARGUMENT if a vertex is off the lattice or the box of voxels
// exceeds max_voxels.
absl::StatusOr<BinaryVertices> BinaryMeshFeatures(const TriMesh& mesh, const BinaryLattice& lattice,
                                                  const VolumeParams& params = {});

// Returns the vertices of a binary-occupancy surface with its terraces
// relaxed: constrained surface nets (Gibson 1998) with the constraint the
// binary data states. Each non-feature vertex moves, `iterations` times,
// half way to the mean of its neighbours, projected onto its own edge
// between the material and the air sample (the data say only that the
// surface crosses there); feature vertices stay. A slanted plane becomes
// flat; convex surfaces sink by at most the slack of their edges, so fits
// belong on the original vertices.
std::vector<Eigen::Vector3d> RelaxTerraces(const TriMesh& mesh, const BinaryVertices& vertices,
                                           int iterations = 64);

// ---------------------------------------------------------------- simplify

struct SimplifyParams {
  // Stop at this many faces (0 = no face target).
  int64_t target_faces = 0;
  // Never make a collapse whose quadric error (root of the mean squared
  // distance to the planes it replaces) exceeds this, in model units; 0 = no
  // bound. At least one of the two must be set.
  double max_error = 0.0;
  // A collapse that turns a face normal by more than this is refused.
  double max_normal_flip_deg = 60.0;
  // On a mesh without given feature points, an edge across which the surface
  // turns by more than this (one-ring scale) is a crease: its vertices slide
  // only along their crease edges, and constraint planes (Garland-Heckbert)
  // price moving a line or a corner. 0 = no creases.
  double crease_deg = 30.0;
  // Measure Simplification::hausdorff (a second pass over both meshes).
  bool measure_hausdorff = true;
  // From this many faces up, the two halves of the mesh (split at the median
  // across its longest side) are first collapsed at once, each to 1.5 times
  // the share of faces asked of the whole; the last collapses are then
  // chosen across the whole mesh (the band between the halves included).
  int64_t two_lanes_min_faces = 200000;
};

struct HausdorffDistance {
  double input_to_output = 0.0;  // max over input vertices of the distance to the output
  double output_to_input = 0.0;  // max over output vertices and face centroids
  double Max() const { return std::max(input_to_output, output_to_input); }
};

struct Simplification {
  Mesh mesh;
  // One per output face: the label of the input face it came from (when
  // face labels were given), else empty.
  std::vector<int> face_labels;
  // One per output vertex: the input vertex it is.
  std::vector<int> input_vertex;
  HausdorffDistance hausdorff;
};

// Returns `mesh` simplified by QEM edge collapse (Garland-Heckbert quadrics,
// cheapest collapse first): `feature_vertex` (one per vertex, may be empty)
// marks feature points (the morphological feature voxels of ALGORITHMS.md S4 on a
// binary surface): an edge between two never collapses, an
// edge with one collapses onto it; otherwise the vertex goes to the
// quadric's optimum. Edges between faces of different `face_labels` (one per
// face, may be empty) are feature edges: their ends are feature points.
// Without feature points, the mesh's creases (params.crease_deg) and open
// borders are feature lines: their vertices slide along them only, priced
// by constraint planes through them. Stops at params.target_faces or when no collapse
// within params.max_error is left. Reports progress as "simplify".
// Errors (INVALID_ARGUMENT): neither target set, sizes that do not match the
// mesh, a mesh without faces; CANCELLED on stop.
absl::StatusOr<Simplification> Simplify(const TriMesh& mesh, const SimplifyParams& params,
                                        std::span<const uint8_t> feature_vertex = {},
                                        std::span<const int> face_labels = {},
                                        const RunContext& ctx = {});

// Returns the one-sided Hausdorff distances between `a` and `b`: exact
// point-to-triangle distances from every vertex (and face centroid) of one
// to the other, through a kd-tree of the other's face centroids.
HausdorffDistance Hausdorff(const TriMesh& a, const TriMesh& b);

// Returns the squared distance from p to the triangle abc.
double SquaredDistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace meshseg

#endif  // MESHSEG_VOXEL_H_
