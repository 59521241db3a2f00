#!/usr/bin/env bash
# Configures and builds sketchlab in build/ (Release) or, with --sanitize, in
# build-asan/ (ASan + UBSan, no viewers, kernel tests only).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir="$root/build"
args=(-DCMAKE_BUILD_TYPE=Release)
targets=(all)
if [ "${1:-}" = "--sanitize" ]; then
  shift
  dir="$root/build-asan"
  args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSKETCHLAB_SANITIZE=ON -DSKETCHLAB_BUILD_VIEWERS=OFF -DSKETCHLAB_BUILD_BENCH=OFF)
  targets=(sketchlab_kernel_tests)
fi
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f "$dir/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$dir" "${generator[@]}" "${args[@]}" >/dev/null
fi
cmake --build "$dir" -j "$(nproc)" --target "${targets[@]}"
