#include "server/spool.h"

#include <filesystem>
#include <system_error>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"

namespace meshseg::server {
namespace fs = std::filesystem;

absl::StatusOr<Spool> Spool::Open(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    return absl::InternalError(
        absl::StrCat("spool: cannot create \"", dir, "\": ", ec.message()));
  }
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (absl::StartsWith(entry.path().filename().string(), "job-")) {
      fs::remove_all(entry.path(), ec);
    }
  }
  if (ec) {
    return absl::InternalError(absl::StrCat("spool: cannot clear \"", dir, "\": ", ec.message()));
  }
  return Spool(dir);
}

std::string Spool::JobDir(const std::string& job_id) const {
  return (fs::path(dir_) / job_id).string();
}

absl::StatusOr<std::string> Spool::CreateJob(const std::string& job_id,
                                             std::string_view file_name) const {
  std::error_code ec;
  const fs::path job_dir = JobDir(job_id);
  fs::create_directories(job_dir, ec);
  if (ec) {
    return absl::InternalError(
        absl::StrCat("spool: cannot create \"", job_dir.string(), "\": ", ec.message()));
  }
  return (job_dir / SafeFileName(file_name)).string();
}

std::string Spool::ResultPath(const std::string& job_id) const {
  // A name no upload can take: SafeFileName never starts with '#'.
  return (fs::path(JobDir(job_id)) / "#result.pb").string();
}

void Spool::RemoveJob(const std::string& job_id) const {
  std::error_code ec;
  fs::remove_all(JobDir(job_id), ec);
}

int64_t Spool::FileCount() const {
  std::error_code ec;
  int64_t count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir_, ec)) {
    if (entry.is_regular_file(ec)) ++count;
  }
  return count;
}

std::string SafeFileName(std::string_view file_name) {
  const std::size_t slash = file_name.find_last_of("/\\");
  if (slash != std::string_view::npos) file_name.remove_prefix(slash + 1);
  std::string safe;
  for (char c : file_name.substr(0, 100)) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    safe.push_back(ok ? c : '_');
  }
  if (safe.empty() || safe.front() == '.') safe.insert(0, "upload");
  return safe;
}

}  // namespace meshseg::server
