#include "reconstruct/handle_loops.h"

#include <algorithm>
#include <array>
#include <functional>
#include <queue>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "mesh/union_find.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

namespace {

// Per-thread scratch of the ball searches; entries are valid where the
// stamp matches.
struct Scratch {
  explicit Scratch(const MeshGraph& g)
      : ball_stamp(g.ring_begin.size(), 0),
        tree_stamp(g.ring_begin.size(), 0),
        face_stamp(g.face_vertices.size(), 0),
        complex_stamp(g.ring_begin.size(), 0),
        edge_stamp(g.edge_faces.size(), 0),
        walk_stamp(g.face_vertices.size(), 0),
        dist(g.ring_begin.size()),
        parent(g.ring_begin.size()),
        parent_edge(g.ring_begin.size()),
        face_node(g.face_vertices.size()) {}
  uint32_t stamp = 0;
  std::vector<uint32_t> ball_stamp, tree_stamp, face_stamp, complex_stamp, edge_stamp, walk_stamp;
  std::vector<double> dist;
  std::vector<int> parent, parent_edge, face_node;
  std::vector<int> reached, ball_faces, union_parent, stack;
  std::vector<HandleLoop> loops;
  std::vector<int> covered;  // seeds whose balls lie in a disc
};

using QueueItem = std::pair<double, int>;
using MinQueue = std::priority_queue<QueueItem, std::vector<QueueItem>, std::greater<>>;

// A center of the covering claims the seeds within this many of its seed
// radii, and its covering ball reaches kCoverReach of them beyond (ShortLoops).
constexpr double kCoverClaim = 3.0;
constexpr double kCoverReach = 1.25;

bool EdgeInBall(const MeshGraph& g, const Scratch& s, int e) {
  for (const int f : g.edge_faces[e]) {
    if (f >= 0 && s.face_stamp[f] == s.stamp) return true;
  }
  return false;
}

// The geodesic ball of `radius` around `seed` under a new stamp: its
// vertices (reached, with dist) and, with `faces`, its faces (all three
// vertices in it). Returns the Euler characteristic of the complex of its
// faces (0 without `faces`).
int64_t GrowBall(const MeshGraph& g, int seed, double radius, Scratch* s, bool faces = true) {
  const uint32_t t = ++s->stamp;
  // The ball: vertices within the radius along edges, faces with all three.
  s->reached.clear();
  MinQueue queue;
  s->dist[seed] = 0.0;
  s->ball_stamp[seed] = t;
  queue.push({0.0, seed});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > s->dist[v]) continue;
    s->reached.push_back(v);
    for (int k = g.ring_begin[v]; k < g.ring_begin[v + 1]; ++k) {
      const int w = g.to[k];
      const double dw = d + g.length[k];
      if (dw > radius || (s->ball_stamp[w] == t && dw >= s->dist[w])) continue;
      s->ball_stamp[w] = t;
      s->dist[w] = dw;
      queue.push({dw, w});
    }
  }
  s->ball_faces.clear();
  if (!faces) return 0;
  for (const int v : s->reached) {
    for (int k = g.faces_begin[v]; k < g.faces_begin[v + 1]; ++k) {
      const int f = g.faces[k];
      if (s->face_stamp[f] == t) continue;
      const auto& fv = g.face_vertices[f];
      if (s->ball_stamp[fv[0]] != t || s->ball_stamp[fv[1]] != t || s->ball_stamp[fv[2]] != t)
        continue;
      s->face_stamp[f] = t;
      s->ball_faces.push_back(f);
    }
  }
  // A ball of Euler characteristic 1 is a disc (all but never disconnected
  // in a geodesic ball): no loop in it is non-contractible.
  int64_t chi = static_cast<int64_t>(s->ball_faces.size());
  for (const int f : s->ball_faces) {
    for (int k = 0; k < 3; ++k) {
      const int v = g.face_vertices[f][k], e = g.face_edges[f][k];
      if (s->complex_stamp[v] != t) ++chi;
      if (s->edge_stamp[e] != t) --chi;
      s->complex_stamp[v] = s->edge_stamp[e] = t;
    }
  }
  return chi;
}

