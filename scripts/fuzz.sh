#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan, build-fuzz/) and runs
# each on its corpus in fuzz/corpus/<harness>/ for FUZZ_SECONDS (default 60),
# as many at a time as there are cores. New inputs go to a scratch copy of
# the corpus (the repository's changes only on purpose, see fuzz/README.md).
# A crash, a leak, undefined behaviour, an input taking over 10 s or 2 GB
# fails the run: the harness's report and the reproducer (base64, with the
# command that replays it) are printed.
#   scripts/fuzz.sh                       # every harness, 60 s each
#   FUZZ_SECONDS=3600 scripts/fuzz.sh fuzz_recording
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir="$root/build-fuzz"
seconds="${FUZZ_SECONDS:-60}"
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(fuzz_recording fuzz_sketch_json fuzz_config fuzz_cassie_import fuzz_openxr_input
                                    fuzz_cassie_graph fuzz_cassie_session fuzz_stroke_session
                                    fuzz_stroke_session_scaffold fuzz_tablet_session)

if [ ! -f "$dir/CMakeCache.txt" ]; then
  generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  # -O1 -g1 (line tables: file:line in the reports) compiles 17-23 % faster
  # than RelWithDebInfo's -O2 -g (patch_mesh.cpp 65 s against 78 s of CPU,
  # kkt_solve.cpp 22 s against 28 s), which CI builds from scratch.
  CC=clang CXX=clang++ cmake -S "$root" -B "$dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
    -DSKETCHLAB_FUZZ=ON -DSKETCHLAB_BUILD_TESTS=OFF -DSKETCHLAB_BUILD_BENCH=OFF \
    -DSKETCHLAB_BUILD_VIEWERS=OFF >/dev/null
fi
cmake --build "$dir" -j "$(nproc)" --target "${harnesses[@]}"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
run_one() {
  local h=$1 work="$dir/fuzz/work/$1" artifacts="$dir/fuzz/artifacts/$1"
  rm -rf "$work" "$artifacts"
  mkdir -p "$work" "$artifacts"
  cp -r "$root/fuzz/corpus/$h/." "$work/"
  if "$dir/fuzz/$h" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
       -artifact_prefix="$artifacts/" "$work" >"$dir/fuzz/$h.log" 2>&1; then
    echo "fuzz: $h: $(grep -m1 'stat::number_of_executed_units' "$dir/fuzz/$h.log" | awk '{print $2}') runs in ${seconds} s, no failure"
    return 0
  fi
  echo "fuzz: $h FAILED; its report:"
  tail -n 60 "$dir/fuzz/$h.log"
  for f in "$artifacts"/*; do
    [ -f "$f" ] || continue
    echo "fuzz: reproducer $(basename "$f") ($(stat -c %s "$f") bytes), base64:"
    base64 -w 100 "$f" | head -c 40000
    echo
    echo "fuzz: replay with: $dir/fuzz/$h $f"
  done
  return 1
}
export -f run_one
export dir root seconds
printf '%s\n' "${harnesses[@]}" | xargs -P "$(nproc)" -I{} bash -c 'run_one {}'
