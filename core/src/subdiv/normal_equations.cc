#include "subdiv/normal_equations.h"

#include <algorithm>
#include <array>

#include <Eigen/Geometry>

namespace meshseg::subdiv_internal {

NormalAssembler::NormalAssembler(const LimitSurface& limit)
    : controls_(static_cast<int>(limit.from_control.cols())) {
  const SparseMatrix& w = limit.from_control;
  const auto& faces = limit.mesh.faces;
  stencil_start_.reserve(faces.size() + 1);
  stencil_start_.push_back(0);
  std::vector<int> slot(controls_, -1);
  for (const auto& t : faces) {
    const int begin = static_cast<int>(stencil_.size());
    for (int c = 0; c < 3; ++c) {
      for (SparseMatrix::InnerIterator it(w, t[c]); it; ++it) {
        const int v = static_cast<int>(it.col());
        if (slot[v] < 0) slot[v] = 0, stencil_.push_back(v);
      }
    }
    std::sort(stencil_.begin() + begin, stencil_.end());
    const int s = static_cast<int>(stencil_.size()) - begin;
    for (int k = 0; k < s; ++k) slot[stencil_[begin + k]] = k;
    const size_t wbegin = weight_.size();
    weight_.resize(wbegin + 3 * s, 0.0);
    for (int c = 0; c < 3; ++c) {
      for (SparseMatrix::InnerIterator it(w, t[c]); it; ++it) {
        weight_[wbegin + c * s + slot[it.col()]] += it.value();
      }
    }
    for (int k = begin; k < static_cast<int>(stencil_.size()); ++k) slot[stencil_[k]] = -1;
    stencil_start_.push_back(static_cast<int>(stencil_.size()));
  }
  // The pattern: vertex a's row holds every vertex sharing a face stencil
  // with it (faces per vertex first, then a marked union).
  std::vector<int> face_start(controls_ + 1, 0);
  for (int v : stencil_) ++face_start[v + 1];
  for (int v = 0; v < controls_; ++v) face_start[v + 1] += face_start[v];
  std::vector<int> face_of(stencil_.size());
  std::vector<int> fill(face_start.begin(), face_start.end() - 1);
  for (size_t f = 0; f + 1 < stencil_start_.size(); ++f) {
    for (int k = stencil_start_[f]; k < stencil_start_[f + 1]; ++k) {
      face_of[fill[stencil_[k]]++] = static_cast<int>(f);
    }
  }
  row_start_.assign(1, 0);
  for (int a = 0; a < controls_; ++a) {
    const size_t begin = row_.size();
    for (int i = face_start[a]; i < face_start[a + 1]; ++i) {
      const int f = face_of[i];
      for (int k = stencil_start_[f]; k < stencil_start_[f + 1]; ++k) {
        if (slot[stencil_[k]] < 0) slot[stencil_[k]] = 0, row_.push_back(stencil_[k]);
      }
    }
    if (slot[a] < 0) row_.push_back(a);  // a vertex no face depends on keeps its diagonal
    std::sort(row_.begin() + begin, row_.end());
    for (size_t k = begin; k < row_.size(); ++k) slot[row_[k]] = -1;
    row_start_.push_back(static_cast<int>(row_.size()));
  }
}

NormalEquations NormalAssembler::Assemble(const LimitSurface& limit,
                                          const std::vector<FootPoint>& feet,
                                          const std::vector<Eigen::Vector3d>& data,
                                          double alpha) const {
  const auto& x = limit.mesh.vertices;
  const auto& faces = limit.mesh.faces;
  // Barycentric moments per face: sum b b^T and sum b_c d.
  std::vector<Eigen::Matrix3d> bb(faces.size(), Eigen::Matrix3d::Zero());
  std::vector<Eigen::Matrix3d> bd(faces.size(), Eigen::Matrix3d::Zero());  // column c: sum b_c d
  std::vector<char> used(faces.size(), 0);
  for (size_t i = 0; i < feet.size(); ++i) {
    const FootPoint& p = feet[i];
    bb[p.face] += p.barycentric * p.barycentric.transpose();
    bd[p.face] += data[i] * p.barycentric.transpose();
    used[p.face] = 1;
  }
  // Blocks of A^T A in the pattern's order, 9 values per (row, neighbour).
  std::vector<double> block(9 * row_.size(), 0.0);
  Eigen::VectorXd atb = Eigen::VectorXd::Zero(3 * controls_);
  std::vector<int> position(controls_, -1);
  Eigen::MatrixXd g;
  for (size_t f = 0; f < faces.size(); ++f) {
    if (!used[f]) continue;
    const auto& t = faces[f];
    Eigen::Vector3d n = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
    const double area2 = n.norm();
    Eigen::Matrix3d k = Eigen::Matrix3d::Identity();
    if (area2 > 0.0) {
      n /= area2;
      k = n * n.transpose() + alpha * Eigen::Matrix3d::Identity();
    }
    const int begin = stencil_start_[f];
    const int s = stencil_start_[f + 1] - begin;
    const Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>> r(
        weight_.data() + 3 * begin, 3, s);
    g.noalias() = r.transpose() * bb[f] * r;  // s x s
    const Eigen::Matrix3d kd = k * bd[f];     // column c: K sum b_c d
    for (int ia = 0; ia < s; ++ia) {
      const int a = stencil_[begin + ia];
      atb.segment<3>(3 * a) += kd * r.col(ia);
      for (int j = row_start_[a]; j < row_start_[a + 1]; ++j) position[row_[j]] = j;
      for (int ib = 0; ib < s; ++ib) {
        Eigen::Map<Eigen::Matrix3d>(block.data() + 9 * position[stencil_[begin + ib]]) +=
            g(ia, ib) * k;
      }
    }
  }
  // Column 3a + c of the symmetric result is row 3a + c: the pattern's
  // neighbours of a, three entries each, ascending.
  NormalEquations out{Eigen::SparseMatrix<double>(3 * controls_, 3 * controls_), std::move(atb)};
  Eigen::VectorXi per_column(3 * controls_);
  for (int a = 0; a < controls_; ++a) {
    per_column.segment<3>(3 * a).setConstant(3 * (row_start_[a + 1] - row_start_[a]));
  }
  out.ata.reserve(per_column);
  for (int a = 0; a < controls_; ++a) {
    for (int c = 0; c < 3; ++c) {
      for (int j = row_start_[a]; j < row_start_[a + 1]; ++j) {
        const Eigen::Map<const Eigen::Matrix3d> b(block.data() + 9 * j);
        for (int l = 0; l < 3; ++l) out.ata.insert(3 * row_[j] + l, 3 * a + c) = b(l, c);
      }
    }
  }
  out.ata.makeCompressed();
  return out;
}

}  // namespace meshseg::subdiv_internal
