#include "subdiv/control_from_mesh.h"

#include "meshseg/curvature.h"
#include "shapes.h"

namespace meshseg::subdiv_internal {
namespace {

// The feature lines of `mesh` from its curvature field, as the fit finds them.
FeatureLines Features(const Mesh& mesh) {
  const absl::StatusOr<CurvatureField> field = EstimateCurvature(mesh);
  EXPECT_TRUE(field.ok()) << field.status();
  if (!field.ok()) return {};
  std::vector<double> strength;
  for (double k : field->kappa_max) strength.push_back(std::abs(k));
  return DetectFeatureLines(mesh.tri, RidgeVertices(mesh.tri, *field, 5.0, kMinRidgeContrast),
                            strength, 4);
}

TEST(ControlFromMesh, CubeKeepsItsEdgesAsCreasesAndCorners) {
  const testing::Triangles t = testing::Cube(1.0, 8);  // 768 faces
  auto mesh = testing::ToMesh(t, "cube");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto control = ControlFromMesh(mesh->tri, 60, Features(*mesh));
  ASSERT_TRUE(control.ok()) << control.status();
  EXPECT_LE(control->faces.size(), 60u);
  EXPECT_EQ(control->corners.size(), 8u);
  // Every crease lies on a cube edge: two coordinates at +-1.
  ASSERT_FALSE(control->creases.empty());
  for (const auto& c : control->creases) {
    for (int v : c) {
      const Eigen::Vector3d a = control->vertices[v].cwiseAbs();
      EXPECT_GE((a.array() > 1.0 - 1e-9).count(), 2) << control->vertices[v].transpose();
    }
    // ... and both ends on the same edge line.
    const Eigen::Vector3d d = control->vertices[c[0]] - control->vertices[c[1]];
    EXPECT_EQ((d.array().abs() > 1e-9).count(), 1) << "crease " << c[0] << "-" << c[1];
  }
  // Corners are the cube's.
  for (int v : control->corners) {
    EXPECT_TRUE(control->vertices[v].cwiseAbs().isApproxToConstant(1.0, 1e-9));
  }
}

TEST(ControlFromMesh, SmoothSphereHasNoCreases) {
  auto mesh = testing::ToMesh(testing::UnitIcosphere(3), "sphere");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto control = ControlFromMesh(mesh->tri, 100, Features(*mesh));
  ASSERT_TRUE(control.ok()) << control.status();
  EXPECT_LE(control->faces.size(), 100u);
  EXPECT_GE(control->faces.size(), 90u);
  EXPECT_TRUE(control->creases.empty());
  EXPECT_TRUE(control->corners.empty());
}

}  // namespace
}  // namespace meshseg::subdiv_internal
