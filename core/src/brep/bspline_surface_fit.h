// A bicubic B-spline surface fitted to a quadric or freeform region: the
// region's vertices (on a quadric region first projected onto its quadric,
// seed 000 §5's closest point) as heights over their least-squares plane,
// control heights on a uniform grid by least squares with a small
// second-difference penalty (it fixes control points no vertex reaches and
// keeps the surface from oscillating between them). The grid reaches past
// the region so its neighbours' surfaces cross it.
#ifndef MESHSEG_SRC_BREP_BSPLINE_SURFACE_FIT_H_
#define MESHSEG_SRC_BREP_BSPLINE_SURFACE_FIT_H_

// meshseg (OpenMesh) headers come before OpenCASCADE ones: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "brep/region_samples.h"
#include "meshseg/segment.h"

#include <string>

#include <Geom_Surface.hxx>

namespace meshseg::brep_internal {

struct BsplineSurfaceFit {
  Handle(Geom_Surface) surface;  // null on failure
  double rms_distance = 0.0;     // of the vertices from it, model units
  std::string failure;
};

// Returns the B-spline of `region` (its vertices in `samples`); `l_avg` and
// `noise_sigma` set the grid spacing and the accepted error. Fails when the
// region is not a height field over its plane (it turns by 90 degrees or
// more) or the fit misses its vertices by more than the noise allows.
BsplineSurfaceFit FitBsplineSurface(const Region& region, const RegionSamples& samples,
                                    double l_avg, double noise_sigma);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_BSPLINE_SURFACE_FIT_H_
