#include "proto/src/brep_to_proto.h"

namespace meshseg {

void SetBrep(const PipelineResult& result, v1::SegmentationResult* out) {
  if (!result.brep && result.brep_error.empty()) return;
  v1::BrepReport* b = out->mutable_brep();
  if (!result.brep) {
    b->set_error(result.brep_error);
    return;
  }
  const BrepReport& r = *result.brep;
  b->set_region_count(r.region_count);
  b->set_patch_count(r.patch_count);
  b->set_face_count(r.face_count);
  b->set_edge_count(r.edge_count);
  b->set_exact_edge_count(r.exact_edge_count);
  b->set_fitted_edge_count(r.fitted_edge_count);
  b->set_closed(r.closed);
  b->set_solid(r.solid);
  b->set_solid_count(r.solid_count);
  b->set_valid(r.valid);
  b->set_volume(r.volume);
  b->set_sewing_tolerance(r.sewing_tolerance);
  b->set_max_tolerance(r.max_tolerance);
  for (const BrepFaceFailure& f : r.failures) {
    v1::BrepFaceFailure* m = b->add_failures();
    m->set_region(f.region);
    m->set_patch(f.patch);
    m->set_reason(f.reason);
  }
  b->set_length_unit(r.length_unit);
  b->set_step_size(r.step_size);
}

}  // namespace meshseg
