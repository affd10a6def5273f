// File: fuzz_entry.h
// -----------------------------------------------------------------------------
// The fuzz targets: each takes untrusted bytes the way the service does (a
// file a client uploaded, an upload header) and checks that the outcome is
// either a well-formed result or a clean error. A violated check aborts, so
// libFuzzer (and the corpus replay test) report it as a finding.
//
// Readers are driven through the same functions ReadMesh / ReadPointCloud
// call after mapping the file (mesh_internal::Read*, BuildFromRaw), so no
// file is written per input. The volume readers take a path (they stream
// samples from the file), so their targets write each input to a scratch
// file (volume_targets.h). Targets of one reader differ only in their seed
// corpus (fuzz/corpus/<name>/).
#ifndef MESHSEG_FUZZ_FUZZ_ENTRY_H_
#define MESHSEG_FUZZ_FUZZ_ENTRY_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace meshseg::fuzz {

struct FuzzTarget {
  std::string_view name;  // also the corpus folder's name
  int (*run)(const uint8_t* data, size_t size);
};

// Every target, in a stable order.
std::span<const FuzzTarget> FuzzTargets();

// Returns the target called `name`, or nullptr.
const FuzzTarget* FindFuzzTarget(std::string_view name);

}  // namespace meshseg::fuzz

#endif  // MESHSEG_FUZZ_FUZZ_ENTRY_H_
