#include "subdiv/normal_equations.h"

#include <random>

#include <Eigen/Geometry>

#include "control_meshes.h"
#include "shapes.h"

namespace meshseg::subdiv_internal {
namespace {

TEST(NormalAssembler, EqualsTheProductsOfTheExplicitRows) {
  // The rows of A written out densely from their definition (normal
  // distance and sqrt(alpha) times the offset, per data point) for points
  // scattered around the limit surface of a creased control mesh: the
  // per-face assembly must give A^T A and A^T b to rounding.
  const ControlMesh control = testing::CreasedOctahedron();
  auto limit = SampleLimitSurface(control, 2);
  ASSERT_TRUE(limit.ok()) << limit.status();
  const Eigen::MatrixXd w(limit->from_control);
  const auto& x = limit->mesh.vertices;
  const auto& faces = limit->mesh.faces;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<FootPoint> feet;
  std::vector<Eigen::Vector3d> data;
  for (int i = 0; i < 400; ++i) {
    FootPoint p;
    p.face = static_cast<int>(u(rng) * faces.size());
    const double b1 = u(rng), b2 = u(rng) * (1.0 - b1);
    p.barycentric = Eigen::Vector3d(1.0 - b1 - b2, b1, b2);
    feet.push_back(p);
    data.push_back(Eigen::Vector3d(u(rng), u(rng), u(rng)));
  }
  const double alpha = 0.1;
  const int n = static_cast<int>(control.vertices.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4 * feet.size(), 3 * n);
  Eigen::VectorXd rhs(4 * feet.size());
  for (size_t i = 0; i < feet.size(); ++i) {
    const auto& t = faces[feet[i].face];
    const Eigen::Vector3d normal = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).normalized();
    Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(n);
    for (int c = 0; c < 3; ++c) r += feet[i].barycentric[c] * w.row(t[c]);
    for (int v = 0; v < n; ++v) {
      for (int k = 0; k < 3; ++k) {
        a(4 * i, 3 * v + k) = r[v] * normal[k];
        a(4 * i + 1 + k, 3 * v + k) = std::sqrt(alpha) * r[v];
      }
    }
    rhs[4 * i] = normal.dot(data[i]);
    rhs.segment<3>(4 * i + 1) = std::sqrt(alpha) * data[i];
  }
  const NormalAssembler assembler(*limit);
  const NormalEquations eq = assembler.Assemble(*limit, feet, data, alpha);
  const Eigen::MatrixXd ata = a.transpose() * a;
  EXPECT_LT((Eigen::MatrixXd(eq.ata) - ata).cwiseAbs().maxCoeff(),
            1e-12 * ata.cwiseAbs().maxCoeff());
  const Eigen::VectorXd atb = a.transpose() * rhs;
  EXPECT_LT((eq.atb - atb).cwiseAbs().maxCoeff(), 1e-12 * atb.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace meshseg::subdiv_internal
