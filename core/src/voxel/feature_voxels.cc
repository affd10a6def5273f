// FeatureVoxels(): seed 003 section 2.1. Erosion, dilation and the distance
// from the opened shape all come from one exact squared Euclidean distance
// transform (Felzenszwalb and Huttenlocher's lower envelope, one axis at a
// time): x lies in the erosion by the ball of radius r iff its distance to
// the complement exceeds r, in the dilation iff its distance to the set is at
// most r. The work box is the material's bounding box plus a margin of air.
#include <algorithm>
#include <cstdint>
#include <limits>

#include "meshseg/voxel.h"

namespace meshseg {
namespace {

constexpr int32_t kFar = std::numeric_limits<int32_t>::max() / 4;

struct Box {
  std::array<int, 3> n;
  size_t Size() const { return static_cast<size_t>(n[0]) * n[1] * n[2]; }
  size_t At(int i, int j, int k) const {
    return static_cast<size_t>(i) + static_cast<size_t>(n[0]) * (j + static_cast<size_t>(n[1]) * k);
  }
};

// 1D squared distance transform of f (0 at sites, kFar elsewhere) in place.
void Transform1d(std::vector<int32_t>& f, std::vector<int32_t>& d, std::vector<int>& v,
                 std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] >= kFar) continue;
    while (k >= 0) {
      const double s =
          ((f[q] + double(q) * q) - (f[v[k]] + double(v[k]) * v[k])) / (2.0 * (q - v[k]));
      if (s > z[k]) break;
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -1e300
                  : ((f[q] + double(q) * q) - (f[v[k - 1]] + double(v[k - 1]) * v[k - 1])) /
                        (2.0 * (q - v[k - 1]));
  }
  if (k < 0) {
    std::fill(d.begin(), d.begin() + n, kFar);
  } else {
    int j = 0;
    for (int q = 0; q < n; ++q) {
      while (j < k && z[j + 1] < q) ++j;
      const int64_t dq = q - v[j];
      d[q] = static_cast<int32_t>(std::min<int64_t>(kFar, dq * dq + f[v[j]]));
    }
  }
  std::copy(d.begin(), d.begin() + n, f.begin());
}

// Squared distance from every voxel to the nearest voxel with site[x] = 1.
std::vector<int32_t> SquaredDistance(const Box& b, const std::vector<uint8_t>& site) {
  std::vector<int32_t> dist(b.Size());
  for (size_t x = 0; x < dist.size(); ++x) dist[x] = site[x] ? 0 : kFar;
  const int longest = std::max({b.n[0], b.n[1], b.n[2]});
  std::vector<int32_t> f(longest), d(longest);
  std::vector<int> v(longest);
  std::vector<double> z(longest + 1);
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    f.resize(b.n[axis]);
    for (int u = 0; u < b.n[a1]; ++u) {
      for (int w = 0; w < b.n[a2]; ++w) {
        std::array<int, 3> c;
        c[a1] = u, c[a2] = w;
        for (int q = 0; q < b.n[axis]; ++q) {
          c[axis] = q;
          f[q] = dist[b.At(c[0], c[1], c[2])];
        }
        Transform1d(f, d, v, z);
        for (int q = 0; q < b.n[axis]; ++q) {
          c[axis] = q;
          dist[b.At(c[0], c[1], c[2])] = f[q];
        }
      }
    }
  }
  return dist;
}

// The tips of what opening `s` by a ball of radius r removes: voxels of
// P = s \ open(s) whose distance from open(s) no 6-neighbour exceeds.
std::vector<uint8_t> OpeningTips(const Box& b, const std::vector<uint8_t>& s, int r) {
  const int32_t r2 = r * r;
  std::vector<uint8_t> mark(s.size());
  for (size_t x = 0; x < s.size(); ++x) mark[x] = !s[x];
  std::vector<int32_t> dist = SquaredDistance(b, mark);                  // to the complement
  for (size_t x = 0; x < s.size(); ++x) mark[x] = s[x] && dist[x] > r2;  // erosion
  dist = SquaredDistance(b, mark);
  for (size_t x = 0; x < s.size(); ++x) mark[x] = dist[x] <= r2;  // opening
  std::vector<uint8_t> removed(s.size());
  for (size_t x = 0; x < s.size(); ++x) removed[x] = s[x] && !mark[x];
  dist = SquaredDistance(b, mark);  // distance from the opened shape
  std::vector<uint8_t> tips(s.size(), 0);
  for (int k = 0; k < b.n[2]; ++k) {
    for (int j = 0; j < b.n[1]; ++j) {
      for (int i = 0; i < b.n[0]; ++i) {
        const size_t x = b.At(i, j, k);
        if (!removed[x]) continue;
        bool top = true;
        const int c[3] = {i, j, k};
        for (int a = 0; a < 3 && top; ++a) {
          for (int step : {-1, 1}) {
            int e[3] = {c[0], c[1], c[2]};
            e[a] += step;
            if (e[a] < 0 || e[a] >= b.n[a]) continue;
            const size_t y = b.At(e[0], e[1], e[2]);
            if (removed[y] && dist[y] > dist[x]) top = false;
          }
        }
        tips[x] = top;
      }
    }
  }
  return tips;
}

}  // namespace

