#include "render/huge_page_allocator.h"

#include <cstdint>

#if defined(RUGOSIM_HUGE_PAGE_MAPPINGS)
#include <sys/mman.h>
#endif

namespace rugosim::huge_pages {
#if defined(RUGOSIM_HUGE_PAGE_MAPPINGS)
namespace {

std::size_t round_up(std::size_t bytes) {
  return (bytes + kHugePage - 1) & ~(kHugePage - 1);
}

}  // namespace
#endif

void* allocate(std::size_t bytes) {
#if defined(RUGOSIM_HUGE_PAGE_MAPPINGS)
  if (bytes >= kHugePageMinimum) {
    // Mapped one huge page longer than needed, then trimmed at both ends to a 2 MB boundary:
    // the kernel puts huge pages only where a whole aligned 2 MB range is mapped.
    const std::size_t length = round_up(bytes);
    void* mapped = ::mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE,
                          MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t aligned = (start + kHugePage - 1) & ~(std::uintptr_t{kHugePage} - 1);
    if (aligned > start) ::munmap(mapped, aligned - start);
    // aligned - start < kHugePage, so a tail is always left over.
    const std::uintptr_t end = start + length + kHugePage;
    ::munmap(reinterpret_cast<void*>(aligned + length), end - (aligned + length));
    // Advice only: refused (THP "never", an old kernel), the buffer is an ordinary mapping.
    ::madvise(reinterpret_cast<void*>(aligned), length, MADV_HUGEPAGE);
    return reinterpret_cast<void*>(aligned);
  }
#endif
  return ::operator new(bytes);
}

void deallocate(void* pointer, [[maybe_unused]] std::size_t bytes) {
  if (pointer == nullptr) return;
#if defined(RUGOSIM_HUGE_PAGE_MAPPINGS)
  if (bytes >= kHugePageMinimum) {
    ::munmap(pointer, round_up(bytes));
    return;
  }
#endif
  ::operator delete(pointer);
}

}  // namespace rugosim::huge_pages
