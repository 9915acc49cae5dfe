#pragma once
// Process-wide allocator settings for searching big models, set once at the start of main().

namespace multidir::app {

// The programs run on tcmalloc (docs/architecture.md, "Memory allocator"), which needs no settings. A build
// without it (-DMULTIDIR_TCMALLOC=OFF, for the sanitizers) runs on glibc's malloc, tuned here for the search's
// pattern: large arrays (a million-face mesh's vertices, faces and per-face sums) made and freed again and again,
// on worker threads.
// - One arena: memory freed by one thread is reused by the next, instead of stranded in the arena of the
//   thread that allocated it (a search's worker threads come and go). The price is the threads waiting on its
//   lock (the noisy 1M knight: 8.5 s against 6.7 s with an arena per thread, at 350 against 455 MiB).
// - Freed blocks up to 32 MiB are kept in the heap for reuse instead of returned to the system and faulted in
//   again page by page (on this project's 2-core VM a page fault costs microseconds: at 64x the kitten's run
//   took 102,000 of them; with these settings 60,000, and its peak memory fell from 192 to 148 MiB).
// A no-op on tcmalloc and where the C library is not glibc.
void tuneHeapForLargeMeshes();

}  // namespace multidir::app
