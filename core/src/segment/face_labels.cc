#include "segment/face_labels.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <map>
#include <utility>

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "mesh/concurrent_union_find.h"

namespace meshseg::segment_internal {
namespace {

// The faces across each face's edges, in OpenMesh circulator order (-1 past
// the last): built once, in parallel, for every round of MergeFaceFragments.
using FaceNeighbors = std::vector<std::array<int, 3>>;

FaceNeighbors AdjacentFaces(const TriMesh& mesh) {
  const int nf = static_cast<int>(mesh.n_faces());
  FaceNeighbors out(nf);
  tbb::parallel_for(tbb::blocked_range<int>(0, nf, 4096), [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) {
      out[f] = {-1, -1, -1};
      int k = 0;
      for (auto it = mesh.cff_iter(TriMesh::FaceHandle(f)); it.is_valid() && k < 3; ++it) {
        out[f][k++] = it->idx();
      }
    }
  });
  return out;
}

// The edge-connected pieces of equally labelled faces (labels >= 0).
struct Pieces {
  std::vector<int> of_face;       // piece id per face, -1 if unlabelled
  std::vector<int> label;         // per piece
  std::vector<std::size_t> size;  // faces per piece
};

// The pieces are the components of the graph of equally labelled
// neighbours, found with a concurrent union-find (each edge joined once, side
// by side; mesh/concurrent_union_find.h). Every component's root is its
// smallest face, whatever order the joins ran in, so numbering the roots in
// face order gives each piece the id a search seeded in face order gives it.
Pieces FindPieces(const FaceNeighbors& adjacent, const std::vector<int>& labels) {
  const int nf = static_cast<int>(labels.size());
  std::vector<std::atomic<int>> parent = mesh_internal::SingletonSets(nf);
  tbb::parallel_for(tbb::blocked_range<int>(0, nf, 4096), [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) {
      if (labels[f] < 0) continue;
      for (const int g : adjacent[f]) {
        if (g < 0) break;
        if (g > f && labels[g] == labels[f]) mesh_internal::JoinToLowest(parent, f, g);
      }
    }
  });
  Pieces p;
  p.of_face = mesh_internal::NumberSets(
      parent, [&](int f) { return labels[f] >= 0; },
      [&](int f) {
        p.label.push_back(labels[f]);
        return static_cast<int>(p.label.size()) - 1;
      });
  p.size.assign(p.label.size(), 0);
  for (int f = 0; f < nf; ++f) {
    if (p.of_face[f] >= 0) ++p.size[p.of_face[f]];
  }
  return p;
}

// One round: the label each piece takes, -1 where it keeps its own (not a
// fragment, or no neighbour that is not one).
std::vector<int> FragmentLabels(const FaceNeighbors& adjacent, const std::vector<int>& labels,
                                const Pieces& p) {
  std::map<int, int> largest;  // label -> its largest piece
  for (int id = 0; id < static_cast<int>(p.label.size()); ++id) {
    auto [it, inserted] = largest.try_emplace(p.label[id], id);
    if (!inserted && p.size[id] > p.size[it->second]) it->second = id;
  }
  std::vector<char> fragment(p.label.size(), 0);
  for (std::size_t id = 0; id < fragment.size(); ++id) {
    fragment[id] = p.size[id] < kMaxFragmentFaces && largest[p.label[id]] != static_cast<int>(id);
  }
  std::map<int, std::map<int, int>> shared;  // fragment piece -> label -> edges
  for (std::size_t f = 0; f < labels.size(); ++f) {
    const int id = p.of_face[f];
    if (id < 0 || !fragment[id]) continue;
    std::map<int, int>& counts = shared[id];
    for (const int g : adjacent[f]) {
      if (g < 0) break;
      // Only pieces that stay count: two fragments side by side would
      // otherwise swap labels and stay fragments.
      const int other = p.of_face[g];
      if (other >= 0 && !fragment[other]) ++counts[p.label[other]];
    }
  }
  std::vector<int> out(p.label.size(), -1);
  for (const auto& [id, counts] : shared) {
    // The most shared edges; the map's order makes ties go to the lower label.
    const auto best = std::max_element(
        counts.begin(), counts.end(),
        [](const auto& x, const auto& y) { return x.second < y.second; });
    if (best != counts.end()) out[id] = best->first;
  }
  return out;
}

}  // namespace

void MergeFaceFragments(const TriMesh& mesh, std::vector<int>* face_labels) {
  const FaceNeighbors adjacent = AdjacentFaces(mesh);
  for (int round = 0; round < kMaxFragmentRounds; ++round) {
    const Pieces p = FindPieces(adjacent, *face_labels);
    const std::vector<int> relabel = FragmentLabels(adjacent, *face_labels, p);
    bool changed = false;
    for (std::size_t f = 0; f < face_labels->size(); ++f) {
      const int id = p.of_face[f];
      if (id < 0 || relabel[id] < 0) continue;
      (*face_labels)[f] = relabel[id];
      changed = true;
    }
    if (!changed) return;
  }
}

std::vector<int> FaceLabels(const SegmentContext& c, const TriMesh& mesh,
                            const std::vector<int>& labels,
                            const std::vector<RegionState>& regions) {
  const int nf = static_cast<int>(mesh.n_faces());
  std::vector<int> out(nf, -1);
  tbb::parallel_for(tbb::blocked_range<int>(0, nf, 2048), [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) {
      int v[3];
      int k = 0;
      for (auto it = mesh.cfv_iter(TriMesh::FaceHandle(f)); it.is_valid() && k < 3; ++it) {
        v[k++] = it->idx();
      }
      if (k != 3) continue;
      const int l0 = labels[v[0]];
      if (l0 == labels[v[1]] && l0 == labels[v[2]]) {
        out[f] = l0;
        continue;
      }
      const Eigen::Vector3d& a = c.position(v[0]);
      const Eigen::Vector3d& b = c.position(v[1]);
      const Eigen::Vector3d& d = c.position(v[2]);
      const Eigen::Vector3d centroid = (a + b + d) / 3.0;
      Eigen::Vector3d normal = (b - a).cross(d - a);
      if (normal.norm() > 0.0) normal.normalize();
      double best = -1.0;
      for (const int vi : v) {
        const int id = labels[vi];
        if (id < 0 || id == out[f]) continue;
        const double agree =
            std::abs(Project(regions[id].surface, centroid, normal).normal.dot(normal));
        if (agree > best || (agree == best && id < out[f])) {
          best = agree;
          out[f] = id;
        }
      }
    }
  });
  MergeFaceFragments(mesh, &out);
  return out;
}

}  // namespace meshseg::segment_internal
