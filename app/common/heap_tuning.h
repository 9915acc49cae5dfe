#pragma once
// Process-wide allocator settings for searching big models, set once at the start of main().

namespace multidir::app {

// glibc's malloc, tuned for the search's pattern: large arrays (a million-face mesh's vertices, faces and
// per-face sums) made and freed again and again, on worker threads.
// - One arena: memory freed by one thread is reused by the next, instead of stranded in the arena of the
//   thread that allocated it (a search's worker threads come and go).
// - Freed blocks up to 32 MiB are kept in the heap for reuse instead of returned to the system and faulted in
//   again page by page (on this project's 2-core VM a page fault costs microseconds: at 64x the kitten's run
//   took 102,000 of them; with these settings 60,000, and its peak memory fell from 192 to 148 MiB).
// A no-op where the C library is not glibc.
void tuneHeapForLargeMeshes();

}  // namespace multidir::app
