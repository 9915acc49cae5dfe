// The programs run on tcmalloc (docs/architecture.md, "Memory allocator"); core hands freed memory back to the
// system through whichever allocator the program runs on.
#include <gtest/gtest.h>

#include <cstddef>
#include <memory>

#include "detail/freed_memory.h"

#if defined(MULTIDIR_TCMALLOC)
#include <gperftools/malloc_extension_c.h>

namespace {

std::size_t tcmallocBytes(const char* property) {
  std::size_t value = 0;
  EXPECT_TRUE(MallocExtension_GetNumericProperty(property, &value)) << property;
  return value;
}

TEST(FreedMemory, TheTestsRunOnTcmallocAsThePrograms) {
  // Fails when the program's malloc is not tcmalloc's (the property is tcmalloc's own).
  std::size_t allocated = 0;
  EXPECT_TRUE(MallocExtension_GetNumericProperty("generic.current_allocated_bytes", &allocated));
}

TEST(FreedMemory, ReturningFreedMemoryHandsTcmallocsFreePagesBackToTheSystem) {
  {
    // 64 MiB touched and freed: tcmalloc keeps the pages mapped for reuse until asked.
    constexpr std::size_t kBytes = std::size_t{64} << 20;
    std::unique_ptr<char[]> block(new char[kBytes]);
    for (std::size_t i = 0; i < kBytes; i += 4096) block[i] = static_cast<char>(i);
  }
  ASSERT_GE(tcmallocBytes("tcmalloc.pageheap_free_bytes"), std::size_t{32} << 20);
  multidir::core::detail::returnFreedMemory();
  EXPECT_LT(tcmallocBytes("tcmalloc.pageheap_free_bytes"), std::size_t{32} << 20);
}

}  // namespace
#endif
