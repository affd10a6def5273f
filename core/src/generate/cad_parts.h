// The catalogue of CAD-mode parts: exact B-reps built with OpenCASCADE from
// primitives, booleans, fillets and chamfers, in millimetres.
#ifndef MESHSEG_GENERATE_CAD_PARTS_H_
#define MESHSEG_GENERATE_CAD_PARTS_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <TopoDS_Shape.hxx>

namespace meshseg::generate_internal {

// Returns the solid `name` (mm), or nullopt if there is none.
// Errors of OpenCASCADE (a boolean or fillet that fails) come back as a null
// shape.
std::optional<TopoDS_Shape> FindCadPart(std::string_view name);

// Names FindCadPart knows, smallest mesh first.
std::vector<std::string> CadCatalogueNames();

}  // namespace meshseg::generate_internal

#endif  // MESHSEG_GENERATE_CAD_PARTS_H_