// The shortest loop not contractible in the geodesic ball of `radius`
// around `seed` that passes through the seed (its tail to the seed
// dropped), if at most max_length long.
void ShortestLoopNear(const MeshGraph& g, int seed, double max_length, double radius, Scratch* s) {
  if (GrowBall(g, seed, radius, s) == 1) return;
  const uint32_t t = s->stamp;
  MinQueue queue;
  // The shortest-path tree of the ball's faces' edges from the seed.
  s->tree_stamp[seed] = t;
  s->dist[seed] = 0.0;
  s->parent[seed] = -1;
  s->parent_edge[seed] = -1;
  queue.push({0.0, seed});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > s->dist[v]) continue;
    for (int k = g.ring_begin[v]; k < g.ring_begin[v + 1]; ++k) {
      const int w = g.to[k];
      const double dw = d + g.length[k];
      if (!EdgeInBall(g, *s, g.edge[k]) || (s->tree_stamp[w] == t && dw >= s->dist[w])) continue;
      s->tree_stamp[w] = t;
      s->dist[w] = dw;
      s->parent[w] = v;
      s->parent_edge[w] = g.edge[k];
      queue.push({dw, w});
    }
  }
  // Dual nodes: the ball's faces the tree reaches, and node 0 for the outside.
  int nodes = 1;
  for (const int f : s->ball_faces) {
    const int v = g.face_vertices[f][0];
    s->face_node[f] = s->tree_stamp[v] == t ? nodes++ : -1;
  }
  const auto node_of = [&](int f) {
    return f >= 0 && s->face_stamp[f] == t && s->face_node[f] > 0 ? s->face_node[f] : 0;
  };
  struct DualEdge {
    double loop;
    int a, b, u, v;
  };
  std::vector<DualEdge> dual;
  for (const int f : s->ball_faces) {
    if (s->face_node[f] < 0) continue;
    for (int i = 0; i < 3; ++i) {
      const int e = g.face_edges[f][i];
      const int other = g.edge_faces[e][0] == f ? g.edge_faces[e][1] : g.edge_faces[e][0];
      if (node_of(other) > s->face_node[f]) continue;  // seen from the other face
      const int u = g.face_vertices[f][i];
      const int v = g.face_vertices[f][(i + 2) % 3];
      if (s->parent_edge[u] == e || s->parent_edge[v] == e) continue;  // a tree edge
      const double loop = s->dist[u] + s->dist[v] + g.edge_length[e];
      dual.push_back({loop, s->face_node[f], node_of(other), u, v});
    }
  }
  // The greedy cotree: longest loops first; an edge whose faces are already
  // joined closes a loop not contractible in the ball.
  std::sort(dual.begin(), dual.end(),
            [](const DualEdge& x, const DualEdge& y) { return x.loop > y.loop; });
  s->union_parent.resize(nodes);
  for (int i = 0; i < nodes; ++i) s->union_parent[i] = i;
  const DualEdge* shortest = nullptr;
  for (const DualEdge& d : dual) {
    const int a = FindRoot(s->union_parent, d.a), b = FindRoot(s->union_parent, d.b);
    if (a != b) {
      s->union_parent[a] = b;
    } else {
      shortest = &d;  // the last leftover is the shortest
    }
  }
  if (shortest == nullptr) return;
  // Both tree paths up to their common ancestor, and the edge between them.
  HandleLoop loop;
  std::vector<int> up;
  for (int v = shortest->u; v >= 0; v = s->parent[v]) up.push_back(v);
  int meet = shortest->v;
  std::vector<int> other;
  while (std::find(up.begin(), up.end(), meet) == up.end()) {
    other.push_back(meet);
    meet = s->parent[meet];
  }
  for (const int v : up) {
    loop.vertices.push_back(v);
    if (v == meet) break;
  }
  loop.vertices.insert(loop.vertices.end(), other.rbegin(), other.rend());
  const size_t n = loop.vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const int a = loop.vertices[i], b = loop.vertices[(i + 1) % n];
    for (int k = g.ring_begin[a]; k < g.ring_begin[a + 1]; ++k) {
      if (g.to[k] == b) loop.length += g.length[k];
    }
  }
  if (n >= 3 && loop.length <= max_length) s->loops.push_back(std::move(loop));
}

