// fuzz_replay TARGET PATH...: runs every file under the PATHs (corpus and
// regression folders) through the fuzz target TARGET once, without
// libFuzzer, so the default test command (gcc, no sanitizers) replays the
// corpus through the same entry function the fuzzers run. A failed check
// aborts; a clean run prints how many inputs it replayed.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/fuzz_entry.h"

namespace {

std::vector<std::filesystem::path> FilesUnder(const std::filesystem::path& path) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_regular_file(path)) return {path};
  for (const auto& entry : std::filesystem::recursive_directory_iterator(path)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: fuzz_replay TARGET PATH...\n");
    return 2;
  }
  const meshseg::fuzz::FuzzTarget* target = meshseg::fuzz::FindFuzzTarget(argv[1]);
  if (target == nullptr) {
    std::fprintf(stderr, "fuzz_replay: no target \"%s\"\n", argv[1]);
    return 2;
  }
  size_t count = 0;
  for (int i = 2; i < argc; ++i) {
    if (!std::filesystem::exists(argv[i])) {
      std::fprintf(stderr, "fuzz_replay: \"%s\" does not exist\n", argv[i]);
      return 2;
    }
    for (const std::filesystem::path& file : FilesUnder(argv[i])) {
      std::ifstream in(file, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::fprintf(stderr, "%s\n", file.c_str());
      target->run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
      ++count;
    }
  }
  if (count == 0) {
    std::fprintf(stderr, "fuzz_replay: no inputs for \"%s\"\n", argv[1]);
    return 1;
  }
  std::printf("fuzz_replay %s: %zu inputs, every check held\n", argv[1], count);
  return 0;
}
