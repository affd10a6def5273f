// The decimation module of Simplify(): Garland-Heckbert quadrics (area-
// weighted face planes) with seed 003 section 2.2's rules for feature points,
// as one OpenMesh decimater priority module. OpenMesh collapses halfedges
// (v0 is removed, v1 stays); the module places v1 where the collapse puts the
// merged vertex before the collapse runs:
//   neither end a feature -> the quadric's optimum (the edge's best point if
//                            the quadric is singular);
//   both ends features     -> never collapsed;
//   one end a feature      -> at the feature end (v0 a feature: illegal, the
//                            opposite halfedge does it).
// A collapse that flips or nearly degenerates a face, or whose error exceeds
// the bound, is illegal.
#ifndef MESHSEG_VOXEL_FEATURE_QUADRIC_MODULE_H_
#define MESHSEG_VOXEL_FEATURE_QUADRIC_MODULE_H_

#include <cmath>
#include <string>

#include <Eigen/Dense>
#include <Eigen/LU>
#include <OpenMesh/Tools/Decimater/ModBaseT.hh>

#include "meshseg/mesh.h"

namespace meshseg::voxel_internal {

// Quadric of squared distances, weighted: x^T A x + 2 b^T x + c; `area` is
// the total weight, so error / area is a mean squared distance.
struct Quadric {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double c = 0.0;
  double area = 0.0;

  void AddPlane(const Eigen::Vector3d& n, double d, double w) {
    a += w * n * n.transpose();
    b += w * d * n;
    c += w * d * d;
    area += w;
  }
  Quadric& operator+=(const Quadric& q) {
    a += q.a, b += q.b, c += q.c, area += q.area;
    return *this;
  }
  double Error(const Eigen::Vector3d& x) const {
    return std::max(0.0, x.dot(a * x) + 2.0 * b.dot(x) + c);
  }
};

template <typename MeshT>
class ModFeatureQuadricT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(ModFeatureQuadricT, MeshT, FeatureQuadric);

  explicit ModFeatureQuadricT(MeshT& mesh) : Base(mesh, false) {
    mesh.add_property(quadric_);
    mesh.add_property(feature_);
  }
  ~ModFeatureQuadricT() override {
    Base::mesh().remove_property(quadric_);
    Base::mesh().remove_property(feature_);
  }

  // Error bound in model units (root mean squared distance); 0 = none.
  void set_max_error(double e) { max_error_ = e; }
  // Cosine of the largest turn of a face normal a collapse may cause.
  void set_min_cos_normal(double c) { min_cos_normal_ = c; }
  void set_feature(typename Mesh::VertexHandle v, bool f) {
    Base::mesh().property(feature_, v) = f;
  }
  bool feature(typename Mesh::VertexHandle v) const { return mesh_const().property(feature_, v); }

  void initialize() override {
    Mesh& m = Base::mesh();
    for (auto v : m.vertices()) m.property(quadric_, v) = Quadric{};
    for (auto f : m.faces()) {
      auto it = m.cfv_iter(f);
      const Eigen::Vector3d p0 = ToEigen(m.point(*it++));
      const Eigen::Vector3d p1 = ToEigen(m.point(*it++));
      const Eigen::Vector3d p2 = ToEigen(m.point(*it));
      Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
      const double twice_area = n.norm();
      if (twice_area == 0.0) continue;
      n /= twice_area;
      Quadric q;
      q.AddPlane(n, -n.dot(p0), 0.5 * twice_area);
      for (auto v : m.fv_range(f)) m.property(quadric_, v) += q;
    }
  }

