// Scratch memory for the tangent generators (see ScratchAllocator in tangent_internal.h).
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "tangent_internal.h"

namespace sherpa::scene::tangent_detail {
namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
std::size_t huge_size(std::size_t bytes) {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}
} // namespace

void* allocate_scratch(std::size_t bytes) {
    if (bytes < kHugePage) return ::operator new(bytes);
    const std::size_t size = huge_size(bytes);
    void* p = std::aligned_alloc(kHugePage, size);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, size, MADV_HUGEPAGE); // advice only: failure leaves ordinary pages
#endif
    return p;
}

void free_scratch(void* p, std::size_t bytes) noexcept {
    if (bytes < kHugePage)
        ::operator delete(p);
    else
        std::free(p);
}

} // namespace sherpa::scene::tangent_detail
