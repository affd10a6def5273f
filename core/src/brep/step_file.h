// Writing the B-rep as a STEP AP214 file: the declared length unit, the
// product name and a name per face.
#ifndef MESHSEG_SRC_BREP_STEP_FILE_H_
#define MESHSEG_SRC_BREP_STEP_FILE_H_

#include <functional>
#include <string>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "absl/status/status.h"

namespace meshseg::brep_internal {

// The STEP name of a unit BrepParams::length_unit accepts ("mm" -> "MM"),
// or "" for an unknown one.
std::string StepUnitName(const std::string& unit);

// The units StepUnitName knows, as BrepParams names them: "mm, cm, m, ...".
std::string StepUnitList();

// Writes `shape` to `path` with its coordinates as they are, declared in
// `unit` (BrepParams::length_unit), each face named by `face_name` (an empty
// name leaves the face unnamed).
// Errors: INVALID_ARGUMENT for an unknown unit; INTERNAL when the transfer
// or the write fails (naming the path).
absl::Status WriteStepFile(const TopoDS_Shape& shape,
                           const std::function<std::string(const TopoDS_Face&)>& face_name,
                           const std::string& unit, const std::string& product_name,
                           const std::string& path);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_STEP_FILE_H_
