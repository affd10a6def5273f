// Headers nearly every core stage's source parses: Eigen, OpenMesh, Abseil and
// the standard library. Precompiled once (core/CMakeLists.txt) and reused by
// every stage library, so a clean build does not parse them ~150 times (about
// 4 s of CPU per file on this project's 2-core CI machine). Third-party headers
// only: a project header here would rebuild every stage whenever it changes.
// oneTBB stays out: its debug-build macro is set only on the stages that link
// it, and GCC reuses a header only under the same macros.
#pragma once

#include <Eigen/Core>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
