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
