// Temporary: fits not implemented yet report valid = false.
#include "fit/fit_internal.h"
#include "meshseg/fit.h"

namespace meshseg {

FitResult FitTorus(const FitInput&, const FitParams&) { return fit_internal::InvalidResult(Torus{}); }
FitResult FitQuadric(const FitInput&, const FitParams&) { return fit_internal::InvalidResult(Quadric{}); }

}  // namespace meshseg
