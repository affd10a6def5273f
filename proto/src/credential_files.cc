#include "meshseg/proto/credential_files.h"

#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"

namespace meshseg {

absl::StatusOr<std::string> ReadCredentialFile(const std::string& path, const char* flag) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || text.str().empty()) {
    return absl::NotFoundError(absl::StrCat(flag, ": cannot read \"", path, "\""));
  }
  return text.str();
}

}  // namespace meshseg
