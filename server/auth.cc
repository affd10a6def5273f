#include "server/auth.h"

#include <utility>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "meshseg/proto/credential_files.h"
#include "meshseg/proto/sha256.h"
#include "meshseg/status_macros.h"

namespace meshseg::server {
namespace {

constexpr std::size_t kMinTokenLength = 16;
constexpr std::size_t kMaxTenantLength = 64;

std::string Digest(std::string_view token) {
  Sha256 sha;
  sha.Update(token);
  return sha.HexDigest();
}

bool IsTokenChar(char c) { return c > 0x20 && c < 0x7F; }

bool IsTenantName(std::string_view name) {
  if (name.empty() || name.size() > kMaxTenantLength) return false;
  for (const char c : name) {
    if (!absl::ascii_isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') {
      return false;
    }
  }
  return true;
}

// Refuses calls without a known bearer token, except to open methods.
class TokenProcessor : public grpc::AuthMetadataProcessor {
 public:
  explicit TokenProcessor(std::shared_ptr<const TokenAuth> auth) : auth_(std::move(auth)) {}

  // The lookup is a map search under a mutex: run it on the call's thread.
  bool IsBlocking() const override { return false; }

  grpc::Status Process(const InputMetadata& metadata, grpc::AuthContext* /*context*/,
                       OutputMetadata* /*consumed*/, OutputMetadata* /*response*/) override {
    const auto path = metadata.find(":path");
    if (path != metadata.end() &&
        std::string_view(path->second.data(), path->second.size()).starts_with(kOpenMethodPrefix)) {
      return grpc::Status::OK;
    }
    const auto header = metadata.find("authorization");
    if (header == metadata.end()) {
      return grpc::Status(grpc::StatusCode::UNAUTHENTICATED,
                          "auth: no bearer token (send metadata \"authorization: Bearer TOKEN\")");
    }
    const std::optional<std::string_view> token =
        BearerToken(std::string_view(header->second.data(), header->second.size()));
    if (!token || !auth_->TenantOfToken(*token)) {
      return grpc::Status(grpc::StatusCode::UNAUTHENTICATED, "auth: unknown bearer token");
    }
    return grpc::Status::OK;
  }

 private:
  std::shared_ptr<const TokenAuth> auth_;
};

}  // namespace

absl::StatusOr<std::map<std::string, std::string>> ParseTokenFile(std::string_view text,
                                                                  std::string_view file) {
  std::map<std::string, std::string> by_digest;
  int line_number = 0;
  for (absl::string_view line : absl::StrSplit(absl::string_view(text.data(), text.size()), '\n')) {
    ++line_number;
    line = line.substr(0, line.find('#'));
    const std::vector<absl::string_view> words =
        absl::StrSplit(line, absl::ByAnyChar(" \t\r"), absl::SkipEmpty());
    if (words.empty()) continue;
    const auto bad = [&](const std::string& what) {
      return absl::InvalidArgumentError(absl::StrCat("auth: token file \"", std::string(file),
                                                     "\" line ", line_number, ": ", what));
    };
    if (words.size() != 2) {
      return bad(absl::StrCat("expected \"TOKEN TENANT\", got ", words.size(), " words"));
    }
    const std::string_view token(words[0].data(), words[0].size());
    const std::string_view tenant(words[1].data(), words[1].size());
    if (token.size() < kMinTokenLength) {
      return bad(absl::StrCat("token of ", token.size(), " characters, at least ", kMinTokenLength,
                              " needed"));
    }
    for (const char c : token) {
      if (!IsTokenChar(c)) return bad("token holds a character outside printable ASCII");
    }
    if (!IsTenantName(tenant)) {
      return bad(
          absl::StrCat("tenant must be 1-", kMaxTenantLength, " characters of [A-Za-z0-9._-]"));
    }
    if (!by_digest.emplace(Digest(token), std::string(tenant)).second) {
      return bad("token listed twice");
    }
  }
  if (by_digest.empty()) {
    return absl::InvalidArgumentError(absl::StrCat("auth: token file \"", std::string(file),
                                                   "\" holds no \"TOKEN TENANT\" line"));
  }
  return by_digest;
}

absl::StatusOr<std::shared_ptr<TokenAuth>> TokenAuth::Load(const std::string& path) {
  MESHSEG_ASSIGN_OR_RETURN(const std::string text, ReadCredentialFile(path, "--auth-tokens"));
  MESHSEG_ASSIGN_OR_RETURN(auto by_digest, ParseTokenFile(text, path));
  return std::shared_ptr<TokenAuth>(new TokenAuth(path, std::move(by_digest)));
}

absl::StatusOr<int> TokenAuth::Reload() {
  MESHSEG_ASSIGN_OR_RETURN(const std::string text, ReadCredentialFile(path_, "--auth-tokens"));
  MESHSEG_ASSIGN_OR_RETURN(auto by_digest, ParseTokenFile(text, path_));
  absl::MutexLock lock(&mu_);
  by_digest_ = std::move(by_digest);
  return static_cast<int>(by_digest_.size());
}

std::optional<std::string> TokenAuth::TenantOfToken(std::string_view token) const {
  const std::string digest = Digest(token);
  absl::ReaderMutexLock lock(&mu_);
  const auto it = by_digest_.find(digest);
  if (it == by_digest_.end()) return std::nullopt;
  return it->second;
}

absl::StatusOr<std::string> TokenAuth::TenantOf(const grpc::ServerContextBase& context) const {
  const auto& metadata = context.client_metadata();
  const auto header = metadata.find("authorization");
  if (header != metadata.end()) {
    if (const std::optional<std::string_view> token =
            BearerToken(std::string_view(header->second.data(), header->second.size()))) {
      if (std::optional<std::string> tenant = TenantOfToken(*token)) return *std::move(tenant);
    }
  }
  return absl::UnauthenticatedError("auth: no known bearer token on the call");
}

std::shared_ptr<grpc::AuthMetadataProcessor> TokenAuth::Processor() {
  // The processor shares ownership: it may outlive the server's own handle.
  return std::make_shared<TokenProcessor>(shared_from_this());
}

std::optional<std::string_view> BearerToken(std::string_view authorization) {
  constexpr std::string_view kScheme = "bearer ";
  if (authorization.size() <= kScheme.size()) return std::nullopt;
  for (std::size_t i = 0; i < kScheme.size(); ++i) {
    if (absl::ascii_tolower(static_cast<unsigned char>(authorization[i])) != kScheme[i]) {
      return std::nullopt;
    }
  }
  std::string_view token = authorization.substr(kScheme.size());
  const std::size_t first = token.find_first_not_of(" \t");
  if (first == std::string_view::npos) return std::nullopt;
  token.remove_prefix(first);
  return token.substr(0, token.find_last_not_of(" \t") + 1);
}

}  // namespace meshseg::server
