#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite: every test in the normal
# build, then tests again under AddressSanitizer + UBSan (build-asan/, no
# viewers, see scripts/build.sh), then each libFuzzer harness for a bounded
# time on its corpus (scripts/fuzz.sh; FUZZ_SECONDS, default 60 s per harness;
# FUZZ_SECONDS=0 skips fuzzing).
#
# SANITIZE=kernel (the default, what CI runs) builds and runs the kernel's
# tests under the sanitizers; SANITIZE=all builds and runs the whole suite
# under them. Measured cold on 2 cores, the whole-suite sanitizer build takes
# 36 min (4,037 s CPU at -O1), which with the Release build (19 min) and the
# fuzzers (9 min) exceeds CI's 60 min; the kernel scope keeps CI near 40 min.
# SANITIZE=none skips the sanitizer stage.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
jobs=$(nproc)
scope="${SANITIZE:-kernel}"
case "$scope" in kernel | all | none) ;;
  *) echo "test.sh: SANITIZE=$scope: allowed values are kernel, all, none" >&2; exit 2 ;;
esac

"$root/scripts/build.sh"
(cd "$root/build" && ctest --output-on-failure -j "$jobs")

# --- installed SDK (issue #22) ---------------------------------------------
# Installs build/ into a clean prefix, builds examples/plugin out of tree
# against it, loads it into the installed binary and imports the installed
# Python package (scripts/check-install.sh, about a minute). The Python API's
# pytest suites run in the ctest above (tests/python, label "python").
"$root/scripts/check-install.sh" "$root/build"
# --- end installed SDK -------------------------------------------------------

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
if [ "$scope" = kernel ]; then
  "$root/scripts/build.sh" --sanitize sketchlab_kernel_tests
  (cd "$root/build-asan" && ctest --output-on-failure -j "$jobs" -R '^kernel/')
elif [ "$scope" = all ]; then
  "$root/scripts/build.sh" --sanitize
  # The hostile-strokes property test (10^6-sample strokes on 15 stacks, 87 s
  # in Release) did not finish in 9 min under the sanitizers: it runs in
  # Release.
  (cd "$root/build-asan" && ctest --output-on-failure -j "$jobs" -LE '^plugins/inputs/openxr$' \
     -E 'hostile strokes never hang')
  # The openxr input's end-to-end tests run `record` through Debian's OpenXR
  # loader (not instrumented) and the test runtime. LeakSanitizer reports 88
  # bytes (+1.2 KB) left at exit by `record --input openxr`, allocated in
  # modules already unloaded then (the plugin, the loader or the runtime), not
  # yet attributed: memory errors and UB are checked there, leaks are not.
  (cd "$root/build-asan" && ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 ctest --output-on-failure -j "$jobs" -L '^plugins/inputs/openxr$')
fi

if [ "${FUZZ_SECONDS:-60}" != 0 ]; then
  "$root/scripts/fuzz.sh"
fi
