// Writing the B-rep as a STEP AP214 file (the declared length unit, the
// product name and a name per face) and reading it back as a reader sees it.
#ifndef MESHSEG_SRC_BREP_STEP_FILE_H_
#define MESHSEG_SRC_BREP_STEP_FILE_H_

#include <functional>
#include <mutex>
#include <string>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

namespace meshseg::brep_internal {

// OpenCASCADE 7.6 keeps the STEP writer's and reader's settings (schema,
// units, product name) in process-wide Interface_Static values: one write or
// read at a time, under this mutex.
std::mutex& StepSessionMutex();

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

struct ReadBackFacts {
  bool valid = false;  // BRepCheck_Analyzer on the shape read back
  int solids = 0;
  int faces = 0;
  // Edges of one face only that are neither seams nor degenerate.
  int free_edges = 0;
  double volume = 0.0;  // of the solids (BRepGProp), model units³
};

// Reads the STEP file at `path` back (coordinates in `unit`, as written) and
// returns what it holds: the file as a reader sees it, which rebuilds what
// the file does not hold (the edges' curves in each face's parameter plane).
// Errors: INTERNAL when the file cannot be read or holds no shape (naming
// the path).
absl::StatusOr<ReadBackFacts> ReadBack(const std::string& path, const std::string& unit);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_STEP_FILE_H_
