#include "server/spool.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"

namespace meshseg::server {
namespace fs = std::filesystem;
namespace {

constexpr char kRecordName[] = "#record.pb";
constexpr char kScratchDir[] = ".scratch";
constexpr char kLockName[] = ".lock";

// Reads one job folder's record; an error says why it cannot be used.
absl::StatusOr<JobRecord> ReadRecord(const fs::path& folder) {
  const fs::path path = folder / kRecordName;
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::NotFoundError("no job record (left by an older meshseg-server?)");
  std::stringstream bytes;
  bytes << in.rdbuf();
  JobRecord record;
  if (!record.ParseFromString(bytes.str()) || record.format_version() == 0) {
    return absl::DataLossError("corrupt job record");
  }
  if (record.format_version() > kRecordFormat) {
    return absl::FailedPreconditionError(absl::StrCat("job record format ", record.format_version(),
                                                      " is newer than this server's (",
                                                      kRecordFormat, ")"));
  }
  if (record.job().job_id() != folder.filename().string()) {
    return absl::DataLossError(absl::StrCat("job record names another job (\"",
                                            record.job().job_id().substr(0, 64), "\")"));
  }
  return record;
}

}  // namespace

Spool::Spool(std::string dir, int lock_fd)
    : dir_(std::move(dir)), lock_fd_(lock_fd), blobs_(dir_) {}

Spool::~Spool() {
  if (lock_fd_ >= 0) close(lock_fd_);  // releases the flock
}

absl::StatusOr<std::unique_ptr<Spool>> Spool::Open(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(fs::path(dir) / kScratchDir, ec);
  if (ec) {
    return absl::InternalError(
        absl::StrCat("spool: cannot create \"", dir, "\": ", ec.message()));
  }
  const std::string lock_path = (fs::path(dir) / kLockName).string();
  const int fd = open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    return absl::InternalError(
        absl::StrCat("spool: cannot open \"", lock_path, "\": ", std::strerror(errno)));
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    close(fd);
    if (err == EWOULDBLOCK) {
      return absl::FailedPreconditionError(
          absl::StrCat("spool: \"", dir, "\" is in use by another meshseg-server (", lock_path,
                       " is locked); give each server its own --spool-dir"));
    }
    return absl::InternalError(
        absl::StrCat("spool: cannot lock \"", lock_path, "\": ", std::strerror(err)));
  }
  // Files in transit when the previous run stopped were never accepted.
  for (const auto& entry : fs::directory_iterator(fs::path(dir) / kScratchDir, ec)) {
    fs::remove_all(entry.path(), ec);
  }
  return std::unique_ptr<Spool>(new Spool(dir, fd));
}

std::string Spool::ScratchPath(const std::string& job_id, absl::string_view name) const {
  return (fs::path(dir_) / kScratchDir / absl::StrCat(job_id, "-", name)).string();
}

absl::Status Spool::WriteRecord(const JobRecord& record) const {
  const fs::path folder = fs::path(dir_) / record.job().job_id();
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) {
    return absl::InternalError(
        absl::StrCat("spool: cannot create \"", folder.string(), "\": ", ec.message()));
  }
  return WriteFileAtomically((folder / kRecordName).string(), record.SerializeAsString());
}

Spool::Recovered Spool::Recover() const {
  Recovered out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir_, ec)) {
    const std::string name = entry.path().filename().string();
    if (!absl::StartsWith(name, "job-")) continue;
    if (entry.is_symlink(ec) || !entry.is_directory(ec)) {
      out.skipped.push_back({name, "not a job folder"});
      continue;
    }
    absl::StatusOr<JobRecord> record = ReadRecord(entry.path());
    if (record.ok()) {
      out.records.push_back(*std::move(record));
    } else {
      out.skipped.push_back({name, std::string(record.status().message())});
    }
  }
  std::sort(out.records.begin(), out.records.end(),
            [](const JobRecord& a, const JobRecord& b) { return a.sequence() < b.sequence(); });
  return out;
}

void Spool::RemoveJob(const std::string& job_id) const {
  if (job_id.empty() || job_id.find('/') != std::string::npos) return;
  std::error_code ec;
  fs::remove_all(fs::path(dir_) / job_id, ec);  // removes symlinks, never follows them
}

int64_t Spool::FileCount() const {
  std::error_code ec;
  int64_t count = 0;
  for (const auto& entry : fs::directory_iterator(dir_, ec)) {
    const std::string name = entry.path().filename().string();
    if (!absl::StartsWith(name, "job-") && name != kScratchDir) continue;
    for (const auto& file : fs::recursive_directory_iterator(entry.path(), ec)) {
      if (file.is_regular_file(ec) && file.path().filename() != kRecordName) ++count;
    }
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
