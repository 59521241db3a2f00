"""Tests whether item 8's six correction points (CASSIE app, item 8: "6 points
on the old curve within ±δ/2 of the target") are spaced in the old curve's
parameter rather than in arclength (cassie README, "Target positions, traced").

Each session is run with CASSIE's selection (`oracle`, as in
trace_target_positions.py) twice: as is, and with `correction_points=0` (our
detected target). Every intersection CASSIE applied on a drawn stroke is paired
with the nearest target we enforce within δ/2; the old curve is CASSIE's
earlier curve nearest CASSIE's target (teacher-forced, it is also ours). Where
our correction moved our target, CASSIE's move from our detected target along
the old curve is expressed, per reading, in units of the candidates' half
span; a reading fits where the value lies on a candidate, ±0.2, ±0.6 or ±1:
  arclength            our spacing (moves of s = u·δ/2);
  t in [0,K], (δ/2)/L  parameter over the K Bézier segments, step from the length L;
  t in [0,1], (δ/2)/L  the same over [0,1];
  per segment, Lseg    the segment's own parameter and length;
  split, [0,K'] / [0,1]  the old curve first cut at the targets logged on it
                       by the strokes in between (K' pieces; de Casteljau keeps
                       the shape and rescales each piece's parameter).
It also prints, where ours moved the smallest step (0.1δ), CASSIE's move on
single-segment old curves (where every parameter reading is arclength up to the
Bézier's speed) and its correlation with K, L, Lseg and the speed.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/trace_correction_spacing.py \\
        [--param NAME=VALUE ...] [SESSION...]
"""
import collections
import os
import sys
import tempfile

import example_args
import numpy as np
import sketchlab as sl

from trace_geometry_residual import POS, kind
from trace_target_positions import DELTA, applied_targets, nearest_on_polyline, run

CANDIDATES = np.array([-1, -0.6, -0.2, 0.2, 0.6, 1])  # u of the six points, in units of δ/2
FITS = 0.03  # a value within this of a candidate (0.3 mm at δ = 2 cm) sits on it
PER_SEGMENT = 400  # parameter grid per Bézier segment


class Grid:
    """A curve sampled on a uniform parameter grid (t in [0, K]): parameter and arclength of a point on it."""

    def __init__(self, curve):
        self.k = curve.segment_count
        self.t = np.linspace(0, self.k, PER_SEGMENT * self.k + 1)
        self.p = np.array([curve.evaluate(t) for t in self.t])
        self.s = np.r_[0, np.cumsum(np.linalg.norm(np.diff(self.p, axis=0), axis=1))]

    def locate(self, q):
        """(parameter, arclength, distance) of the grid polyline's point nearest q."""
        _, d, _, s = nearest_on_polyline(q, self.p)
        return float(np.interp(s, self.s, self.t)), s, d

    def arclength(self, t0, t1):
        return float(np.interp(t1, self.t, self.s) - np.interp(t0, self.t, self.s))

    def speed(self, t):
        h = 1e-3
        a, b = max(t - h, 0.0), min(t + h, self.k)
        return self.arclength(a, b) / (b - a)


