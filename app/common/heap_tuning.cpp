#include "heap_tuning.h"

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__) && !defined(MULTIDIR_TCMALLOC)
#include <malloc.h>
#endif

namespace multidir::app {

void tuneHeapForLargeMeshes() {
#if defined(__GLIBC__) && !defined(MULTIDIR_TCMALLOC)
  constexpr int kLargestHeapBlock = 32 * 1024 * 1024;  // glibc's ceiling for the mmap threshold on 64-bit
  constexpr int kKeptFreeTop = 256 * 1024 * 1024;
  mallopt(M_ARENA_MAX, 1);
  mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
  mallopt(M_TRIM_THRESHOLD, kKeptFreeTop);
#endif
}

}  // namespace multidir::app
