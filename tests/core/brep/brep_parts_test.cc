// WriteStep on every generated part (sharp edges, through holes, turned
// steps, tangent fillets and rounds, a sphere cap, a free torus) at the
// default resolution h with noise 0.05 h, segmented by its ground truth with
// surfaces refitted on the noisy vertices: the STEP file read back is one
// valid closed solid, a face per region patch, the volume of the mesh, and
// the noise-free surface within max(3 sigma, 0.2 h) of the B-rep both ways.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ground_truth_regions.h"
#include "meshseg/brep.h"
#include "meshseg/generate.h"
#include "meshseg/topology.h"
#include "scratch_dir.h"
#include "step_checks.h"

namespace meshseg {
namespace {

constexpr double kNoise = 0.05;             // x h, the noise level
constexpr double kVolumeTolerance = 0.005;  // relative
constexpr double kBoundEdges = 0.2;         // x h: the bound is max(3 sigma, 0.2 h)
// Marching cubes cuts a sharp edge by up to about a voxel: B-rep samples
// within a voxel of an edge are held to that instead.
constexpr double kEdgeMargin = 1.0;  // x h
// Spacing of the samples taken on the B-rep faces.
constexpr double kSpacing = 2.0;  // x h
// Share of noisy vertices farther than the bound: Gaussian noise of 0.05 h
// puts 6e-5 of them beyond 4 sigma = 0.2 h on any surface, the true one too.
constexpr double kNoisyShare = 1e-3;

class WriteStepOnParts : public ::testing::TestWithParam<std::string> {};

TEST_P(WriteStepOnParts, OneValidSolidWithinTheNoise) {
  const std::string name = GetParam();
  absl::StatusOr<GeneratedPart> part = GeneratePart(name, {.noise = kNoise});
  ASSERT_TRUE(part.ok()) << part.status();
  absl::StatusOr<GeneratedPart> clean = GeneratePart(name, {.noise = 0.0});
  ASSERT_TRUE(clean.ok()) << clean.status();
  ASSERT_EQ(clean->mesh.tri.n_vertices(), part->mesh.tri.n_vertices());
  const double h = part->voxel_size;
  const double sigma = part->noise;
  const double bound = std::max(3.0 * sigma, kBoundEdges * h);

  const testing::TruthSegmentation truth = testing::TruthOf(*part);
  absl::StatusOr<Topology> topo = ExtractTopology(part->mesh, truth.face_labels, truth.regions);
  ASSERT_TRUE(topo.ok()) << topo.status();
  const std::string path = testing_files::ScratchPath(name + ".step");
  absl::StatusOr<BrepReport> report =
      WriteStep(part->mesh, truth.face_labels, truth.regions, *topo, path, {.noise_sigma = sigma});
  ASSERT_TRUE(report.ok()) << report.status();
  for (const BrepFaceFailure& f : report->failures) {
    ADD_FAILURE() << name << ": region " << f.region << " patch " << f.patch << ": " << f.reason;
  }

  absl::StatusOr<testing::StepModel> model = testing::ReadStep(path);
  ASSERT_TRUE(model.ok()) << model.status();
  const testing::ShapeFacts facts = testing::FactsOf(model->shape);
  EXPECT_TRUE(facts.valid) << name;
  EXPECT_EQ(facts.solids, 1) << name;
  EXPECT_EQ(facts.shells, 1) << name;
  EXPECT_EQ(facts.free_edges, 0) << name;
  EXPECT_EQ(facts.faces, report->patch_count) << name << ": one face per region patch";
  const double mesh_volume = testing::EnclosedVolume(part->mesh.tri);
  EXPECT_NEAR(facts.volume, mesh_volume, kVolumeTolerance * mesh_volume) << name;

  const testing::ShapeDistance to_brep(model->shape, kSpacing * h);
  EXPECT_EQ(to_brep.samples().untessellated_faces, 0) << name;
  double clean_max = 0.0;
  for (OpenMesh::VertexHandle v : clean->mesh.tri.vertices()) {
    double d = to_brep.Distance(ToEigen(clean->mesh.tri.point(v)));
    if (d > bound) d = to_brep.ExactDistance(ToEigen(clean->mesh.tri.point(v)));
    clean_max = std::max(clean_max, d);
  }
  EXPECT_LE(clean_max, bound) << name << ": noise-free vertex " << clean_max / h << " h off";
  int noisy_over = 0;
  for (OpenMesh::VertexHandle v : part->mesh.tri.vertices()) {
    const Eigen::Vector3d p = ToEigen(part->mesh.tri.point(v));
    noisy_over += to_brep.Distance(p) > bound && to_brep.ExactDistance(p) > bound;
  }
  EXPECT_LE(noisy_over, kNoisyShare * static_cast<double>(part->mesh.tri.n_vertices())) << name;

  const testing::MeshDistance to_mesh(clean->mesh.tri);
  const testing::EdgeSplitMax brep_max =
      testing::MaxDistanceToMesh(to_mesh, model->shape, to_brep.samples().points, kEdgeMargin * h);
  EXPECT_LE(brep_max.away, bound) << name << ": B-rep sample " << brep_max.away / h << " h off";
  EXPECT_LE(brep_max.near, kEdgeMargin * h) << name << ": near an edge " << brep_max.near / h;
}

INSTANTIATE_TEST_SUITE_P(Parts, WriteStepOnParts,
                         ::testing::Values("small_block", "test_piece", "stepped_shaft",
                                           "plate_boss", "rounded_prism", "blend_block",
                                           "sphere_cap", "torus_ring"));

}  // namespace
}  // namespace meshseg
