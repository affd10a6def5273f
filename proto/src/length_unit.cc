// An upload's length units (UploadHeader.length_unit, .step_unit) checked
// against the units a STEP file can declare (meshseg/brep.h).
#include <string>
#include <string_view>

#include "absl/strings/str_cat.h"
#include "meshseg/brep.h"
#include "meshseg/proto/convert.h"
#include "meshseg/status_macros.h"

namespace meshseg {

absl::StatusOr<std::string> LengthUnitFromWire(std::string_view field, std::string_view unit) {
  if (unit.empty()) return std::string();
  std::string canonical = CanonicalLengthUnit(unit);
  if (canonical.empty()) {
    return absl::InvalidArgumentError(absl::StrCat(std::string(field), " \"",
                                                   std::string(unit.substr(0, 64)),
                                                   "\" is not one of ", LengthUnitList()));
  }
  return canonical;
}

absl::StatusOr<std::string> StepUnitFromWire(std::string_view step_unit,
                                             std::string_view length_unit) {
  MESHSEG_ASSIGN_OR_RETURN(const std::string step, LengthUnitFromWire("step_unit", step_unit));
  MESHSEG_ASSIGN_OR_RETURN(const std::string length,
                           LengthUnitFromWire("length_unit", length_unit));
  if (!step.empty() && !length.empty() && step != length) {
    return absl::InvalidArgumentError(
        absl::StrCat("step_unit \"", step, "\" is not length_unit \"", length,
                     "\": the STEP file's coordinates are written unscaled, in the input's unit"));
  }
  if (!step.empty()) return step;
  if (!length.empty()) return length;
  return BrepParams{}.length_unit;
}

}  // namespace meshseg