  float collapse_priority(const CollapseInfo& ci) override {
    const bool f0 = feature(ci.v0), f1 = feature(ci.v1);
    if (f0) return Base::ILLEGAL_COLLAPSE;  // both, or v0 only: see the header
    Quadric q = mesh_const().property(quadric_, ci.v0);
    q += mesh_const().property(quadric_, ci.v1);
    const Eigen::Vector3d p0 = ToEigen(ci.p0), p1 = ToEigen(ci.p1);
    const Eigen::Vector3d x = f1 ? p1 : Optimum(q, p0, p1);
    const double error = q.Error(x);
    if (max_error_ > 0.0 && q.area > 0.0 && error > max_error_ * max_error_ * q.area) {
      return Base::ILLEGAL_COLLAPSE;
    }
    if (!NormalsKept(ci, x)) return Base::ILLEGAL_COLLAPSE;
    return static_cast<float>(error);
  }

  void preprocess_collapse(const CollapseInfo& ci) override {
    Mesh& m = Base::mesh();
    if (feature(ci.v1)) return;
    Quadric q = m.property(quadric_, ci.v0);
    q += m.property(quadric_, ci.v1);
    const Eigen::Vector3d x = Optimum(q, ToEigen(ci.p0), ToEigen(ci.p1));
    m.set_point(ci.v1, typename Mesh::Point(x.x(), x.y(), x.z()));
  }

  void postprocess_collapse(const CollapseInfo& ci) override {
    Mesh& m = Base::mesh();
    m.property(quadric_, ci.v1) += m.property(quadric_, ci.v0);
  }

 private:
  const Mesh& mesh_const() const { return const_cast<ModFeatureQuadricT*>(this)->Base::mesh(); }

  // argmin q over space if A is well conditioned (determinant against the
  // cube of its trace), else over the segment p0 p1.
  static Eigen::Vector3d Optimum(const Quadric& q, const Eigen::Vector3d& p0,
                                 const Eigen::Vector3d& p1) {
    const double trace = q.a.trace();
    const double det = q.a.determinant();
    if (trace > 0.0 && det > 1e-6 * trace * trace * trace) {
      const Eigen::Vector3d x = -(q.a.inverse() * q.b);
      // Stay near the edge: an optimum far off it is a conditioning artefact.
      if ((x - 0.5 * (p0 + p1)).squaredNorm() <= 4.0 * (p1 - p0).squaredNorm()) return x;
    }
    // Along the segment: minimise the 1D quadratic in t.
    const Eigen::Vector3d d = p1 - p0;
    const double dad = d.dot(q.a * d);
    double t = 0.5;
    if (dad > 0.0) t = std::clamp(-(d.dot(q.a * p0) + q.b.dot(d)) / dad, 0.0, 1.0);
    return p0 + t * d;
  }

  // No face around v0 or v1 that survives the collapse turns by more than
  // the limit or loses almost all its area when the merged vertex goes to x.
  bool NormalsKept(const CollapseInfo& ci, const Eigen::Vector3d& x) const {
    const Mesh& m = mesh_const();
    for (auto vh : {ci.v0, ci.v1}) {
      for (auto f : m.vf_range(vh)) {
        if (f == ci.fl || f == ci.fr) continue;
        Eigen::Vector3d p[3], q[3];
        int c = 0;
        for (auto v : m.fv_range(f)) {
          p[c] = ToEigen(m.point(v));
          q[c] = (v == ci.v0 || v == ci.v1) ? x : p[c];
          ++c;
        }
        const Eigen::Vector3d n0 = (p[1] - p[0]).cross(p[2] - p[0]);
        const Eigen::Vector3d n1 = (q[1] - q[0]).cross(q[2] - q[0]);
        const double l0 = n0.norm(), l1 = n1.norm();
        if (l0 == 0.0) continue;
        if (l1 <= 1e-8 * l0) return false;
        if (n0.dot(n1) < min_cos_normal_ * l0 * l1) return false;
      }
    }
    return true;
  }

  OpenMesh::VPropHandleT<Quadric> quadric_;
  OpenMesh::VPropHandleT<bool> feature_;
  double max_error_ = 0.0;
  double min_cos_normal_ = 0.5;
};

}  // namespace meshseg::voxel_internal

#endif  // MESHSEG_VOXEL_FEATURE_QUADRIC_MODULE_H_
