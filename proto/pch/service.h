// Headers every server, client and proto-conversion source parses: the core
// stages' set plus gRPC, protobuf and the generated API messages (the heaviest
// part of a service source's compile). Precompiled once (proto/CMakeLists.txt)
// and reused by meshseg_proto_convert, meshseg_server, meshseg_client,
// meshseg_cli_output and the two executables, which all compile with gRPC's
// flags. Third-party and generated headers only.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <grpcpp/grpcpp.h>

#include <google/protobuf/util/json_util.h>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"
#include "meshseg/v1/segmentation.pb.h"
#include "meshseg/v1/service.grpc.pb.h"
#include "meshseg/v1/service.pb.h"
