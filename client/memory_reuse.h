// Memory a one-shot command frees stays in the process for its next
// allocations, instead of going back to the kernel.
#ifndef MESHSEG_CLIENT_MEMORY_REUSE_H_
#define MESHSEG_CLIENT_MEMORY_REUSE_H_

namespace meshseg::cli {

// The pipeline allocates arrays of the mesh's size stage after stage and
// frees them between stages (a 1M-face mesh: ~100K page faults). By default
// glibc maps each block over its mmap threshold (128 KiB, raised as such
// blocks are freed) on its own and unmaps it when freed, and gives the top
// of its heap back beyond the trim threshold; every 4 KiB page of the next
// array then faults in again, zeroed by the kernel. Here blocks up to 32 MiB
// (glibc's largest threshold) come from the heap, and the heap is never
// trimmed, so a freed block is reused without a fault. Peak memory is what
// the run reaches anyway; the process ends with the command. Not for the
// server, which must give memory back between jobs. Returns false if glibc
// refused a setting (then nothing is lost but the saving).
bool KeepFreedMemoryForReuse();

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_MEMORY_REUSE_H_
