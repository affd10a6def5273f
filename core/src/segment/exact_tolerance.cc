#include "segment/exact_tolerance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace meshseg::segment_internal {
namespace {

// At most this many coordinates are read for the representation (every
// k-th vertex): the format is one for the whole file.
constexpr std::size_t kMaxSampled = 3000;
constexpr int kMaxDecimalDigits = 15;

// A number within this many units in its last place of a short decimal is
// that decimal carried through a unit conversion: x 1000 or x 0.001 is not
// exact in binary, and moves a decimal off its nearest double by an ulp or
// two.
constexpr double kConversionUlps = 4.0;

// The fewest significant decimal digits that print `x` so it reads back
// within kConversionUlps of it; kMaxDecimalDigits + 1 if none up to
// kMaxDecimalDigits.
int DecimalDigits(double x) {
  char text[40];
  const double ulps = kConversionUlps * std::abs(x) * std::numeric_limits<double>::epsilon();
  for (int k = 1; k <= kMaxDecimalDigits; ++k) {
    std::snprintf(text, sizeof(text), "%.*g", k, x);
    if (std::abs(std::strtod(text, nullptr) - x) <= ulps) return k;
  }
  return kMaxDecimalDigits + 1;
}

}  // namespace

double CoordinateResolution(const std::vector<Eigen::Vector3d>& positions) {
  double largest = 0.0;
  for (const Eigen::Vector3d& p : positions) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  if (!(largest > 0.0)) return 0.0;
  const std::size_t stride = std::max<std::size_t>(1, positions.size() * 3 / kMaxSampled);
  bool float32 = true;
  int digits = 0;
  for (std::size_t v = 0; v < positions.size(); v += stride) {
    for (int k = 0; k < 3; ++k) {
      const double x = positions[v][k];
      float32 = float32 && static_cast<double>(static_cast<float>(x)) == x;
      if (digits <= kMaxDecimalDigits) digits = std::max(digits, DecimalDigits(x));
    }
  }
  int exponent = 0;
  std::frexp(largest, &exponent);  // largest = m 2^exponent, m in [0.5, 1)
  double resolution = std::ldexp(1.0, exponent - std::numeric_limits<double>::digits);
  if (float32) {
    resolution = std::ldexp(1.0, exponent - std::numeric_limits<float>::digits);
  }
  if (digits <= kMaxDecimalDigits) {
    const double decimal = std::pow(10.0, std::floor(std::log10(largest)) - digits + 1);
    resolution = float32 ? std::min(resolution, decimal) : decimal;
  }
  return resolution;
}

double PlanarityFloor(const FacetMesh& fm) {
  constexpr int kMaxFacets = 20000;
  const int n = fm.facet_count();
  const int stride = std::max(1, n / kMaxFacets);
  const double loosest = kLoosestExact * fm.diagonal;
  std::vector<double> d;
  for (int f = 0; f < n; f += stride) {
    if (fm.normal[f].isZero()) continue;
    const Eigen::Vector3d& p = fm.points[fm.corners[f][0]];
    for (const int g : fm.across[f]) {
      if (g < 0) continue;
      for (const int v : fm.corners[g]) {
        const double dist = std::abs(fm.normal[f].dot(fm.points[v] - p));
        if (dist < loosest) d.push_back(dist);
      }
    }
  }
  if (static_cast<int>(d.size()) < kMinFloorSamples) return 0.0;
  const auto k = d.begin() + static_cast<std::ptrdiff_t>(kFloorQuantile * (d.size() - 1));
  std::nth_element(d.begin(), k, d.end());
  return *k;
}

double ExactTolerance(const std::vector<Eigen::Vector3d>& positions, double diagonal,
                      double floor) {
  return std::max({kRoundingSpan * CoordinateResolution(positions), kModellerAccuracy * diagonal,
                   kFloorSpan * floor});
}

}  // namespace meshseg::segment_internal
