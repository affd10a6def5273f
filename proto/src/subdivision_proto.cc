#include "proto/src/subdivision_proto.h"

#include <cmath>
#include <string>

#include "absl/strings/str_cat.h"

namespace meshseg {
namespace {

void SetOne(const RegionSubdivision& s, v1::SubdivisionSurface* out) {
  const ControlMesh& c = s.control;
  out->mutable_vertices()->Reserve(static_cast<int>(3 * c.vertices.size()));
  for (const Eigen::Vector3d& p : c.vertices) {
    out->add_vertices(p.x());
    out->add_vertices(p.y());
    out->add_vertices(p.z());
  }
  for (const std::array<int, 3>& f : c.faces) out->mutable_faces()->Add(f.begin(), f.end());
  for (const std::array<int, 2>& e : c.creases) out->mutable_creases()->Add(e.begin(), e.end());
  out->mutable_corners()->Add(c.corners.begin(), c.corners.end());
  out->set_rms_distance(s.rms_distance);
  out->set_max_distance(s.max_distance);
}

// Copies `ids` (a flat array of N-tuples named `what`) into `out`, checking
// each id against `vertex_count`.
template <size_t N>
absl::Status Ids(const google::protobuf::RepeatedField<int32_t>& ids, int region, const char* what,
                 int vertex_count, std::vector<std::array<int, N>>* out) {
  if (ids.size() % N != 0) {
    return absl::InvalidArgumentError(absl::StrCat("result region ", region, " subdivision ", what,
                                                   " has ", ids.size(), " ids, not a multiple of ",
                                                   N));
  }
  for (int k = 0; k < ids.size(); k += static_cast<int>(N)) {
    std::array<int, N> t{};
    for (size_t i = 0; i < N; ++i) {
      t[i] = ids[k + static_cast<int>(i)];
      if (t[i] < 0 || t[i] >= vertex_count) {
        return absl::InvalidArgumentError(absl::StrCat("result region ", region, " subdivision ",
                                                       what, " id ", t[i], " is outside [0, ",
                                                       vertex_count, ")"));
      }
    }
    out->push_back(t);
  }
  return absl::OkStatus();
}

absl::StatusOr<RegionSubdivision> FromOne(const v1::SubdivisionSurface& s, int region) {
  RegionSubdivision out;
  out.region = region;
  out.rms_distance = s.rms_distance();
  out.max_distance = s.max_distance();
  if (s.vertices_size() % 3 != 0) {
    return absl::InvalidArgumentError(absl::StrCat("result region ", region,
                                                   " subdivision vertices has ", s.vertices_size(),
                                                   " numbers, not a multiple of 3"));
  }
  for (int k = 0; k < s.vertices_size(); k += 3) {
    const Eigen::Vector3d p(s.vertices(k), s.vertices(k + 1), s.vertices(k + 2));
    if (!p.allFinite()) {
      return absl::InvalidArgumentError(
          absl::StrCat("result region ", region, " subdivision vertex ", k / 3, " is not finite"));
    }
    out.control.vertices.push_back(p);
  }
  const int n = static_cast<int>(out.control.vertices.size());
  absl::Status status = Ids<3>(s.faces(), region, "faces", n, &out.control.faces);
  if (status.ok()) status = Ids<2>(s.creases(), region, "creases", n, &out.control.creases);
  if (!status.ok()) return status;
  std::vector<std::array<int, 1>> corners;
  if (absl::Status c = Ids<1>(s.corners(), region, "corners", n, &corners); !c.ok()) return c;
  for (const std::array<int, 1>& c : corners) out.control.corners.push_back(c[0]);
  return out;
}

}  // namespace

void SetSubdivisions(const std::vector<RegionSubdivision>& subdivisions,
                     v1::SegmentationResult* out) {
  for (const RegionSubdivision& s : subdivisions) {
    if (s.region < 0 || s.region >= out->regions_size()) continue;
    SetOne(s, out->mutable_regions(s.region)->mutable_subdivision());
  }
}

absl::StatusOr<std::vector<RegionSubdivision>> SubdivisionsFromProto(
    const v1::SegmentationResult& result) {
  std::vector<RegionSubdivision> out;
  for (int k = 0; k < result.regions_size(); ++k) {
    if (!result.regions(k).has_subdivision()) continue;
    absl::StatusOr<RegionSubdivision> s = FromOne(result.regions(k).subdivision(), k);
    if (!s.ok()) return s.status();
    out.push_back(*std::move(s));
  }
  return out;
}

}  // namespace meshseg
