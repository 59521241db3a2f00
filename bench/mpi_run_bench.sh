#!/usr/bin/env bash
# Distributed runs (app/mpi_run.hpp): a sweep of 4 CASSIE sessions x
# (freehand at 25 fit errors + CASSIE at 25 deltas) = 200 cases, run by
# `sketchlab run` alone (-j = every core) and by `mpirun -n N` for N = 1, 2, 4
# (rank 0 hands out the cases, the other ranks run them with their share of
# the cores; --bind-to none so each rank's threads may use every core). Prints
# wall and CPU time (user + system of every process) per run and checks that
# every run's metrics.csv is the single-process run's, byte for byte.
#
#   bench/mpi_run_bench.sh [build-dir]     (default build/; MAX_EVENTS=60)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
cli="$build/bin/sketchlab"
max_events=${MAX_EVENTS:-60}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# As root (CI, containers) mpirun needs these.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

values=$(python3 -c "print(', '.join(f'{0.1 + 0.05 * i:.2f}' for i in range(25)))")
deltas=$(python3 -c "print(', '.join(f'{0.005 + 0.001 * i:.3f}' for i in range(25)))")
cat >"$work/sweep.yaml" <<YAML
experiment: bench
recordings: [$root/data/recordings/hat.jsonl, $root/data/recordings/chair.jsonl,
             $root/data/recordings/01-2-1.jsonl, $root/data/recordings/02-1-2.jsonl]
stacks:
  - name: freehand
    input: {plugin: replay, params: {max_events: $max_events}}
    corrector: {plugin: freehand}
  - name: cassie
    input: {plugin: replay, params: {max_events: $max_events}}
    corrector: {plugin: cassie, params: {mirror: plane}}
sweep:
  stacks.0.corrector.params.fit_error: [$values]
  stacks.1.corrector.params.delta: [$deltas]
outputs: {dir: runs, timestamp: false, pictures: false}
YAML

measure() {  # label, folder, command...
  local label=$1 name=$2 dir="$work/$2"
  shift 2
  mkdir -p "$dir"
  /usr/bin/time -f "%e %U %S" -o "$dir/time.txt" bash -c 'cd "$0" && "$@" >log.txt 2>&1' "$dir" "$@" ||
    { echo "$label: exit status $?, log:" >&2; tail -3 "$dir/log.txt" >&2; }
  read -r wall user sys < <(tail -1 "$dir/time.txt")
  local same=identical
  [ "$name" = single ] || cmp -s "$work/single/runs/bench/metrics.csv" "$dir/runs/bench/metrics.csv" || same=DIFFERENT
  printf "%-34s wall %7.2f s   cpu %7.2f s   cases %s   metrics.csv %s\n" "$label" "$wall" \
    "$(awk "BEGIN {print $user + $sys}")" "$(grep -c '^' "$dir/runs/bench/metrics.csv" | awk '{print $1 - 1}')" "$same"
}

echo "mpi_run_bench: 200 cases, max_events $max_events, $(nproc) cores"
measure "sketchlab run (single process)" single "$cli" run --no-timings ../sweep.yaml
for n in 1 2 4; do
  measure "mpirun -n $n" "n$n" mpirun --oversubscribe --bind-to none -n "$n" "$cli" run --no-timings ../sweep.yaml
done
