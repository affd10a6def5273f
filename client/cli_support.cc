// Helpers the subcommands share: the server to talk to, writing a file.
#include <cstdlib>
#include <fstream>

#include "absl/strings/str_cat.h"
#include "client/commands.h"

namespace meshseg::cli {

absl::StatusOr<MeshsegClient> ConnectFromArgs(const Args& args) {
  std::optional<std::string> address = args.Value("--server");
  if (!address) {
    if (const char* env = std::getenv("MESHSEG_SERVER"); env != nullptr && *env != '\0') {
      address = env;
    }
  }
  if (!address) {
    return absl::InvalidArgumentError("no server: pass --server HOST:PORT or set MESHSEG_SERVER");
  }
  return MeshsegClient::Connect(*address);
}

absl::Status WriteTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out || !out.write(text.data(), static_cast<std::streamsize>(text.size())) ||
      !out.flush()) {
    return absl::InternalError(absl::StrCat("cannot write \"", path, "\""));
  }
  return absl::OkStatus();
}

}  // namespace meshseg::cli
