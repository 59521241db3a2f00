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
# The hostile-strokes property test (10^6-sample strokes on 15 stacks, 87 s in
# Release) did not finish in 9 min under the sanitizers: it runs in Release.
(cd "$root/build-asan" && ctest --output-on-failure -j "$jobs" -LE '^plugins/inputs/openxr$' \
   -E 'hostile strokes never hang')
# The openxr input's end-to-end tests run `record` through Debian's OpenXR
# loader (not instrumented) and the test runtime. LeakSanitizer reports 88
# bytes (+1.2 KB) left at exit by `record --input openxr`, allocated in
# modules already unloaded then (the plugin, the loader or the runtime), not
# yet attributed: memory errors and UB are checked there, leaks are not yet
# (an open item of issue 17).
(cd "$root/build-asan" && ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 ctest --output-on-failure -j "$jobs" -L '^plugins/inputs/openxr$')

if [ "${FUZZ_SECONDS:-60}" != 0 ]; then
  "$root/scripts/fuzz.sh"
fi
