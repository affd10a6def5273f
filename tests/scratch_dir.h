// Where tests write their files: a folder of the test process's own under
// gtest's TempDir(), made on first use and removed when the process exits.
// ctest runs every test in a process of its own, two at a time on CI, so no
// two tests share a file (shared names let one test truncate another's
// stderr capture, stop 25), and a run leaves nothing behind in /tmp.
#ifndef MESHSEG_TESTS_SCRATCH_DIR_H_
#define MESHSEG_TESTS_SCRATCH_DIR_H_

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include <gtest/gtest.h>

namespace meshseg::testing_files {

namespace internal {

class ScratchFolder {
 public:
  ScratchFolder() : owner_(getpid()) {
    std::string pattern = ::testing::TempDir() + "meshseg_test_XXXXXX";
    if (mkdtemp(pattern.data()) == nullptr) {
      ADD_FAILURE() << "cannot make a scratch folder like " << pattern;
      return;
    }
    path_ = pattern;
  }
  // Only the process that made it removes it: a forked child (RunCli, a
  // server under test) that exits normally must not take it away.
  ~ScratchFolder() {
    if (path_.empty() || getpid() != owner_) return;
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::string& path() const { return path_; }

 private:
  pid_t owner_;
  std::string path_;
};

}  // namespace internal

// This process's scratch folder (no trailing '/').
inline const std::string& ScratchDir() {
  static const internal::ScratchFolder folder;
  return folder.path();
}

// `name` in this process's scratch folder.
inline std::string ScratchPath(std::string_view name) {
  return (std::filesystem::path(ScratchDir()) / name).string();
}

}  // namespace meshseg::testing_files

#endif  // MESHSEG_TESTS_SCRATCH_DIR_H_
