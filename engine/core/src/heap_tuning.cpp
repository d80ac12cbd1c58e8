#include <sherpa/core/heap_tuning.h>

#include <cstdlib> // defines __GLIBC__ (via <features.h>) on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace sherpa::core {

void keep_freed_memory_mapped() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
}

} // namespace sherpa::core
