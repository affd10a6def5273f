#include "meshseg/fit.h"

namespace meshseg {

FitResult FitOfType(SurfaceType type, const FitInput& input, const FitParams& params) {
  switch (type) {
    case SurfaceType::kPlane: return FitPlane(input, params);
    case SurfaceType::kCylinder: return FitCylinder(input, params);
    case SurfaceType::kCone: return FitCone(input, params);
    case SurfaceType::kSphere: return FitSphere(input, params);
    case SurfaceType::kTorus: return FitTorus(input, params);
    case SurfaceType::kQuadric:
    case SurfaceType::kFreeform: return FitQuadric(input, params);
  }
  return FitQuadric(input, params);
}

}  // namespace meshseg
