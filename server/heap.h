// File: heap.h
// -----------------------------------------------------------------------------
// The process heap as the operating system sees it. glibc's malloc keeps
// memory a job freed: threads allocate from up to 8 arenas per core, and an
// arena gives pages back to the system only from its top, only once more
// than a threshold is free there. glibc raises that threshold, and the size
// from which a block gets its own mapping (returned on free), to the largest
// block freed so far (up to 32 MiB on 64-bit), so after a few jobs nearly
// every buffer of a job comes from the arenas. A long-running server whose
// jobs allocate and free tens of MiB from several threads therefore holds
// freed pages in every arena a job touched: resident memory climbs as more
// arenas have run a large job, not with what the server keeps.
// ReturnFreeHeap hands those pages back (glibc malloc_trim(0) releases every
// whole free page of every arena); ReadHeapUsage tells memory in use from
// memory held free, so an operator can tell a leak (in use grows) from
// retention (free grows).
#ifndef MESHSEG_SERVER_HEAP_H_
#define MESHSEG_SERVER_HEAP_H_

#include <cstdint>
#include <optional>

namespace meshseg::server {

// Gives every block of at least `threshold_bytes` a mapping of its own, unmapped
// when the block is freed, for the rest of the process. glibc does that from
// 128 KiB by default, but raises the threshold to the largest such block freed
// so far, so after a few jobs a job's large buffers (meshes, graphs, uploads,
// results) come from the arenas, where small blocks allocated between them
// keep their pages resident and only ReturnFreeHeap, run by a worker after a
// job, gives the rest back (buffers a gRPC thread frees after it, e.g. a
// result just sent, wait for the next job's). With a fixed threshold the
// arenas hold only small blocks, and freeing a large buffer returns it at
// once, from any thread. Cost: a system call and fresh zeroed pages per large
// block. Call once, at startup; returns false where the C library cannot.
bool MapLargeBlocks(int64_t threshold_bytes = int64_t{1} << 20);

// Returns the heap's whole free pages to the system. Takes each arena's lock
// in turn (milliseconds for a few hundred MiB of heap); call it between jobs,
// not per allocation. A no-op on C libraries without malloc_trim.
void ReturnFreeHeap();

struct HeapUsage {
  int64_t in_use_bytes = 0;  // allocated and not yet freed (arenas + mmapped blocks)
  int64_t free_bytes = 0;    // freed and kept by malloc (resident unless returned)
};

// The heap's usage (glibc mallinfo2; walks every arena under its lock);
// nullopt on C libraries without it.
std::optional<HeapUsage> ReadHeapUsage();

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_HEAP_H_
