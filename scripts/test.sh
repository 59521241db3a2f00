#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite: every test in the normal
# build, then the kernel tests again under AddressSanitizer + UBSan.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
jobs=$(nproc)

"$root/scripts/build.sh"
(cd "$root/build" && ctest --output-on-failure -j "$jobs")

"$root/scripts/build.sh" --sanitize
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd "$root/build-asan" && ctest --output-on-failure -j "$jobs" -R '^kernel/')