std::vector<uint8_t> FeatureVoxels(const Occupancy& occupancy, int opening_radius,
                                   int closing_radius) {
  const auto& d = occupancy.dims;
  std::vector<uint8_t> features(occupancy.inside.size(), 0);
  int lo[3] = {d[0], d[1], d[2]}, hi[3] = {-1, -1, -1};
  for (int k = 0; k < d[2]; ++k) {
    for (int j = 0; j < d[1]; ++j) {
      for (int i = 0; i < d[0]; ++i) {
        if (!occupancy.inside[occupancy.Index(i, j, k)]) continue;
        lo[0] = std::min(lo[0], i), hi[0] = std::max(hi[0], i);
        lo[1] = std::min(lo[1], j), hi[1] = std::max(hi[1], j);
        lo[2] = std::min(lo[2], k), hi[2] = std::max(hi[2], k);
      }
    }
  }
  if (hi[0] < 0) return features;
  // Air beyond the volume counts as air: the box may reach past it.
  const int margin = std::max(opening_radius, closing_radius) + 2;
  Box b;
  int off[3];
  for (int a = 0; a < 3; ++a) {
    off[a] = lo[a] - margin;
    b.n[a] = hi[a] - lo[a] + 1 + 2 * margin;
  }
  std::vector<uint8_t> s(b.Size(), 0), air(b.Size(), 0);
  for (int k = 0; k < b.n[2]; ++k) {
    for (int j = 0; j < b.n[1]; ++j) {
      for (int i = 0; i < b.n[0]; ++i) {
        const int gi = i + off[0], gj = j + off[1], gk = k + off[2];
        const bool in = gi >= 0 && gj >= 0 && gk >= 0 && gi < d[0] && gj < d[1] && gk < d[2] &&
                        occupancy.inside[occupancy.Index(gi, gj, gk)];
        s[b.At(i, j, k)] = in;
        air[b.At(i, j, k)] = !in;
      }
    }
  }
  // Convex features: tips of the opening's protrusions, material voxels.
  std::vector<uint8_t> convex =
      opening_radius > 0 ? OpeningTips(b, s, opening_radius) : std::vector<uint8_t>(b.Size(), 0);
  // Concave features: closing the material is opening the air; its tips lie
  // in the air, and the material voxels next to them are the features.
  const std::vector<uint8_t> concave =
      closing_radius > 0 ? OpeningTips(b, air, closing_radius) : std::vector<uint8_t>(b.Size(), 0);
  for (int k = 0; k < b.n[2]; ++k) {
    for (int j = 0; j < b.n[1]; ++j) {
      for (int i = 0; i < b.n[0]; ++i) {
        const size_t x = b.At(i, j, k);
        bool feature = convex[x] && s[x];
        if (!feature && s[x]) {
          const int c[3] = {i, j, k};
          for (int a = 0; a < 3 && !feature; ++a) {
            for (int step : {-1, 1}) {
              int e[3] = {c[0], c[1], c[2]};
              e[a] += step;
              if (e[a] >= 0 && e[a] < b.n[a] && concave[b.At(e[0], e[1], e[2])]) feature = true;
            }
          }
        }
        if (!feature) continue;
        const int gi = i + off[0], gj = j + off[1], gk = k + off[2];
        if (gi >= 0 && gj >= 0 && gk >= 0 && gi < d[0] && gj < d[1] && gk < d[2]) {
          features[occupancy.Index(gi, gj, gk)] = 1;
        }
      }
    }
  }
  return features;
}

}  // namespace meshseg
