// The catalogue of named CT-like test parts. Each part is stated in its own
// coordinates (mm) and tilted into the scanner's frame.
#ifndef MESHSEG_GENERATE_PARTS_H_
#define MESHSEG_GENERATE_PARTS_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Geometry>

#include "generate/part_builder.h"

namespace meshseg::generate_internal {

// Returns the rigid motion: rotation by `degrees` about `axis`, then
// translation by `shift`.
Eigen::Isometry3d Tilt(double degrees, const Eigen::Vector3d& axis,
                       const Eigen::Vector3d& shift = Eigen::Vector3d::Zero());

// Returns the part `name`, or nullopt if there is none.
std::optional<PartSpec> FindPart(std::string_view name);

// Names FindPart knows, smallest mesh first.
std::vector<std::string> CatalogueNames();

// The parts, one function each (parts_machined.cc, parts_turned.cc).
PartSpec SmallBlock();
PartSpec TestPiece(const std::string& name, double default_voxel_size);
PartSpec BlendBlock();
PartSpec RoundedPrism();
PartSpec PlateBoss();
PartSpec SteppedShaft();
PartSpec SphereCap();
PartSpec TorusRing();

}  // namespace meshseg::generate_internal

#endif  // MESHSEG_GENERATE_PARTS_H_
