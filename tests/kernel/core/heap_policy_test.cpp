#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>

#include "sketchlab/heap_policy.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

TEST_CASE("keep_freed_heap: a freed solver-sized block stays with the process", "[heap]") {
  if (!sketchlab::keep_freed_heap()) {
    WARN("the allocator takes no trim setting here (sanitizer build or not glibc)");
    return;
  }
#if defined(__GLIBC__)
  // 1 MB: above glibc's default mmap threshold (128 KB), so by default it is
  // mapped and unmapped on its own; under the policy it comes from the heap
  // and, freed, stays there as releasable space at the top.
  constexpr std::size_t size = std::size_t{1} << 20;
  char* block = static_cast<char*>(std::malloc(size));
  REQUIRE(block);
  std::memset(block, 1, size);
  const std::size_t mapped_before_free = mallinfo2().hblkhd;
  std::free(block);
  const struct mallinfo2 info = mallinfo2();
  CHECK(info.hblkhd == mapped_before_free);  // it was not a mapping of its own
  CHECK(info.keepcost >= size);              // the heap top was not trimmed
#endif
}
