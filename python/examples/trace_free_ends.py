"""Where the ends of unconstrained strokes lie against their raw samples
(cassie README, "The newer app's last end").

For every Bézier stroke whose raw_data log holds no position constraint,
applied or rejected (nothing pulled its ends), prints per group of sessions,
for CASSIE's curve and for ours (the cassie corrector, mirror=plane): the
share of first and last ends exactly at the first and last raw sample (0.05
mm), the median distance to it, and where the last end projects onto the
last raw segment (t = 1 at the last sample, 0 at the one before); then the
last end's median distance by the raw stroke's length.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/trace_free_ends.py \\
        [--param NAME=VALUE ...] [SESSION...]

With no session named: every session of data/recordings, Freehand ones
included (compared there with the freehand corrector: CASSIE only fitted
them).
"""
import sys

import example_args
import numpy as np
import sketchlab as sl

from trace_geometry_residual import read_logs

EXACT = 5e-5  # m
BANDS = (0.0, 0.1, 0.2, 0.4, float("inf"))  # m, raw stroke length


def group(session):
    if session[:1].isdigit():
        return {"0": "Freehand", "1": "Armature", "2": "Patch"}[session[3]] + f" (participant {session[:2]})"
    return "showcase"


def on_last_segment(raw, p):
    """Parameter of p's projection onto the last raw segment (1: the last sample)."""
    a, b = raw[-2], raw[-1]
    ab = b - a
    return float((p - a) @ ab / max(ab @ ab, 1e-18))


def main(sessions, params):
    rows = {}
    for session in sessions:
        freehand = session[3:4] == "0"
        logs = read_logs(session)
        rec = sl.read_recording(f"data/recordings/{session}.jsonl")
        strokes = {e.stroke.id: np.array(e.stroke.points) for e in rec.events if e.type == "stroke"}
        corrector = sl.corrector("freehand", {}) if freehand else sl.corrector("cassie", params)
        for r in sl.teacher_forced(rec, corrector):
            raw = strokes.get(r.stroke)
            log = logs.get(r.stroke)
            if not r.compared or r.reference_line or raw is None or len(raw) < 3:
                continue
            if not freehand and (log is None or log["applied"] or log["rejected"]):
                continue
            length = np.linalg.norm(np.diff(raw, axis=0), axis=1).sum()
            theirs = np.array(r.reference_curve.sample(2))
            ours = np.array(r.output_curve.sample(2))
            if r.reversed:
                ours = ours[::-1]
            for who, ends in (("cassie", theirs), ("ours", ours)):
                d0, d1 = np.linalg.norm(ends[0] - raw[0]), np.linalg.norm(ends[-1] - raw[-1])
                rows.setdefault((group(session), who), []).append((d0, d1, on_last_segment(raw, ends[-1]), length))
    print("group who strokes first_exact_pct first_median_mm last_exact_pct last_median_mm last_t_median")
    for (g, who), v in sorted(rows.items()):
        a = np.array(v)
        print(f"{g!r} {who} {len(a)} {100 * np.mean(a[:, 0] < EXACT):.0f} {1000 * np.median(a[:, 0]):.2f} "
              f"{100 * np.mean(a[:, 1] < EXACT):.0f} {1000 * np.median(a[:, 1]):.2f} {np.median(a[:, 2]):.2f}")
    print("\ngroup who length_cm strokes last_median_mm")
    for (g, who), v in sorted(rows.items()):
        a = np.array(v)
        for lo, hi in zip(BANDS, BANDS[1:]):
            band = a[(a[:, 3] >= lo) & (a[:, 3] < hi)]
            if len(band):
                print(f"{g!r} {who} {100 * lo:.0f}-{100 * hi:.0f} {len(band)} {1000 * np.median(band[:, 1]):.2f}")


if __name__ == "__main__":
    sessions, params = example_args.parse(sys.argv[1:], "all")
    main(sessions, {"mirror": "plane", **params})