def trace_session(session, params, out):
    group = "showcase" if session[0].isalpha() else "study"
    rec = sl.read_recording(f"data/recordings/{session}.jsonl")
    logs = applied_targets(session)
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        for sid, targets in logs.items():
            f.write(str(sid) + "".join(f" {x!r}" for p in targets for x in p) + "\n")
    now = run(rec, f.name, params)
    detected = run(rec, f.name, {**params, "correction_points": 0})
    os.unlink(f.name)
    strokes = {e.stroke.id: e.stroke for e in rec.events if e.type == "stroke"}
    curves = {sid: r.reference_curve for sid, r in now.items() if r.compared}
    grids = {}
    grid = lambda s: grids.setdefault(s, Grid(curves[s]))
    order = list(now)
    for sid, r in now.items():
        if sid not in logs or not r.compared or sid not in detected:
            continue
        scale = strokes[sid].workspace_scale
        dl = DELTA / (scale if scale > 0 else 1.0)
        ours = [np.array(c.target) for c in r.constraints if kind(c) in POS and kind(c) != "mirror_plane" and c.enforced]
        dets = [np.array(c.target) for c in detected[sid].constraints if kind(c) in POS and kind(c) != "mirror_plane"]
        earlier = [s for s in order[:order.index(sid)] if s in curves and curves[s].segment_count > 0]
        if not ours or not dets or not earlier:
            continue
        for a in logs[sid]:
            o = min(ours, key=lambda p: np.linalg.norm(p - a))
            if np.linalg.norm(o - a) > dl / 2:
                continue
            old = min(earlier, key=lambda s: grid(s).locate(a)[2])
            g = grid(old)
            ta, sa, da = g.locate(a)
            if da > 2e-4:
                continue
            td, sd, _ = g.locate(min(dets, key=lambda p: np.linalg.norm(p - o)))
            s_ours = g.locate(o)[1] - sd
            if abs(s_ours) < 0.05 * dl:  # ours not corrected (an end of the old curve, item 8's exception)
                continue
            between = order[order.index(old) + 1:order.index(sid)]
            cuts = sorted({float(k) for k in range(g.k + 1)} |
                          {g.locate(q)[0] for s in between for q in logs.get(s, []) if g.locate(q)[2] < 1e-3})
            j = max(int(np.searchsorted(cuts, td, side="right")) - 1, 0)
            width = cuts[min(j + 1, len(cuts) - 1)] - cuts[j]
            seg = min(int(td), g.k - 1)
            length, half, dt = g.s[-1], dl / 2, ta - td
            out[group].append(dict(
                k=g.k, length=length, lseg=g.arclength(seg, seg + 1), speed=g.speed(td), s_ours=s_ours / dl,
                s_cassie=(sa - sd) / dl,
                readings={
                    "arclength": (sa - sd) / half,
                    "t in [0,K], (δ/2)/L": dt / (half / length),
                    "t in [0,1], (δ/2)/L": dt / g.k / (half / length),
                    "per segment, Lseg": dt / (half / g.arclength(seg, seg + 1)),
                    "split, [0,K']": dt / width / (half / length),
                    "split, [0,1]": dt / width / (len(cuts) - 1) / (half / length),
                }))


def report(out):
    chance = len(CANDIDATES) * 2 * FITS / 2.4  # a value uniform over ±1.2
    for group, rows in sorted(out.items()):
        moved = [r for r in rows if abs(r["s_cassie"]) > 0.005]
        print(f"{group}: {len(rows)} intersections our item 8 moved; CASSIE's at our detected target at "
              f"{len(rows) - len(moved)}; on a candidate (within {FITS} of ±0.2, ±0.6, ±1; chance {chance * 100:.0f} %):")
        for name in moved[0]["readings"] if moved else []:
            v = np.array([r["readings"][name] for r in moved])
            on = np.min(np.abs(v[:, None] - CANDIDATES[None, :]), axis=1) < FITS
            print(f"  {name:22s} {on.mean() * 100:5.1f} %")
        small = [r for r in moved if abs(abs(r["s_ours"]) - 0.1) < 0.01]
        for label, keep in (("single-segment old curve", lambda r: r["k"] == 1), ("K ≥ 2", lambda r: r["k"] >= 2)):
            sub = [r for r in small if keep(r)]
            if sub:
                c = np.array([abs(r["s_cassie"]) for r in sub])
                sp = np.median([r["speed"] * r["k"] / r["length"] for r in sub])
                print(f"  ours 0.1δ, {label}: CASSIE's moved a median {np.median(c):.3f}δ, under 0.05δ at "
                      f"{(c < 0.05).sum()} of {len(c)} (speed·K/L median {sp:.2f})")
        c = np.array([abs(r["s_cassie"]) for r in moved])
        rank = lambda x: np.argsort(np.argsort(x))
        print("  |CASSIE's move| against " + ", ".join(
            f"{k}: r {np.corrcoef(c, y)[0, 1]:+.2f} (ranks {np.corrcoef(rank(c), rank(y))[0, 1]:+.2f})"
            for k, y in ((k, np.array([r[k] for r in moved])) for k in ("k", "length", "lseg", "speed"))))


def main(argv):
    sessions, params = example_args.parse(argv)
    out = collections.defaultdict(list)
    for s in sessions:
        trace_session(s, params, out)
    report(out)


if __name__ == "__main__":
    main(sys.argv[1:])
