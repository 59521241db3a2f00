"""Traces the ends CASSIE snapped to a node where we snapped to a curve (the
`sketchlab fidelity --causes` row "both snapped: CASSIE node, we curve";
cassie README, "Node vs curve") and says why item 8's node snap did not
fire in ours: CASSIE's node has one incidence in the rebuilt sketch, lies
beyond the snap radius (δ/s at zoom s) of our target, is not on the curve we
crossed, or has another node of that curve between it and our target.

The cassie corrector runs inside a Python corrector that keeps, per stroke,
the nodes of the sketch it was corrected on (the rebuilt network).

    PYTHONPATH=build/python /usr/bin/python3 python/examples/trace_node_vs_curve.py \\
        [--param NAME=VALUE ...] [SESSION...]
"""
import collections
import json
import sys

import example_args
import numpy as np
import sketchlab as sl

DELTA = 0.02  # m at zoom 1
SEEN = sl.__dict__.setdefault("_trace_node_vs_curve", {})  # shared with the corrector's module copy


class KeepNodes:
    """The cassie corrector, keeping the nodes on the curves its constraints reference."""

    def __init__(self, params="{}"):
        self.inner = sl.corrector("cassie", {"mirror": "plane", **json.loads(params)})

    def correct(self, stroke, sketch):
        c = self.inner.correct(stroke, sketch)
        crossed = {r.id for k in c.constraints for r in k.references if r.kind == sl.RefKind.curve}
        nodes = {}
        for nid, n in sketch.network.nodes.items():
            inc = [(i.curve, i.t) for i in n.incidences]
            if any(cid in crossed for cid, _ in inc):
                nodes[nid] = (np.array(n.position), inc)
        SEEN[stroke.id] = (nodes, DELTA / stroke.workspace_scale)
        return c


def our_target(row, end):
    """(curve id, parameter, position) of the enforced curve constraint at our end."""
    for c in row.constraints:
        refs = [r for r in c.references if r.kind == sl.RefKind.curve]
        if c.enforced and refs and np.linalg.norm(np.array(c.target) - end) < 1e-4:
            return refs[0].id, refs[0].parameter, np.array(c.target)
    return None


def why(nodes, node, target, delta):
    pos, inc = nodes[node]
    curve, t, at = target
    on = [tn for cid, tn in inc if cid == curve]
    if not on:
        return "node not on the crossed curve"
    if len(inc) < 2:
        return "node of one incidence"
    between = [n for n, (_, i) in nodes.items() if n != node
               and any(cid == curve and min(t, on[0]) < tn < max(t, on[0]) for cid, tn in i)]
    if between:
        return "another node between"
    if np.linalg.norm(pos - at) > delta:
        return "node beyond δ of our target"
    return "node within δ of our final target (not of the detected one)"


def main(sessions, params):
    corrector = sl.corrector("python", {"module": __file__, "class": "KeepNodes",
                                        "params": json.dumps({"params": json.dumps(params)})})
    counts = collections.Counter()
    for session in sessions:
        SEEN.clear()
        for row in sl.teacher_forced(sl.read_recording(f"data/recordings/{session}.jsonl"), corrector):
            if not row.compared or row.stroke not in SEEN:
                continue
            nodes, delta = SEEN[row.stroke]
            for k in range(2):
                if row.reference_snap[k] != "node" or row.output_snap[k] != "curve":
                    continue
                cassie_end, our_end = row.reference_end[k], row.output_end[k]
                node = next((n for n, (p, _) in nodes.items() if np.linalg.norm(p - cassie_end) < 1e-4), None)
                target = our_target(row, our_end)
                if node is None or target is None:
                    cause = "CASSIE's node not on a curve we crossed" if node is None else "no enforced curve target"
                    counts[cause] += 1
                    continue
                cause = why(nodes, node, target, delta)
                counts[cause] += 1
                print(f"{session} {row.stroke}/{k}: {cause}; our target "
                      f"{np.linalg.norm(nodes[node][0] - target[2]) / delta:.2f}δ from CASSIE's node "
                      f"({len(nodes[node][1])} incidences)")
    for cause, n in counts.most_common():
        print(f"{n:4d} {cause}")


if __name__ == "__main__":
    main(*example_args.parse(sys.argv[1:]))
