"""Traces the geometry left when the cassie corrector is given CASSIE's own
constraint selection (`sketchlab fidelity --cassie-subset`; cassie README,
"Selection and geometry").

For every drawn stroke with its own raw_data log (mirrored twins left out)
whose enforced position constraints match CASSIE's applied ones one to one
(each applied target within δ/2 of one we enforce, as many of each), it
compares our curve with CASSIE's: where along the curve they differ (the
first and last 10 % of the arclength against the rest), and which of our
rules or CASSIE's decisions differ on the stroke. Each stroke over 2 mm of
mean deviation gets the first cause that applies:
  CASSIE on a surface (item 20: its onSurface flag; no patches rebuilt here),
  planarity differs (item 14: CASSIE's planar flag against our soft term),
  mirror projection differs (item 18: one curve on the plane, the other not),
  our trim (item 16) or hook cut (item 3) changed the curve and undoing it
    brings ours nearer CASSIE's,
  the fit: the freehand corrector's fit of the same samples (no structuring)
    is itself over 2 mm from CASSIE's curve and within 2 mm of ours,
  the solve: the freehand fit is nearer CASSIE's (the constrained solve moved
    ours away), else other.

It also splits each group's deviation into shape and extent: the pointwise
distance of the arclength-resampled curves (the fidelity table's mean
deviation) against the mean distance of each curve to the other as a set
(shape only), by how many targets CASSIE applied (0, 1, 2 or more), and
says where the free ends lie: how far short of the raw stroke's end, along
it, CASSIE's free end and ours stop.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/trace_geometry_residual.py [--positions] \\
        [--param NAME=VALUE ...] [SESSION...]

--positions: also enforce at CASSIE's logged target positions (the
corrector's oracle_positions), so that only the curve differs.
--param: corrector parameters for a reading.
"""
import collections
import json
import os
import sys
import tempfile

import example_args
import numpy as np
import sketchlab as sl

BASE = {"mirror": "plane"}
MATCH = 0.01  # m, δ/2 at zoom 1 (oracle_radius)
GOAL = 0.002  # m
POS = {"coincident_point", "point_on_curve", "intersection", "grid_point", "mirror_plane"}


def read_logs(session):
    point = lambda q: [q["x"], q["y"], q["z"]]
    logs = {}
    for s in json.load(open(f"data/cassie/raw_data/{session}.json")).get("allSketchedStrokes", []):
        # Newer exports log {"position": …, flags}; older ones the bare point.
        targets = lambda key: [point(q["position"]) if "position" in q else point(q) for q in s.get(key) or []]
        logs[s["id"]] = {
            "applied": targets("appliedPositionConstraints"), "rejected": targets("rejectedPositionConstraints"),
            "planar": s.get("planar"), "onSurface": s.get("onSurface")}
    return logs


def kind(c):
    return str(c.kind).split(".")[-1]


def profile(r):
    """Pointwise distance of the two curves resampled by arclength (ours oriented like CASSIE's)."""
    ref = np.array(r.reference_curve.sample(40))
    out = np.array(r.output_curve.sample(40))
    if r.reversed:
        out = out[::-1]
    return np.linalg.norm(ref - out, axis=1)


def on_plane(curve, n, d):
    cp = np.array(curve.control_points)
    return n is not None and np.all(np.abs(cp @ n - d) < 1e-4)


def to_polyline(points, poly):
    """Distance from each point to the polyline."""
    a, b = poly[:-1], poly[1:]
    ab = b - a
    sq = np.maximum((ab ** 2).sum(1), 1e-30)
    out = []
    for p in points:
        t = np.clip(((p - a) * ab).sum(1) / sq, 0, 1)
        out.append(np.linalg.norm(a + t[:, None] * ab - p, axis=1).min())
    return np.array(out)


def short_of_end(raw, p, end):
    """Arclength from the raw stroke's end `end` (0 first, 1 last) to p's projection on it."""
    q = raw if end == 0 else raw[::-1]
    cum = np.r_[0, np.cumsum(np.linalg.norm(np.diff(q, axis=0), axis=1))]
    a, b = q[:-1], q[1:]
    ab = b - a
    sq = np.maximum((ab ** 2).sum(1), 1e-30)
    t = np.clip(((p - a) * ab).sum(1) / sq, 0, 1)
    i = np.argmin(np.linalg.norm(a + t[:, None] * ab - p, axis=1))
    return cum[i] + t[i] * np.sqrt(sq[i])


def matched(r, applied):
    ours = [np.array(c.target) for c in r.constraints if kind(c) in POS and c.enforced]
    if len(ours) != len(applied):
        return False
    return all(min((np.linalg.norm(np.array(a) - o) for o in ours), default=np.inf) <= MATCH for a in applied)


