#include "subdiv/control_topology.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "absl/container/flat_hash_map.h"
#include "absl/strings/str_cat.h"

namespace meshseg::subdiv_internal {
namespace {

uint64_t EdgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<uint64_t>(a) << 32) | static_cast<uint32_t>(b);
}

absl::Status CheckVerticesAndFaces(const ControlMesh& mesh) {
  if (mesh.faces.empty()) return absl::InvalidArgumentError("subdiv: control mesh has no faces");
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!mesh.vertices[v].allFinite()) {
      return absl::InvalidArgumentError(
          absl::StrCat("subdiv: control vertex ", v, " has a NaN or infinite coordinate"));
    }
  }
  const int n = static_cast<int>(mesh.vertices.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& t = mesh.faces[f];
    for (int i = 0; i < 3; ++i) {
      if (t[i] < 0 || t[i] >= n) {
        return absl::InvalidArgumentError(absl::StrCat("subdiv: control face ", f, " has vertex ",
                                                       t[i], " outside [0, ", n, ")"));
      }
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      return absl::InvalidArgumentError(absl::StrCat(
          "subdiv: control face ", f, " repeats a vertex (", t[0], ", ", t[1], ", ", t[2], ")"));
    }
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<ControlTopology> BuildControlTopology(const ControlMesh& mesh) {
  if (absl::Status s = CheckVerticesAndFaces(mesh); !s.ok()) return s;
  ControlTopology topo;
  absl::flat_hash_map<uint64_t, int> edge_of;
  edge_of.reserve(mesh.faces.size() * 2);
  topo.face_edges.resize(mesh.faces.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& t = mesh.faces[f];
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
      auto [it, inserted] = edge_of.try_emplace(EdgeKey(a, b), static_cast<int>(topo.edges.size()));
      if (inserted) {
        topo.edges.push_back({std::min(a, b), std::max(a, b)});
        topo.opposite.push_back({c, -1});
      } else if (topo.opposite[it->second][1] == -1) {
        topo.opposite[it->second][1] = c;
      } else {
        return absl::InvalidArgumentError(absl::StrCat("subdiv: control edge (", a, ", ", b,
                                                       ") has more than 2 faces (face ", f, ")"));
      }
      topo.face_edges[f][i] = it->second;
    }
  }
  topo.sharp.assign(topo.edges.size(), 0);
  for (size_t e = 0; e < topo.edges.size(); ++e) topo.sharp[e] = topo.opposite[e][1] == -1;
  for (const auto& c : mesh.creases) {
    auto it = edge_of.find(EdgeKey(c[0], c[1]));
    if (it == edge_of.end()) {
      return absl::InvalidArgumentError(absl::StrCat("subdiv: crease (", c[0], ", ", c[1],
                                                     ") is not an edge of the control mesh"));
    }
    topo.sharp[it->second] = 1;
  }
  const int n = static_cast<int>(mesh.vertices.size());
  topo.vertex_edges.resize(n);
  std::vector<int> sharp_count(n, 0);
  for (size_t e = 0; e < topo.edges.size(); ++e) {
    for (int v : topo.edges[e]) {
      topo.vertex_edges[v].push_back(static_cast<int>(e));
      sharp_count[v] += topo.sharp[e];
    }
  }
  topo.kind.resize(n);
  for (int v = 0; v < n; ++v) {
    // A vertex no face uses has no neighbours to average: it stays.
    topo.kind[v] = topo.vertex_edges[v].empty() ? VertexKind::kCorner
                   : sharp_count[v] <= 1        ? VertexKind::kSmooth
                   : sharp_count[v] == 2        ? VertexKind::kCrease
                                                : VertexKind::kCorner;
  }
  for (int v : mesh.corners) {
    if (v < 0 || v >= n) {
      return absl::InvalidArgumentError(
          absl::StrCat("subdiv: corner vertex ", v, " outside [0, ", n, ")"));
    }
    topo.kind[v] = VertexKind::kCorner;
  }
  return topo;
}

}  // namespace meshseg::subdiv_internal
