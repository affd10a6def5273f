// libFuzzer's entry for one target, named at compile time by
// MESHSEG_FUZZ_TARGET (fuzz/CMakeLists.txt builds one binary per target).
#include <cstdio>
#include <cstdlib>

#include "fuzz/fuzz_entry.h"

namespace {

const meshseg::fuzz::FuzzTarget& Target() {
  static const meshseg::fuzz::FuzzTarget* target =
      meshseg::fuzz::FindFuzzTarget(MESHSEG_FUZZ_TARGET);
  if (target == nullptr) {
    std::fprintf(stderr, "no fuzz target \"%s\"\n", MESHSEG_FUZZ_TARGET);
    std::abort();
  }
  return *target;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return Target().run(data, size);
}