// Whether the faces of the current ball are one piece across their edges.
bool BallConnected(const MeshGraph& g, Scratch* s) {
  if (s->ball_faces.empty()) return false;
  const uint32_t t = s->stamp;
  s->stack.assign(1, s->ball_faces[0]);
  s->walk_stamp[s->ball_faces[0]] = t;
  size_t walked = 1;
  while (!s->stack.empty()) {
    const int f = s->stack.back();
    s->stack.pop_back();
    for (const int e : g.face_edges[f]) {
      for (const int o : g.edge_faces[e]) {
        if (o < 0 || s->face_stamp[o] != t || s->walk_stamp[o] == t) continue;
        s->walk_stamp[o] = t;
        s->stack.push_back(o);
        ++walked;
      }
    }
  }
  return walked == s->ball_faces.size();
}

// Seeds whose own search cannot find a loop that is cut (the covering below,
// in ShortLoops): the ball of radius cover[c] around each center c is grown
// once; where its faces are one piece with Euler characteristic 1, every
// seed v in it with dist(c, v) + radius[v] <= cover[c] is flagged.
std::vector<uint8_t> CoveredSeeds(const MeshGraph& g, const std::vector<int>& centers,
                                  const std::vector<double>& cover,
                                  const std::vector<double>& radius,
                                  tbb::enumerable_thread_specific<Scratch>* scratch) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, centers.size()), [&](const auto& range) {
    Scratch& s = scratch->local();
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const int c = centers[i];
      if (GrowBall(g, c, cover[c], &s) != 1 || !BallConnected(g, &s)) continue;
      for (const int v : s.reached) {
        // (A margin for the rounding of the two distance sums.)
        if (radius[v] > 0 && s.dist[v] + radius[v] <= cover[c] * (1 - 1e-9)) {
          s.covered.push_back(v);
        }
      }
    }
  });
  std::vector<uint8_t> covered(radius.size(), 0);
  for (Scratch& s : *scratch) {
    for (const int v : s.covered) covered[v] = 1;
    s.covered.clear();
  }
  return covered;
}

// Vertices within max_loop of a vertex flagged in `near` (all if empty).
std::vector<uint8_t> SeedArea(const MeshGraph& g, const std::vector<double>& max_loop,
                              const std::vector<uint8_t>& near) {
  const size_t nv = max_loop.size();
  if (near.empty()) return std::vector<uint8_t>(nv, 1);
  std::vector<double> dist(nv, -1.0);
  MinQueue queue;
  for (size_t v = 0; v < nv; ++v) {
    if (!near[v]) continue;
    dist[v] = 0.0;
    queue.push({0.0, static_cast<int>(v)});
  }
  std::vector<uint8_t> area(nv, 0);
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    area[v] = 1;
    for (int k = g.ring_begin[v]; k < g.ring_begin[v + 1]; ++k) {
      const int w = g.to[k];
      const double dw = d + g.length[k];
      if (dw > max_loop[w] || (dist[w] >= 0 && dw >= dist[w])) continue;
      dist[w] = dw;
      queue.push({dw, w});
    }
  }
  return area;
}

}  // namespace

MeshGraph MakeMeshGraph(const TriMesh& tri) {
  MeshGraph g;
  const size_t nv = tri.n_vertices();
  g.ring_begin.assign(nv + 1, 0);
  g.faces_begin.assign(nv + 1, 0);
  for (const auto v : tri.vertices()) {
    for (const auto h : tri.voh_range(v)) {
      g.to.push_back(tri.to_vertex_handle(h).idx());
      g.edge.push_back(tri.edge_handle(h).idx());
      g.length.push_back((tri.point(tri.to_vertex_handle(h)) - tri.point(v)).norm());
    }
    for (const auto f : tri.vf_range(v)) g.faces.push_back(f.idx());
    g.ring_begin[v.idx() + 1] = static_cast<int>(g.to.size());
    g.faces_begin[v.idx() + 1] = static_cast<int>(g.faces.size());
  }
  for (const auto f : tri.faces()) {
    std::array<int, 3> fv{}, fe{};
    int k = 0;
    for (const auto h : tri.fh_range(f)) {
      fv[k] = tri.to_vertex_handle(h).idx();
      fe[k++] = tri.edge_handle(h).idx();
    }
    g.face_vertices.push_back(fv);
    g.face_edges.push_back(fe);
  }
  for (const auto e : tri.edges()) {
    std::array<int, 2> ef{-1, -1};
    for (int i = 0; i < 2; ++i) {
      const auto f = tri.face_handle(tri.halfedge_handle(e, i));
      if (f.is_valid()) ef[i] = f.idx();
    }
    g.edge_faces.push_back(ef);
    g.edge_length.push_back(tri.calc_edge_length(e));
  }
  return g;
}

