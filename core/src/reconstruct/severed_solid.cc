#include "reconstruct/severed_solid.h"

#include <algorithm>
#include <numeric>

#include "mesh/union_find.h"
#include "reconstruct/graph_cut.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

int64_t RejoinSeveredSolid(const TetMesh& tets, const std::vector<double>& f,
                           const std::vector<uint8_t>& by_sign, const std::vector<uint8_t>& sparse,
                           const std::vector<uint8_t>& seen_outside,
                           const std::vector<uint8_t>& tied, double epsilon,
                           std::vector<uint8_t>* inside) {
  std::vector<uint8_t>& in = *inside;
  const int n = static_cast<int>(in.size());
  // Tet-edge neighbours, compressed.
  std::vector<int> first(n + 1, 0);
  for (const auto& [a, b] : tets.edges) {
    ++first[a + 1];
    ++first[b + 1];
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<int> next(first.begin(), first.end() - 1);
  std::vector<int> nbr(first[n]);
  for (const auto& [a, b] : tets.edges) {
    nbr[next[a]++] = b;
    nbr[next[b]++] = a;
  }
  // Sets of inside vertices joined by tet edges.
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [a, b] : tets.edges) {
    if (!in[a] || !in[b]) continue;
    const int ra = FindRoot(parent, a), rb = FindRoot(parent, b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<int> size(n, 0);
  int main_root = -1;
  for (int v = 0; v < n; ++v) {
    if (!in[v]) continue;
    const int r = FindRoot(parent, v);
    if (++size[r] > (main_root < 0 ? 0 : size[main_root])) main_root = r;
  }
  if (main_root < 0) return 0;
  std::vector<uint8_t> joined(n, 0);  // the main solid, and what joins it
  std::vector<std::vector<int>> severed(n);
  for (int v = 0; v < n; ++v) {
    if (!in[v]) continue;
    const int r = FindRoot(parent, v);
    if (r == main_root) {
      joined[v] = 1;
    } else {
      severed[r].push_back(v);
    }
  }
  const auto resolved = [&](int v) { return ResolvedAt(tets, f, sparse, epsilon, v); };
  // Turned outside by the cut although f and the points leave it inside.
  const auto turned = [&](int v) {
    return by_sign[v] && !in[v] && (seen_outside.empty() || !seen_outside[v]);
  };
  // A resolved vertex the cut was free to turn (outside the set it ties to
  // the source) and turned outside is a severed piece of one vertex
  // (severed_solid.h), kept apart from the inside sets above.
  std::vector<std::vector<int>> pieces;
  for (int r = 0; r < n; ++r) {
    if (!severed[r].empty()) pieces.push_back(std::move(severed[r]));
  }
  for (int v = 0; v < n; ++v) {
    if (turned(v) && resolved(v) && !tied[v]) pieces.push_back({v});
  }
  std::vector<uint8_t> reached(n, 0);
  int64_t rejoined = 0;
  for (const std::vector<int>& piece : pieces) {
    if (std::none_of(piece.begin(), piece.end(), resolved)) continue;
    if (joined[piece.front()]) continue;  // a lone vertex a layer already took back
    std::vector<int> layers;  // the turned vertices reached so far, layer by layer
    std::vector<int> frontier = piece;
    std::vector<int> seen = piece;  // to clear `reached` after
    for (const int v : piece) reached[v] = 1;
    bool meets_main = false;
    while (!frontier.empty() && !meets_main) {
      std::vector<int> layer;
      for (const int v : frontier) {
        for (int e = first[v]; e < first[v + 1]; ++e) {
          const int u = nbr[e];
          meets_main = meets_main || joined[u];
          if (reached[u] || !turned(u)) continue;
          reached[u] = 1;
          seen.push_back(u);
          layer.push_back(u);
        }
      }
      if (meets_main) break;
      layers.insert(layers.end(), layer.begin(), layer.end());
      frontier = std::move(layer);
    }
    for (const int v : seen) reached[v] = 0;
    if (!meets_main) continue;
    for (const int v : piece) {
      rejoined += !in[v];
      in[v] = 1;
      joined[v] = 1;
    }
    for (const int v : layers) {
      in[v] = 1;
      joined[v] = 1;
      ++rejoined;
    }
  }
  return rejoined;
}

}  // namespace meshseg::reconstruct_internal
