#include "subdiv/feature_lines.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <queue>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

namespace meshseg::subdiv_internal {
namespace {

// A vertex whose set neighbours surround it, leaving no gap of more than
// this between consecutive ones (the sum of the face angles at it between
// them, intrinsic to the surface), is where lines meet or pass through: the
// three lines at a cube's corner leave gaps of 90 degrees. The set
// neighbours of a vertex on a band's border lie on one side of it, leaving
// a gap of about 180 degrees (less on an irregular or noisy mesh).
constexpr double kMinBorderGapRad = 150.0 * std::numbers::pi / 180.0;

// The largest sum of consecutive face angles at v between two set
// neighbours of v (2 pi on an open border or with none).
double LargestGap(const TriMesh& mesh, OpenMesh::VertexHandle v, const std::vector<uint8_t>& in) {
  struct Wedge {
    int from, to;  // ring neighbours, in the faces' orientation
    double angle;  // the face's angle at v
  };
  std::vector<Wedge> ring;
  const OpenMesh::Vec3d p = mesh.point(v);
  for (auto h : mesh.voh_range(v)) {
    if (h.is_boundary()) return 2 * std::numbers::pi;
    const auto a = h.to(), b = h.next().to();
    const OpenMesh::Vec3d da = mesh.point(a) - p, db = mesh.point(b) - p;
    ring.push_back({a.idx(), b.idx(),
                    std::atan2(OpenMesh::cross(da, db).norm(), OpenMesh::dot(da, db))});
  }
  int start = -1;
  for (size_t i = 0; i < ring.size() && start < 0; ++i) {
    if (in[ring[i].from]) start = static_cast<int>(i);
  }
  if (start < 0) return 2 * std::numbers::pi;
  double gap = 0.0, run = 0.0;
  int at = start;
  for (size_t step = 0; step < ring.size(); ++step) {
    run += ring[at].angle;
    const int next = ring[at].to;
    if (in[next]) gap = std::max(gap, std::exchange(run, 0.0));
    const auto it = std::find_if(ring.begin(), ring.end(),
                                 [next](const Wedge& w) { return w.from == next; });
    if (it == ring.end()) return 2 * std::numbers::pi;
    at = static_cast<int>(it - ring.begin());
  }
  return gap;
}

// The set neighbours of v in its 1-ring.
struct Ring {
  int inside = 0, outside = 0;
  int arcs = 0;  // runs of consecutive set neighbours
};

Ring CountRing(const TriMesh& mesh, OpenMesh::VertexHandle v, const std::vector<uint8_t>& in) {
  Ring r;
  for (auto h : mesh.voh_range(v)) {
    const int to = h.to().idx();
    if (!in[to]) {
      ++r.outside;
      continue;
    }
    ++r.inside;
    // The ring neighbour on the far side of edge (v, to): the third vertex
    // of the face of its opposite halfedge. An arc starts where it is out.
    const auto opp = h.opp();
    if (opp.is_boundary() || !in[opp.next().to().idx()]) ++r.arcs;
  }
  return r;
}

// Whether the set vertex v can leave the set `in` without changing its
// shape's topology: v has a neighbour outside (it is on the set's border),
// at least two inside (one inside is a line end, which stays), and its
// inside neighbours form one arc of its 1-ring, so they stay connected
// through the ring without v (the simple-vertex test of thinning on a
// triangulated surface, Rössl et al. 2000). A vertex its set neighbours
// surround also stays: removing it would connect them by a chord of its
// ring, which cuts a corner where lines meet.
bool Removable(const TriMesh& mesh, OpenMesh::VertexHandle v, const std::vector<uint8_t>& in) {
  const Ring r = CountRing(mesh, v, in);
  if (r.outside == 0 || r.inside < 2 || r.arcs != 1) return false;
  return LargestGap(mesh, v, in) >= kMinBorderGapRad;
}

// Adds the vertices outside `in` that their set neighbours surround (no
// gap of kMinBorderGapRad or more, as Removable keeps): where lines meet at
// a vertex the curvature fit missed (it can fail at a corner vertex of a
// coarse mesh, whose neighbourhood is three faces at right angles).
void FillJunctions(const TriMesh& mesh, std::vector<uint8_t>& in) {
  std::vector<int> fill;
  for (auto v : mesh.vertices()) {
    if (in[v.idx()] || mesh.is_isolated(v) || CountRing(mesh, v, in).inside < 3) continue;
    if (LargestGap(mesh, v, in) < kMinBorderGapRad) fill.push_back(v.idx());
  }
  for (int v : fill) in[v] = 1;
}

// Thins `in` in place to lines one vertex wide: border vertices leave in
// order of increasing strength while Removable, so what stays runs along
// the strength crest.
void Thin(const TriMesh& mesh, const std::vector<double>& strength, std::vector<uint8_t>& in) {
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (size_t v = 0; v < in.size(); ++v) {
    if (in[v]) queue.push({strength[v], static_cast<int>(v)});
  }
  while (!queue.empty()) {
    const int v = queue.top().second;
    queue.pop();
    const OpenMesh::VertexHandle vh(v);
    if (!in[v] || !Removable(mesh, vh, in)) continue;
    in[v] = 0;
    for (auto u : mesh.vv_range(vh)) {
      if (in[u.idx()]) queue.push({strength[u.idx()], u.idx()});
    }
  }
}

// Where three flagged edges bound a face (lines meeting at a corner whose
// ring has a chord between two of them, or in a small triangle), the
// longest is dropped: it is the chord cutting across, opposite the face's
// widest angle, while the lines run along the other two.
void BreakTriangles(const TriMesh& mesh, std::vector<uint8_t>& edge) {
  for (auto f : mesh.faces()) {
    int flagged = 0;
    OpenMesh::SmartEdgeHandle longest;
    double length = -1.0;
    for (auto fh : f.halfedges()) {
      flagged += edge[fh.edge().idx()];
      const double l = mesh.calc_edge_length(fh.edge());
      if (l > length) length = l, longest = fh.edge();
    }
    if (flagged == 3) edge[longest.idx()] = 0;
  }
}

// The flagged edges of v.
int Degree(const TriMesh& mesh, OpenMesh::VertexHandle v, const std::vector<uint8_t>& edge) {
  int d = 0;
  for (auto e : mesh.ve_range(v)) d += edge[e.idx()];
  return d;
}

// The edges of the chain that leaves v over `first` and runs through
// vertices of degree 2 up to a vertex of another degree (or back to v).
std::vector<int> WalkChain(const TriMesh& mesh, OpenMesh::VertexHandle v,
                           OpenMesh::SmartEdgeHandle first, const std::vector<uint8_t>& edge,
                           OpenMesh::VertexHandle* end) {
  std::vector<int> chain{first.idx()};
  OpenMesh::SmartEdgeHandle e = first;
  OpenMesh::VertexHandle w = e.v0() == v ? e.v1() : e.v0();
  while (w != v && Degree(mesh, w, edge) == 2) {
    for (auto next : mesh.ve_range(w)) {
      if (edge[next.idx()] && next != e) {
        e = next;
        break;
      }
    }
    chain.push_back(e.idx());
    w = e.v0() == w ? e.v1() : e.v0();
  }
  *end = w;
  return chain;
}

// Drops chains of fewer than `min_edges` edges that have a free end (spurs
// at a junction, isolated pieces), until none is left: a spur's removal can
// turn its junction into the inside of a longer line.
void PruneShortChains(const TriMesh& mesh, int min_edges, std::vector<uint8_t>& edge) {
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<int> drop;
    for (auto v : mesh.vertices()) {
      if (Degree(mesh, v, edge) != 1) continue;
      for (auto e : v.edges()) {
        if (!edge[e.idx()]) continue;
        OpenMesh::VertexHandle end;
        std::vector<int> chain = WalkChain(mesh, v, e, edge, &end);
        if (static_cast<int>(chain.size()) < min_edges) {
          drop.insert(drop.end(), chain.begin(), chain.end());
        }
      }
    }
    for (int e : drop) changed |= std::exchange(edge[e], 0) != 0;
  }
  // Closed loops without junctions: a loop of fewer than min_edges edges
  // circles a single noisy vertex or two.
  std::vector<uint8_t> seen(edge.size(), 0);
  for (auto v : mesh.vertices()) {
    if (Degree(mesh, v, edge) != 2) continue;
    for (auto e : v.edges()) {
      if (!edge[e.idx()] || seen[e.idx()]) continue;
      OpenMesh::VertexHandle end;
      const std::vector<int> chain = WalkChain(mesh, v, e, edge, &end);
      for (int c : chain) seen[c] = 1;
      if (end == v && static_cast<int>(chain.size()) < min_edges) {
        for (int c : chain) edge[c] = 0;
      }
      break;
    }
  }
}

// A line end's last edge that turns from the line by more than this and
// leads to a weaker vertex is a hook left by the thinning order: where a
// band ends square, one of its corner vertices becomes a line end (which
// stays) before its neighbour along the band's border leaves.
constexpr double kMaxEndTurnCos = 0.5;  // 60 degrees

// The other flagged edge's far vertex of the degree-2 vertex p, coming from e.
OpenMesh::VertexHandle OtherEnd(const TriMesh& mesh, OpenMesh::VertexHandle p, int from_edge,
                                const std::vector<uint8_t>& edge) {
  for (auto e : mesh.ve_range(p)) {
    if (edge[e.idx()] && e.idx() != from_edge) return e.v0() == p ? e.v1() : e.v0();
  }
  return OpenMesh::VertexHandle();
}

// Drops the hooks (kMaxEndTurnCos) at free line ends, once.
void TrimHooks(const TriMesh& mesh, const std::vector<double>& strength,
               std::vector<uint8_t>& edge) {
  std::vector<int> drop;
  for (auto v : mesh.vertices()) {
    if (Degree(mesh, v, edge) != 1) continue;
    for (auto e : v.edges()) {
      if (!edge[e.idx()]) continue;
      const OpenMesh::VertexHandle p = e.v0() == v ? e.v1() : e.v0();
      if (Degree(mesh, p, edge) != 2 || strength[v.idx()] >= strength[p.idx()]) break;
      const OpenMesh::VertexHandle q = OtherEnd(mesh, p, e.idx(), edge);
      const Eigen::Vector3d last = (ToEigen(mesh.point(v)) - ToEigen(mesh.point(p))).normalized();
      const Eigen::Vector3d along = (ToEigen(mesh.point(p)) - ToEigen(mesh.point(q))).normalized();
      if (last.dot(along) < kMaxEndTurnCos) drop.push_back(e.idx());
      break;
    }
  }
  for (int e : drop) edge[e] = 0;
}

}  // namespace

