"""Traces the ends of the `sketchlab fidelity --causes` row "we snapped, CASSIE
free: CASSIE applied one there, its end is off it" (cassie README, section
'"CASSIE applied one there, its end is off it", traced').

Selects the ends as app/fidelity_causes.cpp does for that row (our end
snapped, CASSIE's free, no rejected but an applied CASSIE target within 2 cm
of our end), on drawn strokes with their own raw_data log (mirrored twins
left out), then reruns each session with one rule of ours switched off and
says which one frees our end.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/trace_applied_off_end.py \\
        [--param NAME=VALUE ...] [SESSION...]
"""
import collections
import json
import os
import sys

import example_args
import numpy as np
import sketchlab as sl

NEAR = 0.02  # m, --cause-distance's default
BASE = {"mirror": "plane"}
VARIANTS = {  # first that frees our end names the rule
    "item 16 trim": {"trim_dangling": False},
    "item 3 hook cut": {"remove_hooks": False},
    "item 9 overlap cut": {"overlap_cut": False},
    "item 12 end-anchor reuse": {"reuse": 0.0, "trim_dangling": False},
}


def read_logs(session):
    path = f"data/cassie/raw_data/{session}.json"
    if not os.path.exists(path):
        return {}
    point = lambda q: np.array([q["x"], q["y"], q["z"]])
    logs = {}
    for s in json.load(open(path)).get("allSketchedStrokes", []):
        log = {}
        for key in ("appliedPositionConstraints", "rejectedPositionConstraints"):
            log[key] = [(point(q["position"]), q) if "position" in q else (point(q), {}) for q in s.get(key, [])]
        logs[s["id"]] = log
    return logs


def traced_ends(rows, logs):
    for r in rows:
        log = logs.get(r.stroke)
        if not r.compared or log is None or r.reference_line != r.output_line:
            continue
        for k in range(2):
            if r.reference_snap[k] or not r.output_snap[k]:
                continue
            cassie_end, our_end = r.reference_end[k], r.output_end[k]
            near = lambda key: [(p, f) for p, f in log[key] if np.linalg.norm(p - our_end) <= NEAR]
            if near("rejectedPositionConstraints") or not near("appliedPositionConstraints"):
                continue
            target, flags = min(near("appliedPositionConstraints"), key=lambda pf: np.linalg.norm(pf[0] - our_end))
            yield r.stroke, k, np.linalg.norm(cassie_end - target), flags


def main(sessions, params):
    counts = collections.Counter()
    for session in sessions:
        rec = sl.read_recording(f"data/recordings/{session}.jsonl")
        logs = read_logs(session)
        now = sl.teacher_forced(rec, sl.corrector("cassie", {**BASE, **params}))
        runs = {name: {r.stroke: r for r in sl.teacher_forced(rec, sl.corrector("cassie", {**BASE, **params, **p}))}
                for name, p in VARIANTS.items()}
        group = "showcase" if session[0].isalpha() else "study"
        for stroke, k, off, flags in traced_ends(now, logs):
            if off < 0.002:
                cause = "CASSIE's end at its target, 0.1-2 mm off"
                moved = ""
            else:
                cause, moved = "other", ""
                for name, run in runs.items():
                    r = run[stroke]
                    if not r.output_snap[k]:
                        cassie_end, our_end = r.reference_end[k], r.output_end[k]
                        cause, moved = name, f"freed, {1000 * np.linalg.norm(cassie_end - our_end):.1f} mm from CASSIE's"
                        break
            counts[(cause, group)] += 1
            print(f"{session} {stroke}/{k}: CASSIE's end {1000 * off:.1f} mm from its target "
                  f"(isAtNewEndpoint {flags.get('isAtNewEndpoint', '-')}); {cause} {moved}")
    for (cause, group), n in sorted(counts.items()):
        print(f"{cause:45s} {group:9s} {n}")


if __name__ == "__main__":
    main(*example_args.parse(sys.argv[1:]))
