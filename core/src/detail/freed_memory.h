#pragma once
// Hands the heap a search freed back to the system. glibc keeps what worker threads freed in their arenas
// (and the main arena's top) until asked, so a finished search on a million faces would otherwise leave its
// peak as the process's resident size.
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace multidir::core::detail {

inline void returnFreedMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace multidir::core::detail
