// A solid as a min/max combination of the exact signed distances of analytic
// surfaces (negative inside). The combination is 1-Lipschitz, and on the
// boundary of the solid the "active" leaf (the one whose value the min/max
// picked) names the analytic surface the point lies on.
#ifndef MESHSEG_GENERATE_CSG_H_
#define MESHSEG_GENERATE_CSG_H_

#include <vector>

#include <Eigen/Core>

#include "meshseg/surface.h"

namespace meshseg::generate_internal {

// One analytic surface bounding a solid: the plane's negative half-space (its
// normal points out), the inside of a cylinder, cone (one nappe, opening
// along the axis), sphere or torus tube.
struct Leaf {
  Surface surface;
  int primitive = -1;  // ground-truth primitive id; -1 = auxiliary surface
  // Precomputed from `surface` for Value():
  SurfaceType type = SurfaceType::kPlane;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // point / axis origin / apex / centre
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   // unit normal or axis direction
  double r1 = 0.0;                                    // radius, major radius
  double r2 = 0.0;                                    // minor radius
  double sin_a = 0.0, cos_a = 1.0;                    // cone half-angle
};

// Returns the leaf of `surface` (any alternative but Quadric).
Leaf MakeLeaf(const Surface& surface, int primitive);

// Exact signed distance from p to the leaf's surface, negative inside.
double LeafValue(const Leaf& leaf, const Eigen::Vector3d& p);

class Csg {
 public:
  struct Value {
    double f = 0.0;  // < 0 inside the solid
    int leaf = -1;   // index into leaves() of the active leaf
  };

  // Each returns the id of a new node; children must exist already.
  int AddLeaf(const Leaf& leaf);
  int Union(std::vector<int> children);
  int Intersection(std::vector<int> children);
  int Complement(int child);
  int Difference(int a, int b) { return Intersection({a, Complement(b)}); }
  void SetRoot(int node) { root_ = node; }

  // Value of the root node at p.
  Value Eval(const Eigen::Vector3d& p) const { return EvalNode(root_, p); }
  const std::vector<Leaf>& leaves() const { return leaves_; }

 private:
  enum class Op { kLeaf, kUnion, kIntersection, kComplement };
  struct Node {
    Op op = Op::kLeaf;
    int leaf = -1;
    std::vector<int> children;
  };

  Value EvalNode(int node, const Eigen::Vector3d& p) const;

  std::vector<Leaf> leaves_;
  std::vector<Node> nodes_;
  int root_ = -1;
};

}  // namespace meshseg::generate_internal

#endif  // MESHSEG_GENERATE_CSG_H_
