"""Two stacks on the bundled CASSIE sessions, side by side (docs/python.md):
the freehand baseline and CASSIE, per session, one plot.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/compare_stacks.py out.png
"""
import glob
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import sketchlab as sl  # noqa: E402

root = os.path.join(os.path.dirname(__file__), "..", "..")
sessions = sorted(glob.glob(os.path.join(root, "data", "recordings", "0*.jsonl")))[:4]
stacks = [sl.stack("freehand"), sl.stack("cassie")]

rows = []
for path in sessions:
    rec = sl.read_recording(path)
    for st in stacks:
        m = sl.replay(rec, st).metrics()
        rows.append((os.path.basename(path), st.name, m["dangling_endpoint_ratio"]))

names = sorted({r[0] for r in rows})
x = np.arange(len(names))
for i, st in enumerate(stacks):
    y = [next(r[2] for r in rows if r[0] == n and r[1] == st.name) for n in names]
    plt.bar(x + 0.4 * i, y, width=0.4, label=st.name)
plt.xticks(x + 0.2, names, rotation=30)
plt.ylabel("dangling endpoint ratio (CASSIE §6.4.2)")
plt.legend()
plt.tight_layout()
plt.savefig(sys.argv[1] if len(sys.argv) > 1 else "compare.png", dpi=100)
for r in rows:
    print(*r)
