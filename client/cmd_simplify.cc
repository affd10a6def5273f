// meshseg simplify IN -o OUT (--target-faces N | --max-error E) [--regions RESULT.json
//                  [--labels-out LABELS.json]]
// Feature-preserving QEM (ALGORITHMS.md S4): a binary-occupancy mesh keeps
// the vertices at its feature voxels (the material's edges and corners); with --regions the region
// boundaries are kept and every face keeps its label, which --labels-out writes as a result JSON
// (face_labels per face of OUT; the regions of RESULT.json with OUT's face counts and areas).
// Prints the Hausdorff distance to IN.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <google/protobuf/util/json_util.h>

#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "meshseg/mesh.h"
#include "meshseg/proto/result_json.h"
#include "meshseg/status_macros.h"
#include "meshseg/v1/segmentation.pb.h"
#include "meshseg/voxel.h"

namespace meshseg::cli {
namespace {

// The largest face target taken: a mesh face count fits in an int.
constexpr double kMaxTargetFaces = 2147483647.0;

absl::StatusOr<v1::SegmentationResult> ReadResult(const std::string& path) {
  std::ifstream in(path);
  if (!in) return absl::NotFoundError(absl::StrCat("cannot open \"", path, "\""));
  std::stringstream text;
  text << in.rdbuf();
  v1::SegmentationResult result;
  google::protobuf::util::JsonParseOptions options;
  options.ignore_unknown_fields = true;
  if (!google::protobuf::util::JsonStringToMessage(text.str(), &result, options).ok()) {
    return absl::InvalidArgumentError(absl::StrCat("\"", path, "\" is not a result JSON"));
  }
  return result;
}

// One label per mesh face from a result whose face_labels follow the input
// file's faces (read from `path`).
absl::StatusOr<std::vector<int>> RegionLabels(const v1::SegmentationResult& result,
                                              const std::string& path, const Mesh& mesh) {
  if (static_cast<size_t>(result.face_labels_size()) != mesh.face_of_input.size()) {
    return absl::InvalidArgumentError(absl::StrCat("\"", path, "\" has ", result.face_labels_size(),
                                                   " face labels, the mesh ",
                                                   mesh.face_of_input.size(), " faces"));
  }
  std::vector<int> labels(mesh.tri.n_faces(), -1);
  for (size_t i = 0; i < mesh.face_of_input.size(); ++i) {
    if (mesh.face_of_input[i] >= 0)
      labels[mesh.face_of_input[i]] = result.face_labels(static_cast<int>(i));
  }
  return labels;
}

// The result `input` relabelled for the simplified mesh: its face labels,
// and each region's face count and area there.
v1::SegmentationResult SimplifiedResult(const v1::SegmentationResult& input,
                                        const Simplification& simple) {
  v1::SegmentationResult out;
  *out.mutable_regions() = input.regions();
  *out.mutable_surfaces() = input.surfaces();
  std::vector<int64_t> faces(out.regions_size(), 0);
  std::vector<double> area(out.regions_size(), 0.0);
  const TriMesh& m = simple.mesh.tri;
  for (auto f : m.faces()) {
    const int label = simple.face_labels[f.idx()];
    out.add_face_labels(label);
    if (label < 0 || label >= out.regions_size()) continue;
    ++faces[label];
    area[label] += m.calc_face_area(f);
  }
  for (int r = 0; r < out.regions_size(); ++r) {
    out.mutable_regions(r)->set_face_count(faces[r]);
    out.mutable_regions(r)->set_area(area[r]);
  }
  out.mutable_mesh()->set_face_count(static_cast<int64_t>(m.n_faces()));
  out.mutable_mesh()->set_mesh_face_count(static_cast<int64_t>(m.n_faces()));
  out.mutable_mesh()->set_vertex_count(static_cast<int64_t>(m.n_vertices()));
  return out;
}

}  // namespace

absl::Status RunSimplify(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(
      const Args args,
      Args::Parse(argv, {"-o", "--target-faces", "--max-error", "--regions", "--labels-out"}, {},
                  1));
  const std::optional<std::string> out = args.Value("-o");
  if (!out) return absl::InvalidArgumentError("-o OUT is required");
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> faces, args.Double("--target-faces"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> error, args.Double("--max-error"));
  if (faces && !(*faces >= 1.0 && *faces <= kMaxTargetFaces && std::floor(*faces) == *faces)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "--target-faces must be a whole number from 1 to ", static_cast<int64_t>(kMaxTargetFaces),
        ", got ", *args.Value("--target-faces")));
  }
  if (error && !(*error > 0.0)) {
    return absl::InvalidArgumentError(
        absl::StrCat("--max-error must be a distance > 0 in the mesh's units, got ",
                     *args.Value("--max-error")));
  }
  const std::optional<std::string> labels_out = args.Value("--labels-out");
  if (labels_out && !args.Has("--regions")) {
    return absl::InvalidArgumentError("--labels-out needs --regions RESULT.json");
  }
  SimplifyParams params;
  if (faces) params.target_faces = static_cast<int64_t>(*faces);
  if (error) params.max_error = *error;
  const absl::StatusOr<Mesh> mesh = ReadMesh(args.positional(0));
  if (!mesh.ok()) return mesh.status();
  std::vector<uint8_t> features;
  if (const std::optional<BinaryLattice> lattice = DetectBinaryLattice(mesh->tri)) {
    MESHSEG_ASSIGN_OR_RETURN(const BinaryVertices binary, BinaryMeshFeatures(mesh->tri, *lattice));
    features = binary.feature;
  }
  std::vector<int> labels;
  v1::SegmentationResult regions_in;
  if (const std::optional<std::string> regions = args.Value("--regions")) {
    MESHSEG_ASSIGN_OR_RETURN(regions_in, ReadResult(*regions));
    MESHSEG_ASSIGN_OR_RETURN(labels, RegionLabels(regions_in, *regions, *mesh));
  }
  const auto start = std::chrono::steady_clock::now();
  const absl::StatusOr<Simplification> simple = Simplify(mesh->tri, params, features, labels);
  if (!simple.ok()) return simple.status();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MESHSEG_RETURN_IF_ERROR(WriteMesh(simple->mesh.tri, *out));
  std::printf(
      "wrote %s: %zu -> %zu faces%s, Hausdorff %.6g to the input (%.6g in->out, %.6g out->in), "
      "%.2f s\n",
      out->c_str(), mesh->tri.n_faces(), simple->mesh.tri.n_faces(),
      features.empty() ? "" : " (binary occupancy: feature voxels kept)", simple->hausdorff.Max(),
      simple->hausdorff.input_to_output, simple->hausdorff.output_to_input, seconds);
  if (labels_out) {
    MESHSEG_ASSIGN_OR_RETURN(const std::string json,
                             ResultJson(SimplifiedResult(regions_in, *simple)));
    MESHSEG_RETURN_IF_ERROR(WriteTextFile(*labels_out, json));
    std::printf("wrote %s: a label per face of %s\n", labels_out->c_str(), out->c_str());
  }
  return absl::OkStatus();
}

}  // namespace meshseg::cli
