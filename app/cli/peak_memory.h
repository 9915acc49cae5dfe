#pragma once
// The process's peak resident memory, measurable per piece of work: Linux resets the peak on request.

namespace multidir::cli {

// Starts a new peak (writes 5 to /proc/self/clear_refs). False when the kernel does not allow it; the peak read
// afterwards is then the whole process's.
bool resetPeakMemory();

// The peak resident set since the last reset, or since the process started (VmHWM), in MiB; 0 if unknown.
double peakMemoryMiB();

}  // namespace multidir::cli
