// Headers nearly every core-stage test parses: GoogleTest, Eigen, Abseil.
// Precompiled once (tests/CMakeLists.txt) and reused by every core test, so a
// clean build does not parse them ~110 times. Third-party headers only: a
// project header here would rebuild every test whenever it changes.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
