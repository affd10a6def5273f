#include "generate/parts.h"

#include <functional>
#include <numbers>
#include <utility>

namespace meshseg::generate_internal {
namespace {

struct Entry {
  const char* name;
  std::function<PartSpec()> make;
};

// Smallest mesh first at the default voxel size (bench/generate measures).
std::vector<Entry> Catalogue() {
  return {
      {"small_block", SmallBlock},
      {"sphere_cap", SphereCap},
      {"rounded_prism", RoundedPrism},
      {"torus_ring", TorusRing},
      {"plate_boss", PlateBoss},
      {"stepped_shaft", SteppedShaft},
      {"blend_block", BlendBlock},
      {"test_piece", [] { return TestPiece("test_piece", 0.6); }},
      {"test_piece_large", [] { return TestPiece("test_piece_large", 0.15); }},
  };
}

}  // namespace

Eigen::Isometry3d Tilt(double degrees, const Eigen::Vector3d& axis, const Eigen::Vector3d& shift) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.rotate(Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, axis.normalized()));
  m.pretranslate(shift);
  return m;
}

std::optional<PartSpec> FindPart(std::string_view name) {
  for (const Entry& e : Catalogue()) {
    if (name == e.name) return e.make();
  }
  return std::nullopt;
}

std::vector<std::string> CatalogueNames() {
  std::vector<std::string> names;
  for (const Entry& e : Catalogue()) names.emplace_back(e.name);
  return names;
}

}  // namespace meshseg::generate_internal
