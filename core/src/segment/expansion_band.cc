#include "segment/expansion_band.h"

#include <algorithm>

namespace meshseg::segment_internal {

ExpansionBands::ExpansionBands(const SegmentContext& c, const std::vector<int>& labels,
                               int region_count)
    : c_(c),
      node_(c.vertex_count(), -1),
      listed_(c.vertex_count(), 0),
      touched_flag_(c.vertex_count(), 0),
      first_ring_(region_count) {
  for (int v = 0; v < c.vertex_count(); ++v) {
    if (OnBoundary(labels, v)) {
      listed_[v] = 1;
      boundary_.push_back(v);
    }
  }
  Regroup(labels);
}

bool ExpansionBands::OnBoundary(const std::vector<int>& labels, int v) const {
  for (const int u : c_.graph.Neighbors(v)) {
    if (labels[u] != labels[v]) return true;
  }
  return false;
}

void ExpansionBands::Touch(int v) {
  if (touched_flag_[v]) return;
  touched_flag_[v] = 1;
  touched_.push_back(v);
}

void ExpansionBands::Moved(std::span<const int> vertices) {
  for (const int v : vertices) {
    Touch(v);
    for (const int u : c_.graph.Neighbors(v)) Touch(u);
  }
}

void ExpansionBands::Regroup(const std::vector<int>& labels) {
  // The boundary now: the listed and the touched vertices still on one
  // (every other vertex has kept its label and its neighbours').
  std::vector<int> boundary;
  for (const int v : boundary_) listed_[v] = 0;
  for (const std::vector<int>* from : {&boundary_, &touched_}) {
    for (const int v : *from) {
      if (!listed_[v] && OnBoundary(labels, v)) {
        listed_[v] = 1;
        boundary.push_back(v);
      }
    }
  }
  for (const int v : touched_) touched_flag_[v] = 0;
  touched_.clear();
  boundary_.swap(boundary);
  for (std::vector<int>& ring : first_ring_) ring.clear();
  for (const int v : boundary_) {
    for (const int u : c_.graph.Neighbors(v)) {
      const int l = labels[u];
      if (l < 0 || l == labels[v]) continue;
      std::vector<int>& ring = first_ring_[l];
      if (ring.empty() || ring.back() != v) ring.push_back(v);
    }
  }
}

std::vector<int> ExpansionBands::Band(const std::vector<int>& labels, int alpha, int rings) {
  std::vector<int> band;
  if (rings < 1) return band;
  std::vector<int> ring;
  // The first ring, from the boundary grouped by region and the vertices
  // touched since.
  for (const std::vector<int>* from : {&first_ring_[alpha], &touched_}) {
    for (const int v : *from) {
      if (labels[v] == alpha || node_[v] >= 0) continue;
      const auto neighbours = c_.graph.Neighbors(v);
      if (std::none_of(neighbours.begin(), neighbours.end(),
                       [&](int u) { return labels[u] == alpha; })) {
        continue;
      }
      node_[v] = 0;
      ring.push_back(v);
    }
  }
  for (int k = 1; k <= rings && !ring.empty(); ++k) {
    band.insert(band.end(), ring.begin(), ring.end());
    if (k == rings) break;
    std::vector<int> next;
    for (const int v : ring) {
      for (const int u : c_.graph.Neighbors(v)) {
        if (labels[u] != alpha && node_[u] < 0) {
          node_[u] = 0;
          next.push_back(u);
        }
      }
    }
    ring.swap(next);
  }
  // Every vertex marked is in the band (each ring walked is added to it).
  std::sort(band.begin(), band.end());
  for (int k = 0; k < static_cast<int>(band.size()); ++k) node_[band[k]] = k;
  return band;
}

void ExpansionBands::Release(std::span<const int> band) {
  for (const int v : band) node_[v] = -1;
}

}  // namespace meshseg::segment_internal