def main(sessions, positions, params):
    shape = collections.defaultdict(list)
    free_ends = collections.defaultdict(list)
    causes = {"study": collections.Counter(), "showcase": collections.Counter()}
    where = {"study": [], "showcase": []}
    devs = {"study": [], "showcase": []}
    counts = {"study": collections.Counter(), "showcase": collections.Counter()}
    for session in sessions:
        group = "showcase" if session[0].isalpha() else "study"
        rec = sl.read_recording(f"data/recordings/{session}.jsonl")
        logs = read_logs(session)
        ws = rec.header.workspace
        n = np.array(ws.mirror_normal) if ws.mirror_enabled or np.linalg.norm(ws.mirror_normal) > 0 else None
        d = ws.mirror_offset / np.linalg.norm(n) if n is not None else 0.0
        if n is not None:
            n = n / np.linalg.norm(n)
        with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
            for sid, log in logs.items():
                f.write(str(sid) + "".join(f" {x!r}" for p in log["applied"] for x in p) + "\n")
            oracle = f.name
        raw = {e.stroke.id: np.array(e.stroke.points) for e in rec.events if e.type == "stroke"}
        base = {**BASE, **params, "oracle": oracle, "oracle_positions": positions}
        run = lambda extra: {r.stroke: r for r in sl.teacher_forced(rec, sl.corrector("cassie", {**base, **extra}))}
        now = run({})
        untrimmed = run({"trim_dangling": False})
        unhooked = run({"remove_hooks": False})
        fit = {r.stroke: r for r in sl.teacher_forced(rec, sl.corrector("freehand"))}
        os.unlink(oracle)
        for sid, r in now.items():
            log = logs.get(sid)
            if log is None or not r.compared:
                continue
            counts[group]["logged"] += 1
            if not matched(r, log["applied"]):
                continue
            counts[group]["same enforced set"] += 1
            if r.reference_line or r.output_line:
                counts[group]["lines"] += 1
                continue
            counts[group]["Beziers"] += 1
            devs[group].append(r.mean_deviation)
            ref, out = np.array(r.reference_curve.sample(60)), np.array(r.output_curve.sample(60))
            shape[(group, min(len(log["applied"]), 2))].append(
                (r.mean_deviation, 0.5 * (to_polyline(ref, out).mean() + to_polyline(out, ref).mean())))
            for k in range(2):
                if r.reference_snap[k] or r.output_snap[k]:
                    continue
                ours = out[0] if (k == 0) != r.reversed else out[-1]
                cassie = ref[0] if k == 0 else ref[-1]
                end = 0 if np.linalg.norm(cassie - raw[sid][0]) < np.linalg.norm(cassie - raw[sid][-1]) else 1
                free_ends[(group, "first" if end == 0 else "last")].append(
                    (short_of_end(raw[sid], cassie, end), short_of_end(raw[sid], ours, end)))
            p = profile(r)
            ends, middle = np.r_[p[:4], p[-4:]].mean(), p[4:-4].mean()
            where[group].append((ends, middle))
            if r.mean_deviation <= GOAL:
                causes[group]["within 2 mm"] += 1
                continue
            ours_planar = any(kind(c) in ("planar", "axis_plane") for c in r.constraints)
            fr = fit.get(sid)
            fit_dev = fr.mean_deviation if fr is not None and fr.compared else np.inf
            fit_ours = np.abs(np.array(fr.output_curve.sample(40)) - np.array(r.output_curve.sample(40))[::(-1 if r.reversed != fr.reversed else 1)]).max() if fr is not None and fr.compared else np.inf
            closer = lambda alt: alt.get(sid) is not None and alt[sid].compared and \
                len(alt[sid].output_curve.control_points) != len(r.output_curve.control_points) and \
                alt[sid].mean_deviation < r.mean_deviation
            if log["onSurface"]:
                cause = "CASSIE projected it onto a surface (item 20)"
            elif log["planar"] is not None and bool(log["planar"]) != ours_planar:
                cause = "planarity differs (item 14): " + ("CASSIE planar, we not" if log["planar"] else "we planar, CASSIE not")
            elif n is not None and on_plane(r.reference_curve, n, d) != on_plane(r.output_curve, n, d):
                cause = "mirror projection differs (item 18)"
            elif closer(untrimmed):
                cause = "our trim (item 16)"
            elif closer(unhooked):
                cause = "our hook cut (item 3)"
            elif fit_dev > GOAL and fit_ours <= GOAL:
                cause = "the fit: the freehand fit is as far from CASSIE's"
            elif fit_dev < r.mean_deviation:
                cause = "the solve: the freehand fit is nearer CASSIE's"
            else:
                cause = "other (ours nearer CASSIE's than the plain fit)"
            causes[group][cause + (", both planar" if ours_planar and log["planar"] else "")] += 1
    for g in ("study", "showcase"):
        if not devs[g]:
            continue
        w = np.array(where[g]) * 1000
        print(f"{g}: {dict(counts[g])}")
        print(f"  mean deviation of the matched Béziers, median / p90: {np.median(devs[g]) * 1000:.2f} / "
              f"{np.percentile(devs[g], 90) * 1000:.2f} mm")
        print(f"  pointwise distance, first and last 10 %: median {np.median(w[:, 0]):.2f} mm; interior: "
              f"median {np.median(w[:, 1]):.2f} mm; ends larger at {np.mean(w[:, 0] > w[:, 1]) * 100:.0f} %")
        for cause, k in causes[g].most_common():
            print(f"  {k:5d}  {cause}")
        for k in range(3):
            a = np.array(shape.get((g, k), [(np.nan, np.nan)])) * 1000
            print(f"  {'0 1 2+'.split()[k]:>2} applied ({len(shape.get((g, k), []))}): mean deviation median {np.nanmedian(a[:, 0]):.2f} mm, "
                  f"shape only {np.nanmedian(a[:, 1]):.2f} mm")
        for end in ("first", "last"):
            a = np.array(free_ends.get((g, end), [(np.nan, np.nan)])) * 1000
            print(f"  free {end} ends ({len(free_ends.get((g, end), []))}): short of the raw end, median / p75: CASSIE "
                  f"{np.nanmedian(a[:, 0]):.1f} / {np.nanpercentile(a[:, 0], 75):.1f} mm, ours "
                  f"{np.nanmedian(a[:, 1]):.1f} / {np.nanpercentile(a[:, 1], 75):.1f} mm")


if __name__ == "__main__":
    sessions, params = example_args.parse([a for a in sys.argv[1:] if a != "--positions"])
    main(sessions, "--positions" in sys.argv[1:], params)
