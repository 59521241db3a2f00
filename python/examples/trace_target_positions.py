"""Traces where the cassie corrector puts its position targets against the
targets CASSIE logged as applied (cassie README, "Selection and geometry",
"Target positions, traced").

Each session is run with CASSIE's own selection (the corrector's `oracle`
parameter, as `sketchlab fidelity --cassie-subset`); every target CASSIE
applied on a drawn stroke with its own raw_data log (mirrored twins left
out) is paired with the nearest target we enforce within δ/2. Per group
(study, showcase) and kind it prints:
  mirror-plane targets (items 6, 18): the offset, its components along the
    stroke's direction in the plane and across it, and which event of the
    brush along the exported samples each target sits at (the stroke
    starting within δ of the plane, entering that slab, leaving it), for
    CASSIE's and ours;
  intersections over 1 mm off (items 7, 8): along CASSIE's old curve against
    across it, and how item 8's correction (6 points within ±δ/2, nearest
    the new fit) placed ours and CASSIE's relative to our detected target
    (the run with `correction_points=0`); item 7's merge (`merge=0
    plane_merge=0`).

    PYTHONPATH=build/python /usr/bin/python3 python/examples/trace_target_positions.py [--param K=V ...] [SESSION...]

--param: corrector parameters for a reading (e.g. correction_keeps_target=true);
the offsets then show how near that reading puts the targets.
"""
import collections
import json
import os
import sys
import tempfile

import example_args
import numpy as np
import sketchlab as sl

from trace_geometry_residual import POS, kind

DELTA = 0.02  # m at zoom 1
BIG = 0.001  # m: intersections traced in detail
STILL = 0.005  # ×δ: a target within this of our detected one did not move


def applied_targets(session):
    point = lambda q: np.array([q["x"], q["y"], q["z"]])
    return {s["id"]: [point(q.get("position", q)) for q in s.get("appliedPositionConstraints", [])]
            for s in json.load(open(f"data/cassie/raw_data/{session}.json")).get("allSketchedStrokes", [])}


def nearest_on_polyline(p, poly, measure=None):
    """(point, distance, unit direction of the segment, arclength) of the polyline's point nearest p; the
    arclength along `measure` (a polyline with as many vertices, e.g. the unprojected samples), else along poly."""
    a, b = poly[:-1], poly[1:]
    ab = b - a
    sq = np.maximum((ab ** 2).sum(1), 1e-30)
    t = np.clip(((p - a) * ab).sum(1) / sq, 0, 1)
    q = a + t[:, None] * ab
    d = np.linalg.norm(q - p, axis=1)
    i = int(np.argmin(d))
    edges = np.linalg.norm(np.diff(poly if measure is None else measure, axis=0), axis=1)
    return q[i], d[i], ab[i] / np.sqrt(sq[i]), edges[:i].sum() + t[i] * edges[i]


def slab_events(raw, normal, offset, radius):
    """Arclengths along the samples where the brush starts within `radius` of the plane, enters or leaves that slab."""
    side = np.abs(raw @ normal - offset)
    cum = np.r_[0, np.cumsum(np.linalg.norm(np.diff(raw, axis=0), axis=1))]
    events = [("start", 0.0)] if side[0] <= radius else []
    for m in range(len(raw) - 1):
        s0, s1 = side[m], side[m + 1]
        if s0 > radius >= s1:
            events.append(("entry", cum[m] + (s0 - radius) / (s0 - s1) * (cum[m + 1] - cum[m])))
        elif s0 <= radius < s1:
            events.append(("exit", cum[m] + (radius - s0) / (s1 - s0) * (cum[m + 1] - cum[m])))
    return events


def run(rec, oracle, params):
    return {r.stroke: r for r in sl.teacher_forced(rec, sl.corrector("cassie", {"mirror": "plane", "oracle": oracle, **params}))}