std::vector<uint8_t> RidgeVertices(const TriMesh& mesh, const CurvatureField& field,
                                   double radius_edges, double min_contrast) {
  const VertexGraph graph = BuildVertexGraph(mesh);
  std::vector<uint8_t> out(field.sharp.size(), 0);
  NeighborhoodScratch scratch;
  std::vector<int> around;
  std::vector<double> flank;
  for (size_t v = 0; v < out.size(); ++v) {
    if (!field.sharp[v] || mesh.is_isolated(OpenMesh::VertexHandle(static_cast<int>(v)))) continue;
    CollectNeighborhood(graph, static_cast<int>(v), radius_edges * field.mean_edge_length[v], {},
                        &scratch, &around);
    flank.clear();
    for (int u : around) flank.push_back(std::abs(field.kappa_max[u]));
    const auto quartile = flank.begin() + flank.size() / 4;
    std::nth_element(flank.begin(), quartile, flank.end());
    out[v] = std::abs(field.kappa_max[v]) >= min_contrast * *quartile;
  }
  return out;
}

FeatureLines DetectFeatureLines(const TriMesh& mesh, const std::vector<uint8_t>& sharp,
                                const std::vector<double>& strength, int min_edges) {
  std::vector<uint8_t> in(mesh.n_vertices(), 0);
  for (auto v : mesh.vertices()) in[v.idx()] = sharp[v.idx()] && !mesh.is_isolated(v);
  FillJunctions(mesh, in);
  Thin(mesh, strength, in);
  FeatureLines out{std::vector<uint8_t>(mesh.n_edges(), 0),
                   std::vector<int>(mesh.n_vertices(), 0)};
  for (auto e : mesh.edges()) out.edge[e.idx()] = in[e.v0().idx()] && in[e.v1().idx()];
  BreakTriangles(mesh, out.edge);
  PruneShortChains(mesh, min_edges, out.edge);
  TrimHooks(mesh, strength, out.edge);
  for (auto e : mesh.edges()) {
    if (!out.edge[e.idx()]) continue;
    ++out.count[e.v0().idx()];
    ++out.count[e.v1().idx()];
  }
  return out;
}

}  // namespace meshseg::subdiv_internal
