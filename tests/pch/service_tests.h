// Headers every server, client and proto test parses: the core tests' set plus
// gRPC, protobuf and the generated service messages (the heaviest part of a
// service test's compile). Third-party and generated headers only.
#pragma once

#include "core_tests.h"

#include <grpcpp/grpcpp.h>
#include <grpcpp/generic/generic_stub.h>

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>

#include "absl/synchronization/mutex.h"
#include "absl/synchronization/notification.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"
#include "meshseg/v1/service.grpc.pb.h"
#include "meshseg/v1/service.pb.h"
