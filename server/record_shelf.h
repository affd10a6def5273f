// File: record_shelf.h
// -----------------------------------------------------------------------------
// The embedded store's job records, kept as long as their results (the result
// TTL, 24 h by default), each serialized in one block, in memory pages mapped
// for the shelf alone.
//
// Why apart from malloc: a job's transient buffers (meshes, graphs, result
// bytes) come from malloc's arenas, and malloc_trim can return a page only if
// nothing on it is in use. A record kept as a protobuf message is dozens of
// small blocks, allocated and grown by whichever thread changed the job (the
// upload's, then a worker's), so they land between the job buffers of those
// threads' arenas; after the buffers are freed each small block keeps its page
// resident. A server keeping thousands of finished jobs then grows by pages per
// job instead of by the record's few hundred bytes. Here the records share
// pages with nothing else, packed by a pool that reuses expired records' blocks.
//
// Not thread-safe: the owning store guards it with its lock.
#ifndef MESHSEG_SERVER_RECORD_SHELF_H_
#define MESHSEG_SERVER_RECORD_SHELF_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory_resource>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "absl/functional/function_ref.h"
#include "server/job_record.pb.h"

namespace meshseg::server {

// Memory mapped from the system (mmap) in whole pages, unmapped on
// deallocation: what the shelf's pool takes its chunks from.
class MappedPages final : public std::pmr::memory_resource {
 public:
  MappedPages() = default;
  MappedPages(const MappedPages&) = delete;
  MappedPages& operator=(const MappedPages&) = delete;

  int64_t mapped_bytes() const { return mapped_bytes_; }

 private:
  void* do_allocate(std::size_t bytes, std::size_t alignment) override;
  void do_deallocate(void* p, std::size_t bytes, std::size_t alignment) override;
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
    return this == &other;
  }

  int64_t mapped_bytes_ = 0;
};

class RecordShelf {
 public:
  RecordShelf();
  RecordShelf(const RecordShelf&) = delete;
  RecordShelf& operator=(const RecordShelf&) = delete;

  // Stores `record` under its job id, replacing the one stored before.
  void Put(const JobRecord& record);
  // The record of `id`, or nullopt.
  std::optional<JobRecord> Get(std::string_view id) const;
  // Forgets `id`; false if it was not there.
  bool Erase(std::string_view id);
  // Calls `visit` with every record, in job id order.
  void ForEach(absl::FunctionRef<void(const JobRecord&)> visit) const;
  // The id of the job `tenant` created with `request_id`; nullopt when there
  // is none or `request_id` is empty. Reads no record.
  std::optional<std::string> FindRequest(std::string_view tenant,
                                         std::string_view request_id) const;
  // Ids of the finished jobs (a terminal state) that ended before
  // `cutoff_unix_ms`, in id order. Reads no record.
  std::vector<std::string> FinishedBefore(int64_t cutoff_unix_ms) const;

  std::size_t size() const { return entries_.size(); }
  // Bytes mapped for the records (for tests and reports).
  int64_t mapped_bytes() const { return pages_.mapped_bytes(); }

 private:
  // What the store filters on, kept beside the serialized record.
  struct Entry {
    bool terminal = false;
    int64_t finished_unix_ms = 0;
    std::pmr::string request;  // tenant '\n' request_id, empty without a request id
    std::pmr::string bytes;    // the serialized JobRecord
  };

  MappedPages pages_;
  std::pmr::unsynchronized_pool_resource pool_;
  std::pmr::map<std::pmr::string, Entry, std::less<>> entries_;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_RECORD_SHELF_H_