std::vector<HandleLoop> ShortLoops(const MeshGraph& g, const std::vector<double>& max_loop,
                                   const std::vector<uint8_t>& near) {
  const int nv = static_cast<int>(max_loop.size());
  std::vector<int> seeds;
  std::vector<uint8_t> near_seed(nv, 0);
  std::vector<double> radius(nv, 0.0);  // of each seed's ball
  const std::vector<uint8_t> area = SeedArea(g, max_loop, near);
  for (int v = 0; v < nv; ++v) {
    if (near_seed[v] || !area[v] || !(max_loop[v] > 0)) continue;
    seeds.push_back(v);
    double reach = 0.0;
    for (int k = g.ring_begin[v]; k < g.ring_begin[v + 1]; ++k) {
      near_seed[g.to[k]] = 1;
      reach = std::max(reach, g.length[k]);
    }
    radius[v] = 0.5 * max_loop[v] + reach;
  }
  tbb::enumerable_thread_specific<Scratch> scratch([&] { return Scratch(g); });
  // The covering. A seed's search finds loops inside its ball, and the
  // global test (handle_strips.h) cuts a loop only if it does not separate
  // the surface. A simple closed curve on a surface separates it when it is
  // a boundary over Z2 (its class in H1(S; Z2) is 0). A connected complex
  // of faces with Euler characteristic 1 that is not a whole closed surface
  // (whose χ would be even) has b2 = 0, hence b1 = b0 − χ = 0 over Z2: every
  // loop inside it is a boundary there, hence on the surface, and separates.
  // So a seed whose ball lies in such a complex finds no loop that could be
  // cut, and its own search is skipped. Centers are taken greedily from the
  // seeds, each claiming the seeds within kCoverClaim of its own radius; its
  // covering ball reaches kCoverReach of its radius beyond, holding the
  // balls of the seeds it claimed where their radii are alike. Seeds left
  // uncovered (near a handle, on a part thinner than a covering ball) are
  // searched as before.
  // What a skipped loop did was cost a check against the whole surface and
  // mark its vertices as on a separating loop (handle_strips.cc).
  std::vector<int> centers;
  std::vector<double> cover(nv, 0.0);
  {
    Scratch& s = scratch.local();
    std::vector<uint8_t> claimed(nv, 0);
    for (const int v : seeds) {
      if (claimed[v]) continue;
      centers.push_back(v);
      cover[v] = (kCoverClaim + kCoverReach) * radius[v];
      GrowBall(g, v, kCoverClaim * radius[v], &s, false);
      for (const int w : s.reached) claimed[w] = 1;
    }
  }
  const std::vector<uint8_t> covered = CoveredSeeds(g, centers, cover, radius, &scratch);
  std::vector<int> searched;
  for (const int v : seeds) {
    if (!covered[v]) searched.push_back(v);
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, searched.size()), [&](const auto& range) {
    Scratch& s = scratch.local();
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const int v = searched[i];
      ShortestLoopNear(g, v, max_loop[v], radius[v], &s);
    }
  });
  std::vector<HandleLoop> loops;
  for (Scratch& s : scratch) {
    for (HandleLoop& l : s.loops) loops.push_back(std::move(l));
  }
  std::sort(loops.begin(), loops.end(), [](const HandleLoop& a, const HandleLoop& b) {
    return a.length != b.length ? a.length < b.length : a.vertices < b.vertices;
  });
  return loops;
}

}  // namespace meshseg::reconstruct_internal