def trace_session(session, params, out):
    group = "showcase" if session[0].isalpha() else "study"
    rec = sl.read_recording(f"data/recordings/{session}.jsonl")
    logs = applied_targets(session)
    ws = rec.header.workspace
    n = np.array(ws.mirror_normal, float)
    plane = (n / np.linalg.norm(n), ws.mirror_offset / np.linalg.norm(n)) if np.linalg.norm(n) > 0 else None
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        for sid, targets in logs.items():
            f.write(str(sid) + "".join(f" {x!r}" for p in targets for x in p) + "\n")
    now = run(rec, f.name, params)
    detected = run(rec, f.name, {**params, "correction_points": 0})
    unmerged = run(rec, f.name, {**params, "correction_points": 0, "merge": 0, "plane_merge": 0, "oracle_radius": 1})
    os.unlink(f.name)
    strokes = {e.stroke.id: e.stroke for e in rec.events if e.type == "stroke"}
    cassie_curves = {sid: np.array(r.reference_curve.sample(400)) for sid, r in now.items() if r.compared}
    earlier = list(now)
    targets = lambda res, sid, enforced: [(np.array(c.target), kind(c)) for c in res[sid].constraints
                                          if kind(c) in POS and (c.enforced or not enforced)] if sid in res else []
    for sid, r in now.items():
        if sid not in logs or not r.compared:
            continue
        stroke = strokes[sid]
        dl = DELTA / (stroke.workspace_scale if stroke.workspace_scale > 0 else 1.0)
        raw = np.array(stroke.points)
        ours = targets(now, sid, True)
        for a in logs[sid]:
            d = [np.linalg.norm(o - a) for o, _ in ours]
            if not d or min(d) > dl / 2:
                continue
            o, k = ours[int(np.argmin(d))]
            off = min(d)
            if k == "mirror_plane" and plane is not None:
                normal, offset = plane
                _, _, direction, _ = nearest_on_polyline(a, raw)
                along = direction - (direction @ normal) * normal
                along /= max(np.linalg.norm(along), 1e-12)
                projected = raw - np.outer(raw @ normal - offset, normal)
                events = slab_events(raw, normal, offset, dl)
                at = lambda p: min(events, key=lambda e: abs(e[1] - nearest_on_polyline(p, projected, raw)[3]))[0] if events else "none"
                out[(group, "plane")].append(dict(off=off, along=(o - a) @ along, across=(o - a) @ np.cross(normal, along),
                                                  cassie_at=at(a), ours_at=at(o)))
                continue
            row = dict(off=off)
            det = [p for p, _ in targets(detected, sid, False)]
            if det:
                row["detected_off"] = min(np.linalg.norm(p - a) for p in det)
            row["unmerged_off"] = min((np.linalg.norm(p - a) for p, _ in targets(unmerged, sid, False)), default=np.inf)
            if off > BIG and det:
                old = min((nearest_on_polyline(a, cassie_curves[s]) for s in earlier[:earlier.index(sid)] if s in cassie_curves),
                          key=lambda h: h[1], default=None)
                if old is not None:
                    t = old[2]
                    v = o - a
                    row["along"], row["across"] = abs(v @ t), np.linalg.norm(v - (v @ t) * t)
                    base = min(det, key=lambda p: np.linalg.norm(p - o))
                    row["cassie_moved"], row["ours_moved"] = (a - base) @ t / dl, (o - base) @ t / dl
            out[(group, "intersection")].append(row)


def item8_case(c, o):
    if abs(o) <= STILL and abs(c) <= STILL:
        return "neither moved (the detected targets differ across the old curve)"
    if abs(o) <= STILL:
        return "ours not moved, CASSIE's elsewhere along the old curve"
    if abs(c) <= STILL:
        return "CASSIE's at our detected target, our item 8 moved ours"
    if np.sign(c) != np.sign(o):
        return "both moved, to opposite sides (the two fits cross the old curve apart)"
    if abs(c) < abs(o):
        return "both moved, same side, CASSIE's less" + (" (ours the smallest step, 0.1δ)" if abs(abs(o) - 0.1) < 0.01 else "")
    return "both moved, same side, CASSIE's more"


def report(out):
    mm = lambda xs: np.array(xs) * 1000
    for (group, k), rows in sorted(out.items()):
        off = mm([r["off"] for r in rows])
        print(f"{group} {k}: {len(rows)} pairs, offset median {np.median(off):.2f} / p75 {np.percentile(off, 75):.2f} mm, "
              f"under 0.01 mm {np.mean(off < 0.01) * 100:.0f} %, under 2 mm {np.mean(off < 2) * 100:.0f} %")
        if k == "plane":
            al, ac = mm([r["along"] for r in rows]), mm([r["across"] for r in rows])
            print(f"  along the stroke (ours − CASSIE's): median {np.median(al):.2f} mm, |.| {np.median(np.abs(al)):.2f} mm, "
                  f"ours further along at {np.mean(al > 0) * 100:.0f} %; across |.| {np.median(np.abs(ac)):.2f} mm")
            events = collections.Counter((r["cassie_at"], r["ours_at"]) for r in rows)
            for (c, o), count in events.most_common():
                sub = mm([r["off"] for r in rows if (r["cassie_at"], r["ours_at"]) == (c, o)])
                print(f"  {count:5d}  CASSIE's at the slab's {c}, ours at its {o}: offset median {np.median(sub):.2f} mm")
            continue
        det = mm([r.get("detected_off", np.inf) for r in rows])
        print(f"  our detected target (no item 8): offset median {np.median(det):.2f} / p75 {np.percentile(det, 75):.2f} mm")
        big = [r for r in rows if "along" in r]
        if not big:
            continue
        al, ac = mm([r["along"] for r in big]), mm([r["across"] for r in big])
        bd, bo = mm([r["detected_off"] for r in big]), mm([r["off"] for r in big])
        print(f"  over 1 mm off ({len(big)}): along the old curve median {np.median(al):.2f} mm, across {np.median(ac):.2f} mm, "
              f"along > across at {np.mean(al > ac) * 100:.0f} %")
        print(f"    our detected one nearer CASSIE's than our corrected one at {np.mean(bd < bo) * 100:.0f} % "
              f"(median {np.median(bd):.2f} mm); within 0.1 mm: detected {np.mean(bd < 0.1) * 100:.0f} %, "
              f"any unmerged one {np.mean(mm([r['unmerged_off'] for r in big]) < 0.1) * 100:.0f} %")
        for case, count in collections.Counter(item8_case(r["cassie_moved"], r["ours_moved"]) for r in big).most_common():
            print(f"    {count:5d}  {case}")
        small = [r for r in big if abs(abs(r["ours_moved"]) - 0.1) < 0.01]
        if small:
            print(f"    where ours moved 0.1δ, CASSIE's moved a median {np.median([abs(r['cassie_moved']) for r in small]):.3f}δ")


def main(argv):
    sessions, params = example_args.parse(argv)
    out = collections.defaultdict(list)
    for s in sessions:
        trace_session(s, params, out)
    report(out)


if __name__ == "__main__":
    main(sys.argv[1:])
