// A region's surface as an OpenCASCADE surface: the analytic types as
// Geom_Plane, Geom_CylindricalSurface, Geom_ConicalSurface,
// Geom_SphericalSurface and Geom_ToroidalSurface, framed so the parameter
// seam and the poles lie away from the region; quadric and freeform regions
// as a B-spline fitted to the region's vertices (bspline_surface_fit.h).
#ifndef MESHSEG_SRC_BREP_OCCT_SURFACE_H_
#define MESHSEG_SRC_BREP_OCCT_SURFACE_H_

// meshseg (OpenMesh) headers come before OpenCASCADE ones: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "brep/region_samples.h"
#include "meshseg/segment.h"

#include <string>

#include <Geom_Surface.hxx>

namespace meshseg::brep_internal {

struct RegionSurface {
  Handle(Geom_Surface) surface;  // null when none could be made
  // +1: the surface normal (D1U x D1V) points out of the solid; -1: into it.
  int sign = 1;
  bool fitted = false;  // a B-spline fitted to the region (not its analytic surface)
  std::string failure;  // why `surface` is null
};

// Returns the OCCT surface of `region`. `l_avg` is the mesh's mean edge
// length, `noise_sigma` its noise (model units), both for the B-spline fit.
RegionSurface MakeRegionSurface(const Region& region, const RegionSamples& samples, double l_avg,
                                double noise_sigma);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_OCCT_SURFACE_H_
