#pragma once
// Large buffers in 2 MiB pages. The first touch of a fresh 4 KiB page costs a page fault, and on this
// project's machines (virtualised) a fault is slow: filling 100 MB of new memory took 0.3-0.9 s in 4 KiB
// pages and 0.03-0.05 s in 2 MiB ones. Loading and decimating a million-triangle model fills several hundred
// MB of new arrays, so its big buffers are reserved here first. With transparent huge pages set to
// "madvise" (the usual default) the kernel gives the advised range 2 MiB pages; with "never", or on other
// systems, this is a plain reserve. Only where memory goes, never what is stored: results are unchanged.
#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace multidir::core::detail {

// Below this a buffer is not worth a system call.
constexpr std::size_t kHugePageMinBytes = std::size_t{4} << 20;

// Advises the 2 MiB-aligned interior of [data, data + bytes) for huge pages.
inline void adviseHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes < kHugePageMinBytes) return;
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // a hint: errors ignored
#else
  (void)data;
  (void)bytes;
#endif
}

// v.reserve(count), the new buffer advised for huge pages before anything is written to it. Call on an
// empty vector (or one whose contents may move): what is already stored is copied as reserve copies it.
template <typename T>
void reserveInHugePages(std::vector<T>& v, std::size_t count) {
  if (count <= v.capacity()) return;
  v.reserve(count);
  adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

// A vector of `count` copies of `value` in huge pages.
template <typename T>
std::vector<T> filledInHugePages(std::size_t count, const T& value) {
  std::vector<T> v;
  reserveInHugePages(v, count);
  v.assign(count, value);
  return v;
}

}  // namespace multidir::core::detail
