// The check the fuzz targets use: unlike assert() it stays on in release
// builds (the corpus replay test runs a release build), and names what failed.
#ifndef MESHSEG_FUZZ_CHECK_H_
#define MESHSEG_FUZZ_CHECK_H_

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace meshseg::fuzz {

// Prints `what` and `detail` and aborts if `ok` is false.
inline void Check(bool ok, const char* what, std::string_view detail = {}) {
  if (ok) return;
  std::fprintf(stderr, "fuzz check failed: %s: ", what);
  std::fwrite(detail.data(), 1, detail.size(), stderr);  // not NUL-terminated
  std::fputc('\n', stderr);
  std::abort();
}

}  // namespace meshseg::fuzz

#endif  // MESHSEG_FUZZ_CHECK_H_
