// File: volume_args.h
// -----------------------------------------------------------------------------
// The volume flags `segment` and `info` share: --iso, --volume-mode and the
// layout of a headerless .raw file (--dims X,Y,Z --spacing SX,SY,SZ
// --type T [--origin X,Y,Z] [--big-endian]).
#ifndef MESHSEG_CLIENT_VOLUME_ARGS_H_
#define MESHSEG_CLIENT_VOLUME_ARGS_H_

#include <string_view>

#include "absl/status/status.h"
#include "client/args.h"
#include "client/meshseg_client.h"

namespace meshseg::cli {

// The switch of the volume options; their value flags are --iso,
// --volume-mode, --dims, --spacing, --origin and --type.
inline constexpr std::string_view kBigEndianSwitch = "--big-endian";

// Sets options->segment's iso_value / volume_mode and options->raw's raw_*
// fields from `args`. Errors (INVALID_ARGUMENT): malformed numbers, a raw
// layout that RawLayout refuses.
absl::Status VolumeOptionsFromArgs(const Args& args, UploadOptions* options);

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_VOLUME_ARGS_H_
