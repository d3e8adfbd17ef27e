// Memory for frame-sized buffers (a 4K RGBA frame is 33 MB) in transparent huge pages.
//
// A fresh page costs a fault when it is first written, and a process that renders touches its
// frame buffers before its first frame is out: a short render (a farm's chunk) pays that once
// per process, so it is part of what a chunk costs more than the same frames inside a long
// render. In 4 KB pages a 33 MB buffer takes 8,100 faults, in 2 MB pages 17. Measured on these
// machines (a virtual machine, where a fault costs about 9 µs): writing 330 MB of fresh memory
// takes 0.76–1.5 s in 4 KB pages and 0.03–0.5 s in huge pages; a re-write 0.02 s
// (docs/scale-out.md). glibc asks for huge pages only when told at process start
// (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), so buffers of at least kHugePageMinimum bytes are
// mapped here, aligned to 2 MB and advised MADV_HUGEPAGE, which the kernel honours in its
// default "madvise" mode. Where the kernel says no (THP "never", another system) the mapping is
// an ordinary one: the same pixels, only the faults differ. Smaller buffers use operator new.
#pragma once

#include <cstddef>
#include <new>

namespace rugosim {

namespace huge_pages {
inline constexpr std::size_t kHugePageMinimum = std::size_t{4} << 20;  // bytes
inline constexpr std::size_t kHugePage = std::size_t{2} << 20;  // x86-64's and arm64's PMD size
// Whether large buffers are mappings of their own: on Linux, except under the sanitizers, where
// every buffer comes from operator new so that AddressSanitizer still sees a frame's bounds.
#if defined(__linux__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define RUGOSIM_HUGE_PAGE_MAPPINGS 1
inline constexpr bool kMapsLargeBuffers = true;
#else
inline constexpr bool kMapsLargeBuffers = false;
#endif
void* allocate(std::size_t bytes);                  // throws std::bad_alloc
void deallocate(void* pointer, std::size_t bytes);  // bytes: as allocated
}  // namespace huge_pages

template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(huge_pages::allocate(n * sizeof(T)));
  }
  void deallocate(T* pointer, std::size_t n) noexcept {
    huge_pages::deallocate(pointer, n * sizeof(T));
  }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;  // stateless: any instance frees what another allocated
  }
};

}  // namespace rugosim
