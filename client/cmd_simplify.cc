// meshseg simplify IN -o OUT (--target-faces N | --max-error E) [--regions RESULT.json]
// Feature-preserving QEM (ALGORITHMS.md S4): a binary-occupancy mesh keeps
// the vertices at its feature voxels (the material's edges and corners); with --regions the region boundaries are kept
// and every face keeps its label. Prints the Hausdorff distance to IN.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <google/protobuf/util/json_util.h>

#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "meshseg/mesh.h"
#include "meshseg/status_macros.h"
#include "meshseg/v1/segmentation.pb.h"
#include "meshseg/voxel.h"

namespace meshseg::cli {
namespace {

// One label per mesh face from a result JSON whose face_labels follow the
// input file's faces.
absl::StatusOr<std::vector<int>> RegionLabels(const std::string& path, const Mesh& mesh) {
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

}  // namespace

absl::Status RunSimplify(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(
      const Args args,
      Args::Parse(argv, {"-o", "--target-faces", "--max-error", "--regions"}, {}, 1));
  const std::optional<std::string> out = args.Value("-o");
  if (!out) return absl::InvalidArgumentError("-o OUT is required");
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> faces, args.Double("--target-faces"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> error, args.Double("--max-error"));
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
  if (const std::optional<std::string> regions = args.Value("--regions")) {
    MESHSEG_ASSIGN_OR_RETURN(labels, RegionLabels(*regions, *mesh));
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
  return absl::OkStatus();
}

}  // namespace meshseg::cli
