#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite: every test in the normal
# build, then every test again under AddressSanitizer + UBSan (build-asan/:
# no viewers, see scripts/build.sh), then each libFuzzer harness for a
# bounded time on its corpus (scripts/fuzz.sh; FUZZ_SECONDS, default 60 s
# per harness; FUZZ_SECONDS=0 skips fuzzing).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
jobs=$(nproc)

"$root/scripts/build.sh"
(cd "$root/build" && ctest --output-on-failure -j "$jobs")

"$root/scripts/build.sh" --sanitize
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd "$root/build-asan" && ctest --output-on-failure -j "$jobs")

if [ "${FUZZ_SECONDS:-60}" != 0 ]; then
  "$root/scripts/fuzz.sh"
fi
