#include "server/dir_blob_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <random>
#include <system_error>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace meshseg::server {
namespace fs = std::filesystem;
namespace {

absl::Status SysError(absl::string_view what, const std::string& path) {
  return absl::InternalError(
      absl::StrCat("blob store: cannot ", what, " \"", path, "\": ", std::strerror(errno)));
}

// Returns a name no other writer picks: pid and 64 random bits.
std::string TempName(const std::string& path) {
  thread_local std::mt19937_64 rng(std::random_device{}());
  return absl::StrFormat("%s.tmp-%d-%016x", path, getpid(), rng());
}

absl::Status SyncFile(int fd, const std::string& path) {
  if (fsync(fd) != 0) return SysError("fsync", path);
  return absl::OkStatus();
}

// Copies `from` into the new file `to` and fsyncs it.
absl::Status CopyFile(const std::string& from, const std::string& to) {
  const int in = open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) return SysError("read", from);
  const int out = open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (out < 0) {
    close(in);
    return SysError("create", to);
  }
  absl::Status status;
  char buf[1 << 16];
  while (status.ok()) {
    const ssize_t n = read(in, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) status = SysError("read", from);
    if (n <= 0) break;
    for (ssize_t done = 0; done < n && status.ok();) {
      const ssize_t w = write(out, buf + done, static_cast<std::size_t>(n - done));
      if (w < 0 && errno != EINTR) status = SysError("write", to);
      if (w > 0) done += w;
    }
  }
  if (status.ok()) status = SyncFile(out, to);
  close(in);
  close(out);
  return status;
}

class FileBlob final : public LocalBlob {
 public:
  FileBlob(std::string path, int64_t size) : path_(std::move(path)), size_(size) {}
  const std::string& path() const override { return path_; }
  int64_t size() const override { return size_; }

 private:
  std::string path_;
  int64_t size_;
};

}  // namespace

std::string UploadKey(const std::string& job_id, const std::string& safe_file_name) {
  return absl::StrCat(job_id, "/", safe_file_name);
}

std::string ResultKey(const std::string& job_id) { return absl::StrCat(job_id, "/#result.pb"); }

std::string StepKey(const std::string& job_id) { return absl::StrCat(job_id, "/#result.step"); }

absl::Status SyncDir(const std::string& dir) {
  const int fd = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return SysError("open folder", dir);
  const absl::Status status = SyncFile(fd, dir);
  close(fd);
  return status;
}

absl::Status WriteFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string temp = TempName(path);
  const int fd = open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return SysError("create", temp);
  absl::Status status;
  for (std::size_t done = 0; done < bytes.size() && status.ok();) {
    const ssize_t w = write(fd, bytes.data() + done, bytes.size() - done);
    if (w < 0 && errno != EINTR) status = SysError("write", temp);
    if (w > 0) done += static_cast<std::size_t>(w);
  }
  if (status.ok()) status = SyncFile(fd, temp);
  close(fd);
  if (status.ok() && rename(temp.c_str(), path.c_str()) != 0) status = SysError("rename", temp);
  if (!status.ok()) {
    unlink(temp.c_str());
    return status;
  }
  return SyncDir(fs::path(path).parent_path().string());
}

absl::StatusOr<std::unique_ptr<DirBlobStore>> DirBlobStore::Create(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    return absl::InternalError(
        absl::StrCat("blob store: cannot create \"", dir, "\": ", ec.message()));
  }
  return std::make_unique<DirBlobStore>(dir);
}

std::string DirBlobStore::Path(const std::string& key) const {
  return (fs::path(dir_) / key).string();
}

absl::Status DirBlobStore::Put(const std::string& key, const std::string& local_path) {
  const std::string path = Path(key);
  const std::string folder = fs::path(path).parent_path().string();
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) {
    return absl::InternalError(
        absl::StrCat("blob store: cannot create \"", folder, "\": ", ec.message()));
  }
  // Same file system: fsync the file, rename it in. Else copy to a temp
  // file beside the blob first, so the rename stays atomic.
  std::string source = local_path;
  if (rename(local_path.c_str(), path.c_str()) != 0) {
    if (errno != EXDEV) return SysError("move into the store", local_path);
    source = TempName(path);
    if (absl::Status s = CopyFile(local_path, source); !s.ok()) {
      unlink(source.c_str());
      return s;
    }
    if (rename(source.c_str(), path.c_str()) != 0) {
      unlink(source.c_str());
      return SysError("rename", source);
    }
    unlink(local_path.c_str());
  } else {
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return SysError("open", path);
    const absl::Status synced = SyncFile(fd, path);
    close(fd);
    if (!synced.ok()) return synced;
  }
  return SyncDir(folder);
}

absl::StatusOr<std::unique_ptr<LocalBlob>> DirBlobStore::Open(const std::string& key) const {
  const std::string path = Path(key);
  struct stat st {};
  if (lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
    return absl::NotFoundError(absl::StrCat("blob store: no blob \"", key, "\" in \"", dir_, "\""));
  }
  return std::make_unique<FileBlob>(path, static_cast<int64_t>(st.st_size));
}

absl::Status DirBlobStore::Remove(const std::string& key) {
  const std::string path = Path(key);
  if (unlink(path.c_str()) != 0 && errno != ENOENT) return SysError("remove", path);
  rmdir(fs::path(path).parent_path().c_str());  // fails while not empty: fine
  return absl::OkStatus();
}

}  // namespace meshseg::server
