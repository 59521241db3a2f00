"""How often CASSIE's search rejected a constraint, against ours (cassie
README, "How often each search rejects").

Per session, over the drawn strokes that have a raw_data log: the strokes
whose log rejects a position constraint, those where one rejected lies more
than 1 cm from every applied one (not a duplicate lost to a clash, item 12),
and the strokes where our corrector leaves one of its position constraints
unenforced. Then every logged target is placed by where it lies on CASSIE's
curve (within δ of an end, or inside) and by what we did with the target we
detected nearest it within δ/2 (enforced, rejected, none there). Last, the
mirror-plane targets logged more than 2.5δ from the stroke's samples: item 18
makes a plane constraint only where the brush touches the plane.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/trace_rejections.py \\
        [--param NAME=VALUE ...] [SESSION...]

--param: corrector parameters for a reading (e.g. lambda=0.85).
"""
import collections
import sys

import example_args
import numpy as np
import sketchlab as sl

from trace_geometry_residual import POS, read_logs
from trace_target_positions import nearest_on_polyline


def main(sessions, params):
    places = collections.Counter()
    print("session strokes cassie_rejects cassie_rejects_far ours_rejects far_plane_targets")
    for session in sessions:
        rec = sl.read_recording(f"data/recordings/{session}.jsonl")
        ws = rec.header.workspace
        normal, offset = np.array(ws.mirror_normal), ws.mirror_offset
        strokes = {s.id: s for s in rec.strokes()}
        logs = read_logs(session)
        n = theirs = theirs_far = ours = far_plane = 0
        for r in sl.teacher_forced(rec, sl.corrector("cassie", params)):
            log, stroke = logs.get(r.stroke), strokes.get(r.stroke)
            if log is None or stroke is None or not r.compared or len(stroke.points) < 2:
                continue
            delta = 0.02 / stroke.workspace_scale
            samples = np.array(stroke.points)
            applied, rejected = (np.array(log[key]).reshape(-1, 3) for key in ("applied", "rejected"))
            mine = [c for c in r.constraints if c.kind.name in POS]
            n += 1
            theirs += len(rejected) > 0
            far = [q for q in rejected if all(np.linalg.norm(q - a) > 0.01 for a in applied)]
            theirs_far += bool(far)
            ours += any(not c.enforced for c in mine)
            ends = np.array(r.reference_curve.control_points)[[0, -1]]
            for q, verdict in [(q, "applied") for q in applied] + [(q, "rejected") for q in far]:
                if np.linalg.norm(normal) > 0 and abs(q @ normal - offset) < 1e-4 \
                        and nearest_on_polyline(q, samples)[1] > 2.5 * delta:
                    far_plane += 1
                where = "end" if min(np.linalg.norm(q - e) for e in ends) < delta else "inside"
                near = [c for c in mine if np.linalg.norm(np.array(c.target) - q) < delta / 2]
                if not near:
                    what = "none there"
                else:
                    c = min(near, key=lambda c: np.linalg.norm(np.array(c.target) - q))
                    what = "enforced" if c.enforced else "rejected"
                group = "01" if session.startswith("01") else "02" if session.startswith("02") else "showcase"
                places[(group, verdict, where, what)] += 1
        print(session, n, theirs, theirs_far, ours, far_plane)
    print("\ngroup cassie where: ours enforced / rejected / none there")
    for group in ("01", "02", "showcase"):
        for verdict in ("applied", "rejected"):
            for where in ("end", "inside"):
                counts = [places[(group, verdict, where, w)] for w in ("enforced", "rejected", "none there")]
                if any(counts):
                    print(group, verdict, where, *counts)


if __name__ == "__main__":
    sessions, params = example_args.parse(sys.argv[1:], "logged")
    main(sessions, {"mirror": "plane", **params})
