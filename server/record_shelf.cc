#include "server/record_shelf.h"

#include <sys/mman.h>
#include <unistd.h>

#include <new>

#include "server/job_store.h"

namespace meshseg::server {
namespace {

std::size_t PageSize() {
  static const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  return page;
}

std::size_t RoundToPages(std::size_t bytes) {
  const std::size_t page = PageSize();
  return (bytes + page - 1) / page * page;
}

// The pool serves every record from blocks of its own chunks; only a record
// over this size gets a mapping of its own (a job's record is well under a
// page: ids, names, options and at most one error message).
constexpr std::size_t kLargestPooledBlock = 64 << 10;

std::string RequestKey(std::string_view tenant, std::string_view request_id) {
  if (request_id.empty()) return "";
  std::string key(tenant);
  key += '\n';
  key += request_id;
  return key;
}

}  // namespace

void* MappedPages::do_allocate(std::size_t bytes, std::size_t alignment) {
  if (alignment > PageSize()) throw std::bad_alloc();
  const std::size_t size = RoundToPages(bytes);
  void* p = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  mapped_bytes_ += static_cast<int64_t>(size);
  return p;
}

void MappedPages::do_deallocate(void* p, std::size_t bytes, std::size_t /*alignment*/) {
  const std::size_t size = RoundToPages(bytes);
  munmap(p, size);
  mapped_bytes_ -= static_cast<int64_t>(size);
}

RecordShelf::RecordShelf()
    : pool_(std::pmr::pool_options{.max_blocks_per_chunk = 0,
                                   .largest_required_pool_block = kLargestPooledBlock},
            &pages_),
      entries_(&pool_) {}

void RecordShelf::Put(const JobRecord& record) {
  const v1::Job& job = record.job();
  Entry entry{.terminal = IsTerminal(job.state()),
              .finished_unix_ms = job.finished_unix_ms(),
              .request = std::pmr::string(RequestKey(job.tenant(), job.request_id()), &pool_),
              .bytes = std::pmr::string(&pool_)};
  entry.bytes.resize(record.ByteSizeLong());
  record.SerializeWithCachedSizesToArray(reinterpret_cast<uint8_t*>(entry.bytes.data()));
  const auto it = entries_.find(std::string_view(job.job_id()));
  if (it != entries_.end()) {
    it->second = std::move(entry);  // same resource on both sides: moves the blocks
  } else {
    entries_.emplace(job.job_id(), std::move(entry));
  }
}

std::optional<JobRecord> RecordShelf::Get(std::string_view id) const {
  const auto it = entries_.find(id);
  if (it == entries_.end()) return std::nullopt;
  JobRecord record;
  // Written by Put from a valid message: parsing cannot fail short of memory
  // corruption, which the next state change would overwrite anyway.
  (void)record.ParseFromArray(it->second.bytes.data(), static_cast<int>(it->second.bytes.size()));
  return record;
}

bool RecordShelf::Erase(std::string_view id) {
  const auto it = entries_.find(id);
  if (it == entries_.end()) return false;
  entries_.erase(it);
  return true;
}

void RecordShelf::ForEach(absl::FunctionRef<void(const JobRecord&)> visit) const {
  JobRecord record;
  for (const auto& [id, entry] : entries_) {
    record.Clear();
    (void)record.ParseFromArray(entry.bytes.data(), static_cast<int>(entry.bytes.size()));
    visit(record);
  }
}

std::optional<std::string> RecordShelf::FindRequest(std::string_view tenant,
                                                    std::string_view request_id) const {
  const std::string key = RequestKey(tenant, request_id);
  if (key.empty()) return std::nullopt;
  for (const auto& [id, entry] : entries_) {
    if (std::string_view(entry.request) == key) return std::string(id);
  }
  return std::nullopt;
}

std::vector<std::string> RecordShelf::FinishedBefore(int64_t cutoff_unix_ms) const {
  std::vector<std::string> out;
  for (const auto& [id, entry] : entries_) {
    if (entry.terminal && entry.finished_unix_ms < cutoff_unix_ms) out.emplace_back(id);
  }
  return out;
}

}  // namespace meshseg::server
