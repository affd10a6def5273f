// The curvature filter of seed 002 A4: one median filter over the sharp-free
// 1-ring, then three mean filters, on non-sharp vertices.
#ifndef MESHSEG_SRC_CURVATURE_FILTER_CURVATURE_H_
#define MESHSEG_SRC_CURVATURE_FILTER_CURVATURE_H_

#include "curvature/spatial_order.h"
#include "meshseg/curvature.h"

namespace meshseg::curvature_internal {

// Filters field->kappa_max and kappa_min in place (sharp vertices keep their
// values and are not used by their neighbours), then restores
// |kappa_max| >= |kappa_min| by swapping values and directions. `walk` is
// the mesh's vertex graph in Morton order (spatial_order.h); the field is
// indexed by vertex as always.
void FilterCurvature(const OrderedGraph& walk, CurvatureField* field);

}  // namespace meshseg::curvature_internal

#endif  // MESHSEG_SRC_CURVATURE_FILTER_CURVATURE_H_
