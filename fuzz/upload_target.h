// The upload header target (fuzz_entry.cc).
#ifndef MESHSEG_FUZZ_UPLOAD_TARGET_H_
#define MESHSEG_FUZZ_UPLOAD_TARGET_H_

#include <string_view>

namespace meshseg::fuzz {

// Parses `bytes` as an UploadRequest; for a header, runs the checks the
// Upload handler runs before it receives the file (CheckUploadHeader,
// FromProto of the options, FormatFromHint) and aborts unless each either
// accepts a value within its stated range or refuses with a clean error.
void FuzzUploadHeader(std::string_view bytes);

}  // namespace meshseg::fuzz

#endif  // MESHSEG_FUZZ_UPLOAD_TARGET_H_
