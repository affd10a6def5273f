// File: mesh.h
// -----------------------------------------------------------------------------
// The `mesh` stage: the triangle mesh every other stage works on, reading and
// writing it (STL ASCII/binary, OBJ, OFF, PLY ASCII/binary LE/BE), statistics,
// and the mapping from the faces of the input file to mesh faces so results
// can be reported per INPUT face in input order.
//
// In: a file path. Out: Mesh (OpenMesh TriMesh, double precision) plus the
// input-face map. Errors are absl::Status naming the file, the problem and
// where (line or byte offset).
#ifndef MESHSEG_MESH_H_
#define MESHSEG_MESH_H_

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

namespace meshseg {

struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
  FaceAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge);
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

// What building the mesh found in the input's indices. OpenMesh cannot hold
// non-manifold input, so these are counted before faces are added.
struct InputTopology {
  int64_t degenerate_face_count = 0;      // zero-area or repeated-index faces
  int64_t duplicate_face_count = 0;       // same vertex set as an earlier face
  int64_t refused_face_count = 0;         // refused by OpenMesh (complex edge/vertex)
  // Over the non-degenerate input triangles, duplicates included:
  int64_t non_manifold_edge_count = 0;    // edges of > 2 triangles
  int64_t non_manifold_vertex_count = 0;  // vertices whose triangles form > 1 fan
};

// A triangle mesh and where its faces came from.
// Cost note: OpenMesh 9 meshes have no move constructor, so moving a Mesh
// (e.g. `MESHSEG_ASSIGN_OR_RETURN(Mesh m, ReadMesh(p))`) deep-copies `tri`
// (0.8 s CPU for 2M triangles, bench/mesh). For big inputs keep the StatusOr
// and use `*result`, and pass meshes by reference.
struct Mesh {
  // Vertices in file order (STL: first appearance after welding); vertices no
  // kept face uses stay as isolated vertices. Face and vertex normals are set.
  TriMesh tri;
  // One entry per face of the input file, in file order: the index of the
  // mesh face it became, or -1 if it was dropped (degenerate, non-manifold,
  // duplicate). A polygon with n > 3 corners is fan-triangulated; its entry
  // is its first triangle.
  std::vector<int> face_of_input;
  // Vertex count as declared / read from the file (before welding for STL).
  int64_t input_vertex_count = 0;
  // The file name (no directories), for messages.
  std::string name;
  // Set by ReadMesh and BuildMesh; zero for a Mesh filled in by hand.
  InputTopology input_topology;
};

// Returns the mesh with `vertices` and indexed `triangles` (0-based), with the
// rules of ReadMesh: degenerate, duplicate and non-manifold triangles are
// dropped and map to -1 in face_of_input (one entry per triangle). No welding.
// `name` is used in messages.
// Errors (INVALID_ARGUMENT): NaN/Inf coordinates, out-of-range indices, no
// triangles, all triangles dropped.
absl::StatusOr<Mesh> BuildMesh(std::vector<Eigen::Vector3d> vertices,
                               const std::vector<std::array<int, 3>>& triangles,
                               std::string name);

// Copies an OpenMesh point into an Eigen vector.
inline Eigen::Vector3d ToEigen(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }

enum class FileFormat {
  kUnknown, kStl, kObj, kOff, kPly, kXyz, kPwn,
  // Volumes (meshseg/voxel.h): NRRD (.nrrd/.nhdr), MetaImage (.mha, .mhd +
  // data file) and headerless .raw samples.
  kNrrd, kMha, kMhd, kRaw,
};

// True for the volume formats (kNrrd, kMha, kMhd, kRaw).
inline bool IsVolumeFormat(FileFormat format) {
  return format == FileFormat::kNrrd || format == FileFormat::kMha || format == FileFormat::kMhd ||
         format == FileFormat::kRaw;
}

// "stl", "obj", ... ("unknown" for kUnknown).
const char* FileFormatName(FileFormat format);

// Returns the format of `path`: by extension, else by content sniffing.
// Errors: NOT_FOUND if the file cannot be opened; INVALID_ARGUMENT if neither
// extension nor content identify a supported format.
absl::StatusOr<FileFormat> DetectFileFormat(const std::string& path);

// True if `path` holds a point cloud (XYZ, PWN, or a PLY without faces).
absl::StatusOr<bool> IsPointCloudFile(const std::string& path);

struct ReadMeshOptions {
  // Overrides detection (e.g. a format hint sent with an upload).
  std::optional<FileFormat> format;
  // Upper bound on declared vertex/face counts; a header declaring more is
  // rejected before anything is allocated.
  int64_t max_elements = 200'000'000;
};

// Returns the mesh in `path`. STL corners with identical coordinates are
// welded. Degenerate (zero-area or repeated-index) and non-manifold faces are
// dropped and map to -1 in face_of_input.
// Errors (INVALID_ARGUMENT unless noted), each naming the file and the place:
// missing file (NOT_FOUND), unknown format, truncated binary data, counts that
// disagree with the data, NaN/Inf coordinates, out-of-range indices, declared
// counts over max_elements, an empty mesh, a mesh whose faces are all dropped.
absl::StatusOr<Mesh> ReadMesh(const std::string& path, const ReadMeshOptions& options = {});

struct MeshStats {
  int64_t input_vertex_count = 0;  // as in the file
  int64_t input_face_count = 0;    // as in the file
  int64_t vertex_count = 0;        // of the built mesh (after welding)
  int64_t face_count = 0;          // of the built mesh
  int64_t dropped_face_count = 0;  // input faces mapped to -1
  double mean_edge_length = 0.0;
  Eigen::Vector3d bbox_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d bbox_max = Eigen::Vector3d::Zero();
  int64_t boundary_edge_count = 0;
  int64_t non_manifold_edge_count = 0;    // edges of > 2 input faces
  int64_t non_manifold_vertex_count = 0;  // vertices whose faces form > 1 fan
  int64_t component_count = 0;            // face-connected components
  int64_t degenerate_face_count = 0;      // zero-area or repeated-index input faces
  int64_t isolated_vertex_count = 0;      // mesh vertices without a face
};

// Returns the statistics of `mesh`.
MeshStats MeshStatistics(const Mesh& mesh);

// Returns the mean edge length l_avg of `mesh` (0 for a mesh without edges).
double MeanEdgeLength(const TriMesh& mesh);

// Writes `mesh` as PLY (binary little-endian, double coordinates), OFF or OBJ
// (17 significant digits), all three reading back bit-identical, or binary
// STL (float32 coordinates and facet normals, as CAD systems export it),
// chosen by the extension of `path`. Errors: INVALID_ARGUMENT for another
// extension; INTERNAL if the file cannot be written.
absl::Status WriteMesh(const TriMesh& mesh, const std::string& path);

// Writes `mesh` as a binary PLY with one colour per face: faces with the same
// label share a colour, label -1 is grey. `face_labels` has one entry per mesh
// face. Errors: INVALID_ARGUMENT if the sizes differ; INTERNAL on write failure.
absl::Status WriteColoredPly(const TriMesh& mesh, const std::vector<int>& face_labels,
                             const std::string& path);

}  // namespace meshseg

#endif  // MESHSEG_MESH_H_
