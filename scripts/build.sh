#!/usr/bin/env bash
# Configures and builds sketchlab in build/ (Release) or, with --sanitize, in
# build-asan/ (ASan + UBSan: every target, the viewers, benchmarks and the
# whole test suite included; or only the targets named after --sanitize).
# The sanitizer build is the one CI builds and tests (scripts/test.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir="$root/build"
args=(-DCMAKE_BUILD_TYPE=Release)
targets=(all)
if [ "${1:-}" = "--sanitize" ]; then
  shift
  dir="$root/build-asan"
  # -O1 -g1 (line tables: file:line in the sanitizers' reports) compiles the
  # instrumented code 2.6x faster than -O2 -g (json_codec.cpp: 47 s against
  # 121 s of CPU), which keeps the whole suite's sanitizer build within CI.
  args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
        -DSKETCHLAB_SANITIZE=ON)
fi
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f "$dir/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$dir" "${generator[@]}" "${args[@]}" >/dev/null
fi
[ $# -gt 0 ] && targets=("$@")
cmake --build "$dir" -j "$(nproc)" --target "${targets[@]}"
