// The uniform cubic B-spline of the tests' crease curves.
#ifndef MESHSEG_TESTS_CORE_SUBDIV_BSPLINE_H_
#define MESHSEG_TESTS_CORE_SUBDIV_BSPLINE_H_

#include <cmath>
#include <vector>

namespace meshseg::testing {

// Returns the uniform cubic B-spline with control values c[k] at knots k,
// at parameter u in [1, c.size() - 2] (de Boor's basis on [i, i + 1]).
inline double CubicBSpline(const std::vector<double>& c, double u) {
  int i = static_cast<int>(std::floor(u));
  if (i >= static_cast<int>(c.size()) - 2) i = static_cast<int>(c.size()) - 3;
  const double t = u - i;
  const double b0 = (1 - t) * (1 - t) * (1 - t) / 6.0;
  const double b1 = (3 * t * t * t - 6 * t * t + 4) / 6.0;
  const double b2 = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6.0;
  const double b3 = t * t * t / 6.0;
  return b0 * c[i - 1] + b1 * c[i] + b2 * c[i + 1] + b3 * c[i + 2];
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_SUBDIV_BSPLINE_H_
