#include "sketchlab/heap_policy.hpp"

#include <algorithm>
#include <climits>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace sketchlab {

bool keep_freed_heap(std::size_t keep_bytes) {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  // Setting either threshold also stops glibc's own adjustment of both, so
  // the policy does not depend on what the process allocated before.
  const int keep = static_cast<int>(std::min<std::size_t>(keep_bytes, INT_MAX));
  return mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1 && mallopt(M_TRIM_THRESHOLD, keep) == 1;
#else
  (void)keep_bytes;
  return false;
#endif
}

}  // namespace sketchlab
