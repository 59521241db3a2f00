#!/usr/bin/env bash
# The README's pictures, made by the viewer: `sketchlab vr` on the test
# OpenXR runtime with scripted input; the runtime reads the left eye back
# from the swapchain (`dump`); Python's zlib turns it into PNG.
# Usage (after a build): xvfb-run -a -s "-screen 0 1280x1024x24" viewers/openxr/doc/make_screenshots.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
build=${BUILD:-$root/build}
out=$root/viewers/openxr/doc
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export XR_RUNTIME_JSON=$build/tests/openxr_runtime/sketchlab_test_runtime.json

# Writes $tmp/NAME.txt (the script) and $tmp/NAME.frame (the frame dumped).
python3 - "$tmp" <<'PY'
import math, sys
tmp = sys.argv[1]
head_down = "head=0,1.5,0.6,-0.21644,0,0,0.97630"
menu = "left=-0.15,1.2,0.1"
opts = "option eye_size 640 480\noption fov 45 36\noption frame_ms 11.1\noption dump_dir %s\n" % tmp

class Script:
    def __init__(self, name, start):
        self.name, self.lines, self.frame = name, [opts, "frame 3 " + start + "\n"], 3
    def add(self, line, n=1):
        self.lines.append("frame %d %s\n" % (n, line))
        self.frame += n
    def stroke(self, points, rest=40):
        for p in points:
            self.add("right=%.4f,%.4f,%.4f right/input/trigger/value=0.8" % p)
        self.add("right/input/trigger/value=0 right=0.3,1.1,0.2", rest)
    def press(self, at):
        at = "right=%.4f,%.4f,%.4f" % at
        self.add(at)
        self.add(at + " right/input/trigger/value=0.9", 2)
        self.add(at + " right/input/trigger/value=0")
    def dump(self):
        open(tmp + "/" + self.name + ".frame", "w").write(str(self.frame))
        self.add("dump")
        open(tmp + "/" + self.name + ".txt", "w").write("".join(self.lines))

def line(a, b, n=20):
    return [tuple(a[i] + (b[i] - a[i]) * k / n for i in range(3)) for k in range(n + 1)]

# A box's scaffold and a curve over it, drawn in shape mode.
s = Script("stage", head_down + " " + menu + " right=0.05,1.3,0")
s.press((-0.15, 1.2 + 0.11 + 0.035 * 1.5, 0.1))  # "shape" (row 0, column 1)
c = [(-0.02, 1.25, -0.1), (0.18, 1.25, -0.1), (0.18, 1.25, -0.3), (-0.02, 1.25, -0.3)]
for i in range(4):
    s.stroke(line(c[i], c[(i + 1) % 4]))
for i in range(4):
    s.stroke(line(c[i], (c[i][0], 1.42, c[i][2])))
s.stroke([(0.08 + 0.1 * math.cos(math.pi * k / 30), 1.42 + 0.05 * math.sin(math.pi * k / 30), -0.1) for k in range(31)], 200)
s.add("right=0.1,1.32,0.15", 5)
s.dump()
# A snap: 12 frames after the second stroke's release.
s = Script("snap", "head=0,1.5,0.6 right=-0.15,1.4,0")
s.stroke(line((-0.15, 1.4, 0), (0.05, 1.4, 0)))
s.stroke(line((0.056, 1.404, 0), (0.056, 1.604, 0)), 12)
s.dump()
# Compare: a wobbly circle, then the menu's "compare" (row 3, column 0).
s = Script("compare", head_down + " " + menu + " right=0.05,1.3,0")
s.stroke([(0.08 + 0.06 * math.cos(2 * math.pi * k / 30) + 0.008 * math.sin(7 * k),
           1.3 + 0.06 * math.sin(2 * math.pi * k / 30), -0.05) for k in range(31)], 60)
s.press((-0.15 - 0.035, 1.2 + 0.11 - 0.035 * 1.5, 0.1))
s.add("right=0.3,1.1,0.2", 20)
s.dump()
PY
# shot NAME CONFIG FLAGS...
shot() {
  local name=$1 config=$2
  shift 2
  SKETCHLAB_XR_SCRIPT=$tmp/$name.txt "$build/bin/sketchlab" vr "$root/$config" -o "$tmp/$name.jsonl" --overwrite "$@" \
    >/dev/null
  python3 - "$tmp/frame$(cat "$tmp/$name.frame")_eye0.ppm" "$out/$name.png" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
magic, w, h, _max, pixels = data.split(maxsplit=4)
w, h = int(w), int(h)
rows = b"".join(b"\0" + pixels[3 * w * y:3 * w * (y + 1)] for y in range(h))
chunk = lambda kind, body: struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
png += chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
open(sys.argv[2], "wb").write(png)
PY
}
shot stage configs/stacks/cassie.yaml --grid 0.1
shot snap configs/stacks/cassie.yaml
shot compare configs/compare.yaml
echo "wrote $out/stage.png $out/snap.png $out/compare.png"
