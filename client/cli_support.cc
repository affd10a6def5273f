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
  ConnectOptions options;
  options.tls_ca = args.Value("--tls-ca").value_or("");
  options.tls_cert = args.Value("--tls-cert").value_or("");
  options.tls_key = args.Value("--tls-key").value_or("");
  options.token = args.Value("--token").value_or("");
  if (const char* env = std::getenv("MESHSEG_TOKEN"); options.token.empty() && env != nullptr) {
    options.token = env;
  }
  return MeshsegClient::Connect(*address, options);
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
