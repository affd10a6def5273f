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
// That slack tells a converted decimal from any other number only where
// the decimal's own spacing is far coarser: a decimal of 12 digits is spaced
// by at least 1e-12 of the number, over 1000 times the slack. A decimal of
// 13 to 15 digits is spaced by as little as 1e-15, and a double of 16-17
// digits lies within 4 units in the last place of one of 15 digits about
// half the time: such a decimal must read back exactly.
constexpr int kMaxConvertedDigits = 12;

// The fewest significant decimal digits that print `x` so it reads back
// within kConversionUlps of it (exactly beyond kMaxConvertedDigits);
// kMaxDecimalDigits + 1 if none up to kMaxDecimalDigits.
int DecimalDigits(double x) {
  char text[40];
  const double ulps = kConversionUlps * std::abs(x) * std::numeric_limits<double>::epsilon();
  for (int k = 1; k <= kMaxDecimalDigits; ++k) {
    std::snprintf(text, sizeof(text), "%.*g", k, x);
    const double slack = k <= kMaxConvertedDigits ? ulps : 0.0;
    if (std::abs(std::strtod(text, nullptr) - x) <= slack) return k;
  }
  return kMaxDecimalDigits + 1;
}

// A length converted from one unit to another is multiplied by a power of
// ten (metric prefixes) or by the inch's 25.4 mm times a power of ten;
// a float32 file (binary STL) read in another unit is float32 times one of
// these. The powers span nanometres to kilometres.
constexpr int kLeastUnitPower = -9;
constexpr int kMostUnitPower = 9;
constexpr double kInchInMillimetres = 25.4;

// True if `x` / `factor` lies within kConversionUlps of a float32 value.
bool Float32Times(double x, double factor) {
  const double y = x / factor;
  const double nearest = static_cast<double>(static_cast<float>(y));
  return std::abs(nearest - y) <=
         kConversionUlps * std::abs(y) * std::numeric_limits<double>::epsilon();
}

// The unit factor s such that every coordinate read (every `stride`-th
// vertex) is a float32 times s, 1 first; 0 if there is none. With
// `decimal`, the coordinates are short decimals, and only s = 1 is tried: a
// short decimal is an integer times a power of ten, and so a float32 times
// one, which says nothing of a conversion.
double Float32Factor(const std::vector<Eigen::Vector3d>& positions, std::size_t stride,
                     bool decimal) {
  std::vector<double> factors = {1.0};
  for (int k = kLeastUnitPower; k <= kMostUnitPower && !decimal; ++k) {
    if (k != 0) factors.push_back(std::pow(10.0, k));
    factors.push_back(kInchInMillimetres * std::pow(10.0, k));
  }
  for (const double factor : factors) {
    bool all = true;
    for (std::size_t v = 0; all && v < positions.size(); v += stride) {
      for (int k = 0; all && k < 3; ++k) all = Float32Times(positions[v][k], factor);
    }
    if (all) return factor;
  }
  return 0.0;
}

}  // namespace

double CoordinateResolution(const std::vector<Eigen::Vector3d>& positions) {
  double largest = 0.0;
  for (const Eigen::Vector3d& p : positions) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  if (!(largest > 0.0)) return 0.0;
  const std::size_t stride = std::max<std::size_t>(1, positions.size() * 3 / kMaxSampled);
  int digits = 0;
  for (std::size_t v = 0; v < positions.size(); v += stride) {
    for (int k = 0; k < 3 && digits <= kMaxDecimalDigits; ++k) {
      digits = std::max(digits, DecimalDigits(positions[v][k]));
    }
  }
  int exponent = 0;
  std::frexp(largest, &exponent);  // largest = m 2^exponent, m in [0.5, 1)
  double resolution = std::ldexp(1.0, exponent - std::numeric_limits<double>::digits);
  const double factor = Float32Factor(positions, stride, digits <= kMaxDecimalDigits);
  const bool float32 = factor > 0.0;
  if (float32) {
    // The float32 spacing at the largest coordinate in the file's own unit.
    std::frexp(largest / factor, &exponent);
    resolution = factor * std::ldexp(1.0, exponent - std::numeric_limits<float>::digits);
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
