"""How a stroke with one applied constraint moves (cassie README, "How a
stroke with one applied constraint moves, by session").

For every stroke whose raw_data log holds exactly one applied position
constraint lying at an end of CASSIE's curve (within 0.1 mm), compares the
displacement of each curve end from the raw stroke's end sample: the free
end's over the snapped end's (1: the curve moved as a whole; small: it bent
near the snap), and the cosine between the two displacements. Printed per
session for CASSIE's curve and for ours (the cassie corrector, mirror=plane)
on the same strokes.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/trace_one_constraint_motion.py \\
        [--param NAME=VALUE ...] [SESSION...]

--param: corrector parameters for a reading (e.g. position_scale=8).
"""
import sys

import example_args
import numpy as np
import sketchlab as sl

from trace_geometry_residual import read_logs

AT_END = 1e-4  # m: the applied target is the curve's end


def one_applied(session):
    """Stroke id -> the single applied target, for strokes that logged exactly one."""
    return {sid: np.array(log["applied"][0]) for sid, log in read_logs(session).items() if len(log["applied"]) == 1}


def motion(ends, raw, snapped):
    """(free end's displacement / snapped end's, cosine of the two)."""
    k = snapped
    d_snap = ends[k] - raw[0 if k == 0 else -1]
    d_free = ends[1 - k] - raw[-1 if k == 0 else 0]
    ns, nf = np.linalg.norm(d_snap), np.linalg.norm(d_free)
    return nf / max(ns, 1e-6), float(d_snap @ d_free) / max(ns * nf, 1e-12)


def main(sessions, params):
    print("session strokes cassie_ratio cassie_cos ours_ratio")
    for session in sessions:
        targets = one_applied(session)
        rec = sl.read_recording(f"data/recordings/{session}.jsonl")
        raw = {e.stroke.id: np.array(e.stroke.points) for e in rec.events if e.type == "stroke"}
        theirs, ours = [], []
        for r in sl.teacher_forced(rec, sl.corrector("cassie", params)):
            if not r.compared or r.stroke not in targets or len(raw.get(r.stroke, [])) < 3:
                continue
            ref = np.array(r.reference_curve.sample(2))
            gaps = [np.linalg.norm(ref[0] - targets[r.stroke]), np.linalg.norm(ref[-1] - targets[r.stroke])]
            if min(gaps) > AT_END:
                continue
            snapped = int(gaps[1] < gaps[0])
            out = np.array(r.output_curve.sample(2))
            if r.reversed:
                out = out[::-1]
            theirs.append(motion(ref, raw[r.stroke], snapped))
            ours.append(motion(out, raw[r.stroke], snapped)[0])
        if theirs:
            t = np.array(theirs)
            print(f"{session} {len(t)} {np.median(t[:, 0]):.2f} {np.median(t[:, 1]):.2f} {np.median(ours):.2f}")


if __name__ == "__main__":
    sessions, params = example_args.parse(sys.argv[1:], "logged")
    main(sessions, {"mirror": "plane", **params})
