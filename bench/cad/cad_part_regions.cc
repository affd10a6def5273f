// The exact-facet path on one CAD-mode generated part (meshseg/generate.h:
// GenerateCadPart), region by region against the part's B-rep faces: for
// each region its type, facet count, main parameters and the truth face
// most of its facets lie on; then the truth faces spread over more than one
// region or found as none. For looking into a case of
// tests/core/pipeline/cad_generated_test.cc.
// Usage: cad_part_regions PART coarse|fine [m|mm|um] [MESH_OUT]
//   MESH_OUT (.stl or .obj) also writes the tessellation.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace {

// Type name and main parameters of `s`.
std::string Describe(const meshseg::Surface& s) {
  char text[160];
  if (const auto* p = std::get_if<meshseg::Plane>(&s)) {
    std::snprintf(text, sizeof text, "plane offset %.9g", p->normal.dot(p->point));
  } else if (const auto* c = std::get_if<meshseg::Cylinder>(&s)) {
    std::snprintf(text, sizeof text, "cylinder r %.9g", c->radius);
  } else if (const auto* c = std::get_if<meshseg::Cone>(&s)) {
    std::snprintf(text, sizeof text, "cone half_angle %.9g apex (%.6g %.6g %.6g)", c->half_angle,
                  c->apex.x(), c->apex.y(), c->apex.z());
  } else if (const auto* c = std::get_if<meshseg::Sphere>(&s)) {
    std::snprintf(text, sizeof text, "sphere r %.9g", c->radius);
  } else if (const auto* c = std::get_if<meshseg::Torus>(&s)) {
    std::snprintf(text, sizeof text, "torus R %.9g r %.9g", c->major_radius, c->minor_radius);
  } else {
    std::snprintf(text, sizeof text, "freeform");
  }
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s PART coarse|fine [m|mm|um] [MESH_OUT]\n", argv[0]);
    return 2;
  }
  meshseg::CadParams params;
  params.deflection = std::string(argv[2]) == "fine" ? meshseg::CadDeflection::kFine
                                                     : meshseg::CadDeflection::kCoarse;
  const absl::StatusOr<double> scale = meshseg::UnitScale(argc > 3 ? argv[3] : "mm");
  if (!scale.ok()) {
    std::fprintf(stderr, "%s\n", scale.status().ToString().c_str());
    return 2;
  }
  params.unit_scale = *scale;
  const absl::StatusOr<meshseg::GeneratedPart> part = meshseg::GenerateCadPart(argv[1], params);
  if (!part.ok()) {
    std::fprintf(stderr, "%s\n", part.status().ToString().c_str());
    return 1;
  }
  if (argc > 4) {
    if (const absl::Status written = meshseg::WriteMesh(part->mesh.tri, argv[4]); !written.ok()) {
      std::fprintf(stderr, "%s\n", written.ToString().c_str());
      return 1;
    }
  }
  const std::clock_t cpu = std::clock();
  const auto wall = std::chrono::steady_clock::now();
  const absl::StatusOr<meshseg::Segmentation> seg = meshseg::SegmentExactFacets(part->mesh);
  if (!seg.ok()) {
    std::fprintf(stderr, "%s\n", seg.status().ToString().c_str());
    return 1;
  }
  std::printf(
      "%zu facets, %zu regions, %zu surfaces, %zu faces; segment %.3f s wall "
      "%.3f s cpu\n",
      part->mesh.tri.n_faces(), seg->regions.size(), seg->surfaces.size(), part->primitives.size(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(),
      static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC);
  // counts[region][face]
  std::vector<std::map<int, int>> counts(seg->regions.size());
  for (std::size_t f = 0; f < seg->face_labels.size(); ++f) {
    if (seg->face_labels[f] >= 0) ++counts[seg->face_labels[f]][part->face_primitive[f]];
  }
  std::map<int, std::vector<int>> regions_of_face;
  for (const meshseg::Region& r : seg->regions) {
    int face = -1, most = 0;
    for (const auto& [k, n] : counts[r.id]) {
      if (n > most) face = k, most = n;
    }
    regions_of_face[face].push_back(r.id);
    std::printf(
        "region %3d %5lld facets surface %3d %-60s rms %.2g max %.2g | "
        "face %d (%d)\n",
        r.id, static_cast<long long>(r.face_count), r.surface_id, Describe(r.surface).c_str(),
        r.rms_distance, r.max_distance, face, most);
  }
  for (const meshseg::PrimitiveTruth& p : part->primitives) {
    const std::vector<int>& rs = regions_of_face[p.id];
    if (rs.size() == 1) continue;
    std::printf("face %3d %-20s %-60s in %zu regions\n", p.id, p.name.c_str(),
                p.freeform ? "freeform" : Describe(p.surface).c_str(), rs.size());
  }
  return 0;
}
