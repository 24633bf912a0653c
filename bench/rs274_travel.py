#!/usr/bin/env python3
"""XY rapid travel of a drilling program as LinuxCNC's own interpreter runs it:
rs274 -g prints canonical moves; the XY length of every STRAIGHT_TRAVERSE,
from X0 Y0, in mm. Usage: rs274_travel.py PROGRAM"""
import math
import os
import re
import subprocess
import sys
import tempfile

text = open(sys.argv[1], encoding="utf-8", errors="replace").read()
scale = 25.4 if re.search(r"\bG20\b", text) else 1.0
tools = sorted({int(t) for t in re.findall(r"\bT(\d+)", text)})
with tempfile.TemporaryDirectory() as d:
    with open(os.path.join(d, "tool.tbl"), "w") as f:
        for t in tools:
            f.write(f"T{t} P{t} Z0 D1\n")
    # HOME of its own: LinuxCNC 2.9 shares $HOME/.tool.mmap between every rs274 of the user.
    canon = subprocess.run(["rs274", "-t", "tool.tbl", "-g", os.path.abspath(sys.argv[1])], cwd=d,
                           env=dict(os.environ, HOME=d), capture_output=True, text=True).stdout
x = y = 0.0
travel = 0.0
for m in re.finditer(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED)\(([^)]*)\)", canon):
    v = [float(a) * scale for a in m.group(2).split(",")[:2]]
    if m.group(1) == "STRAIGHT_TRAVERSE":
        travel += math.hypot(v[0] - x, v[1] - y)
    x, y = v
print(f"{travel:.3f}")
