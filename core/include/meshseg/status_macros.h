// File: status_macros.h
// -----------------------------------------------------------------------------
// MESHSEG_RETURN_IF_ERROR and MESHSEG_ASSIGN_OR_RETURN: early return on a
// non-OK absl::Status / absl::StatusOr. Debian 12's Abseil (20220623) ships no
// absl/status/status_macros.h; these match the newer ABSL_ macros so switching
// later is a rename.
#ifndef MESHSEG_STATUS_MACROS_H_
#define MESHSEG_STATUS_MACROS_H_

#include "absl/status/status.h"
#include "absl/status/statusor.h"

#define MESHSEG_STATUS_CONCAT_INNER_(a, b) a##b
#define MESHSEG_STATUS_CONCAT_(a, b) MESHSEG_STATUS_CONCAT_INNER_(a, b)

// Evaluates `expr` (an absl::Status); returns it from the caller if not OK.
#define MESHSEG_RETURN_IF_ERROR(expr)                 \
  do {                                                \
    const ::absl::Status meshseg_status_ = (expr);    \
    if (!meshseg_status_.ok()) return meshseg_status_; \
  } while (0)

// `lhs` = value of `rexpr` (an absl::StatusOr<T>), or returns its status.
// `lhs` may be a declaration: MESHSEG_ASSIGN_OR_RETURN(Mesh m, ReadMesh(p));
// A reference declaration, MESHSEG_ASSIGN_OR_RETURN(const Mesh& m, ...),
// leaves the value in the StatusOr (which lives to the end of the enclosing
// scope) instead of moving it out: use it for a Mesh, whose OpenMesh kernel
// has no move constructor, so that moving it out copies the whole mesh.
#define MESHSEG_ASSIGN_OR_RETURN(lhs, rexpr) \
  MESHSEG_ASSIGN_OR_RETURN_IMPL_(            \
      MESHSEG_STATUS_CONCAT_(meshseg_statusor_, __LINE__), lhs, rexpr)

#define MESHSEG_ASSIGN_OR_RETURN_IMPL_(statusor, lhs, rexpr) \
  auto statusor = (rexpr);                                   \
  if (!statusor.ok()) return std::move(statusor).status();   \
  lhs = std::move(statusor).value()

#endif  // MESHSEG_STATUS_MACROS_H_
