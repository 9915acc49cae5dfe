#pragma once
// Hands the heap a search freed back to the system, so that a finished search on a million faces does not leave
// its peak as the process's resident size. Which call does that depends on the program's allocator (core links
// none: the programs choose, docs/architecture.md "Memory allocator"): tcmalloc's release when the program runs
// on tcmalloc (found through a weak reference, so core needs no gperftools), else glibc's trim, which hands back
// what worker threads freed in their arenas and the main arena's top.
#if defined(__GLIBC__)
#include <malloc.h>
#endif

extern "C" void MallocExtension_ReleaseFreeMemory(void) __attribute__((weak));

namespace multidir::core::detail {

inline void returnFreedMemory() {
  if (MallocExtension_ReleaseFreeMemory != nullptr) {
    MallocExtension_ReleaseFreeMemory();
    return;
  }
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace multidir::core::detail
