// LargeVector: a std::vector whose big buffers live in transparent huge pages.
// On the reference VM a 4 KiB page fault costs several microseconds, and
// reading a 2M-triangle STL touches a few hundred MB of scratch arrays; with
// 2 MiB pages the faults all but vanish (measured by bench/mesh).
#ifndef MESHSEG_MESH_LARGE_VECTOR_H_
#define MESHSEG_MESH_LARGE_VECTOR_H_

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

namespace meshseg::mesh_internal {

template <typename T>
class HugePageAllocator {
 public:
  using value_type = T;

  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) {}  // NOLINT: rebinding

  T* allocate(size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes < kThreshold) return std::allocator<T>().allocate(n);
    // Map one huge page more than needed and trim, so the buffer starts on a
    // 2 MiB boundary.
    const size_t length = RoundUp(bytes);
    char* raw = static_cast<char*>(mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE,
                                        MAP_PRIVATE | MAP_ANONYMOUS, -1, 0));
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const uintptr_t address = reinterpret_cast<uintptr_t>(raw);
    char* aligned = raw + (kHugePage - address % kHugePage) % kHugePage;
    if (aligned > raw) munmap(raw, aligned - raw);
    const size_t tail = (raw + length + kHugePage) - (aligned + length);
    if (tail > 0) munmap(aligned + length, tail);
    madvise(aligned, length, MADV_HUGEPAGE);
    return reinterpret_cast<T*>(aligned);
  }

  void deallocate(T* p, size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes < kThreshold) {
      std::allocator<T>().deallocate(p, n);
    } else {
      munmap(p, RoundUp(bytes));
    }
  }

  template <typename U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }

 private:
  static constexpr size_t kHugePage = size_t{2} << 20;
  static constexpr size_t kThreshold = size_t{4} << 20;
  static size_t RoundUp(size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }
};

template <typename T>
using LargeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_LARGE_VECTOR_H_
