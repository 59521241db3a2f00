#!/usr/bin/env bash
# The tablet experiment (configs/tablet.yaml's stacks: freehand, analytic,
# justdrawit) over several seeds and noise levels: synthesises every
# MODEL x STYLE x SEED x NOISE session with `sketchlab synth` into
# OUT/sessions, runs the experiment on them into OUT/runs, and prints one
# line per (model, style, noise, stack): the median over the seeds of the
# ground-truth figures of metrics.csv (aligned: gt_distance_mean_aligned_eye_scale_m,
# written for one-view sessions, raw: gt_distance_mean_m, and the shape
# pair gt_shape_distance_mean_m / gt_shape_coverage_mean_m, eye-scaled like
# aligned where the session is one view, in mm;
# parallel/perpendicular/coincident recalls; dangling endpoint ratio; curves
# made: a distance is over the curves made only, so a session that infers
# few curves scores a small distance and a large coverage).
#
#   scripts/tablet-sweep.sh OUT
#   MODELS="cube lamp" SEEDS="1 2" NOISES="0 1" STYLES=analytic scripts/tablet-sweep.sh OUT
#   ANALYTIC_PARAMS="f_vanishing: 1" scripts/tablet-sweep.sh OUT   # the analytic stack's params (YAML map body)
#
# Needs build/bin/sketchlab (scripts/build.sh sketchlab_cli).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -eq 1 ] || { echo "usage: $0 OUT_DIR" >&2; exit 2; }
out=$1
bin="$root/build/bin/sketchlab"
models=${MODELS:-cube mug chair lamp}
seeds=${SEEDS:-1 2 3}
noises=${NOISES:-0 0.5 1 2}
styles=${STYLES:-analytic justdrawit}
mkdir -p "$out/sessions"
out=$(cd "$out" && pwd)
for model in $models; do
  for style in $styles; do
    for seed in $seeds; do
      for noise in $noises; do
        "$bin" synth "$model" --modality tablet --param "style=$style" --seed "$seed" --noise "$noise" \
          --overwrite -o "$out/sessions/${model}_${style}_n${noise}_s${seed}.jsonl" >/dev/null
      done
    done
  done
done
cat >"$out/sweep.yaml" <<EOF
experiment: tablet-sweep
recordings: [sessions/*.jsonl]
stacks:
  - {name: freehand, corrector: {plugin: freehand}}
  - {name: analytic, corrector: {plugin: analytic, params: {${ANALYTIC_PARAMS:-}}}}
  - {name: justdrawit, corrector: {plugin: justdrawit}}
outputs: {dir: $out/runs, timestamp: false, report: true, sketch_json: false, stroke_csv: false, ply: false, obj: false, mlp: false, pictures: false}
EOF
rm -rf "$out/runs/tablet-sweep"
"$bin" run "$out/sweep.yaml" --no-timings >/dev/null 2>&1
# metrics.csv: recording,stack,<sweep values>,ok,error,wall_ms,<metrics...>
awk -F, -v keys="gt_distance_mean_aligned_eye_scale_m gt_distance_mean_m gt_shape_distance_mean_m gt_shape_coverage_mean_m gt_parallel_recall gt_perpendicular_recall gt_coincident_point_recall dangling_endpoint_ratio curves" '
  function median(list,   n, a, i, j, t) {
    n = split(list, a, " ")
    for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (a[j] + 0 < a[i] + 0) { t = a[i]; a[i] = a[j]; a[j] = t }
    return n == 0 ? "-" : (n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2)
  }
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; nk = split(keys, k, " "); next }
  {
    split($col["recording"], r, "_")
    group = r[1] " " r[2] " " substr(r[3], 2) " " $col["stack"]
    if (!(group in seen)) { seen[group] = 1; order[++ng] = group }
    for (i = 1; i <= nk; ++i) {
      key = k[i]
      # The shape pair eye-scaled where the session is one view (as aligned_mm).
      if (key ~ /^gt_shape_/) { a = key; sub(/_m$/, "_aligned_eye_scale_m", a); if ((a in col) && $col[a] != "") key = a }
      if ((key in col) && $col[key] != "") v[group, i] = v[group, i] " " $col[key]
    }
  }
  END {
    for (g = 1; g <= ng; ++g) {
      printf "%s", order[g]
      for (i = 1; i <= nk; ++i) {
        x = median(v[order[g], i])
        if (x == "-") printf " -"
        else if (i <= 4) printf " %.1f", 1000 * x
        else if (k[i] == "curves") printf " %g", x
        else printf " %.2f", x
      }
      printf "\n"
    }
  }' "$out/runs/tablet-sweep/metrics.csv" | sort -k1,1 -k2,2 -k4,4 -k3,3n |
  { echo "model style noise stack aligned_mm raw_mm shape_mm coverage_mm parallel perpendicular coincident dangling curves"; cat; } | column -t
