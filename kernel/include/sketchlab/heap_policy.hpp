#pragma once
// The heap policy of sketchlab's own programs (the CLI with its viewers, the
// benchmarks): freed memory stays with the process for reuse.
#include <cstddef>

namespace sketchlab {

// Asks the C library to keep up to `keep_bytes` of freed heap instead of
// returning it to the system at each free, and to serve blocks up to 32 MB
// from the heap. glibc's defaults trim the heap top as soon as 128 KB or
// more is free and fault it in again at the next allocation; a solver that
// allocates and frees its workspace per subset tried (Eigen's SparseLU: a
// few hundred KB per factorisation) then pays a system call, a TLB flush
// and fresh page faults every time, which doubled the slowest real stroke's
// correction (cassie README, "Latency"). Call once at the start of main,
// before threads start; process-wide. Returns false where the allocator
// takes no such setting (not glibc, or a sanitizer's allocator).
bool keep_freed_heap(std::size_t keep_bytes = std::size_t{64} << 20);

}  // namespace sketchlab
