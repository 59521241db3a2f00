#!/usr/bin/env bash
# Sets up, builds the whole test suite once and runs every test, then each
# libFuzzer harness for a bounded time on its corpus (scripts/fuzz.sh;
# FUZZ_SECONDS, default 60 s per harness; FUZZ_SECONDS=0 skips fuzzing).
#
# SANITIZE=all (the default, what CI runs) builds everything under
# AddressSanitizer + UBSan (build-asan/, scripts/build.sh --sanitize) and runs
# every test there, leaks checked (suppressions: tests/lsan.supp).
# SANITIZE=none builds and tests in Release (build/) instead.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
jobs=$(nproc)
case "${SANITIZE:-all}" in
  all)
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      LSAN_OPTIONS=suppressions=$root/tests/lsan.supp:print_suppressions=0
    build="$root/build-asan"
    "$root/scripts/build.sh" --sanitize ;;
  none)
    build="$root/build"
    "$root/scripts/build.sh" ;;
  *) echo "test.sh: SANITIZE=$SANITIZE: allowed values are all, none" >&2; exit 2 ;;
esac
(cd "$build" && ctest --output-on-failure -j "$jobs")

# --- installed SDK (issue #22) ---------------------------------------------
# Installs the build just tested into a clean prefix, builds examples/plugin
# out of tree against it, loads it into the installed binary and imports the
# installed Python package (scripts/check-install.sh, seconds). The Python
# API's pytest suites run in the ctest above (tests/python, label "python").
"$root/scripts/check-install.sh" "$build"
# --- end installed SDK -------------------------------------------------------

if [ "${FUZZ_SECONDS:-60}" != 0 ]; then
  "$root/scripts/fuzz.sh"
fi
