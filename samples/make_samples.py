#!/usr/bin/python3
"""Writes the sample parts with ezdxf (Debian python3-ezdxf), an independent DXF
writer, together with the hole list each one holds (NAME.holes.csv, mm), so the
reader is tested against a file it did not write.

Run with Debian's interpreter (the python3 first on PATH may not see ezdxf):
    /usr/bin/python3 samples/make_samples.py samples/

The thesis's parts (10" x 12" x 1/4" plates with 10, 27, 45, 65 and 70 holes of
1/4"; the 21-hole circular plate; 8" x 8" and 15" x 15" plates with 10, 21, 35
and 70 holes) are shown there only as pictures, so these are laid out like real
parts: bolt circles, grids, edge rows and flange patterns, drawn in inches.
"""
import math
import os
import random
import re
import sys

import ezdxf

IN = 25.4
QUARTER = 0.25  # inch


def bolt_circle(cx, cy, r, n, start_deg=0.0):
    return [(cx + r * math.cos(math.radians(start_deg + 360.0 * k / n)),
             cy + r * math.sin(math.radians(start_deg + 360.0 * k / n))) for k in range(n)]


def grid(x0, y0, dx, dy, nx, ny):
    return [(x0 + i * dx, y0 + j * dy) for j in range(ny) for i in range(nx)]


def edge_rows(w, h, margin, pitch):
    pts = []
    nx = int((w - 2 * margin) / pitch) + 1
    ny = int((h - 2 * margin) / pitch) + 1
    for i in range(nx):
        pts.append((margin + i * pitch, margin))
        pts.append((margin + i * pitch, h - margin))
    for j in range(1, ny - 1):
        pts.append((margin, margin + j * pitch))
        pts.append((w - margin, margin + j * pitch))
    return pts


def take(points, n, seed):
    """n points of a pattern, chosen reproducibly, keeping the pattern's look."""
    rng = random.Random(seed)
    pts = list(dict.fromkeys((round(x, 4), round(y, 4)) for x, y in points))
    if len(pts) < n:
        raise SystemExit(f"pattern has {len(pts)} points, {n} wanted")
    rng.shuffle(pts)
    return pts[:n]


def thesis_plate(n, seed):
    """10" x 12" plate (X 12, Y 10): a flange bolt circle, a bearing pattern, edge clamping holes, a grid."""
    w, h = 12.0, 10.0
    features = (bolt_circle(3.0, 5.0, 1.75, 8, 22.5)
                + bolt_circle(3.0, 5.0, 0.9, 4, 45)
                + bolt_circle(8.5, 6.5, 1.25, 6)
                + grid(7.0, 1.0, 0.75, 0.75, 6, 3)
                + edge_rows(w, h, 0.5, 1.5)
                + grid(9.5, 3.0, 0.6, 0.6, 3, 3))
    # Keep the symmetric features whole where the count allows, then fill.
    rng = random.Random(seed)
    pts = []
    for group in (bolt_circle(3.0, 5.0, 1.75, 8, 22.5), bolt_circle(8.5, 6.5, 1.25, 6),
                  bolt_circle(3.0, 5.0, 0.9, 4, 45), edge_rows(w, h, 0.5, 1.5),
                  grid(7.0, 1.0, 0.75, 0.75, 6, 3), grid(9.5, 3.0, 0.6, 0.6, 3, 3)):
        if len(pts) + len(group) <= n:
            pts += group
    rest = [p for p in features if p not in pts]
    rng.shuffle(rest)
    pts += rest[: n - len(pts)]
    if len(pts) < n:
        raise SystemExit("not enough features")
    rng.shuffle(pts)  # a CAD export lists holes in drawing order, not drilling order
    return w, h, [(x, y, QUARTER) for x, y in pts]


def circular21():
    """The 21-hole circular plate: 12 on the outer bolt circle, 8 inner, 1 centre."""
    pts = bolt_circle(4.0, 4.0, 3.25, 12, 15) + bolt_circle(4.0, 4.0, 1.75, 8, 0) + [(4.0, 4.0)]
    return 8.0, 8.0, [(x, y, QUARTER) for x, y in pts]


def square_plate(size, n, seed):
    """8" x 8" and 15" x 15" plates of the machining comparisons."""
    c = size / 2
    features = (bolt_circle(c, c, size * 0.3, 12, 15)
                + bolt_circle(c, c, size * 0.15, 6)
                + edge_rows(size, size, 0.5, size / 8)
                + grid(c - size * 0.1, c - size * 0.1, size * 0.1, size * 0.1, 3, 3)
                + bolt_circle(size * 0.2, size * 0.8, size * 0.08, 5)
                + bolt_circle(size * 0.8, size * 0.2, size * 0.08, 5)
                + grid(size * 0.62, size * 0.62, size * 0.06, size * 0.06, 4, 4)
                + grid(size * 0.1, size * 0.1, size * 0.06, size * 0.06, 4, 3))
    pts = take(features, n, seed)
    return size, size, [(x, y, QUARTER) for x, y in pts]


def pcb_board():
    """A small multi-diameter board in mm: DIP rows, headers, vias, mounting holes."""
    holes = []
    for k, (x0, y0) in enumerate([(10, 10), (35, 10), (10, 30)]):  # three DIP-14
        for i in range(7):
            holes.append((x0 + i * 2.54, y0, 0.8))
            holes.append((x0 + i * 2.54, y0 + 7.62, 0.8))
    for i in range(10):  # a 2x10 header
        holes.append((40 + i * 2.54, 32, 1.0))
        holes.append((40 + i * 2.54, 34.54, 1.0))
    rng = random.Random(42)
    for _ in range(40):  # vias
        holes.append((round(rng.uniform(5, 75), 3), round(rng.uniform(5, 45), 3), 0.4))
    for x, y in [(3.5, 3.5), (76.5, 3.5), (3.5, 46.5), (76.5, 46.5)]:  # mounting
        holes.append((x, y, 3.2))
    return 80.0, 50.0, holes


def write(folder, name, w, h, holes, inches):
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 1 if inches else 4
    doc.layers.add("OUTLINE")
    doc.layers.add("HOLES")
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (w, 0), (w, h), (0, h)], close=True, dxfattribs={"layer": "OUTLINE"})
    for x, y, d in holes:
        msp.add_circle((x, y), d / 2, dxfattribs={"layer": "HOLES"})
    # Fixed dates and GUIDs, so regenerating changes no byte that matters.
    doc.header["$TDCREATE"] = 2460000.5
    doc.header["$FINGERPRINTGUID"] = "{00000000-0000-0000-0000-000000000001}"
    doc.header["$VERSIONGUID"] = "{00000000-0000-0000-0000-000000000002}"
    path = os.path.join(folder, name + ".dxf")
    doc.saveas(path)
    # ezdxf stamps a fresh $VERSIONGUID and a save time on every save; pin them.
    with open(path) as f:
        text = f.read()
    text = re.sub(r"(\$VERSIONGUID\n  2\n)\{[0-9A-F-]+\}", r"\1{00000000-0000-0000-0000-000000000002}", text)
    text = re.sub(r"(\$TDUPDATE\n 40\n)[0-9.]+", r"\g<1>2460000.5", text)
    text = re.sub(r"(\d+\.\d+\.\d+) @ \d{4}-\d\d-\d\dT[0-9:.+]+", r"\1 @ 2024-01-01T00:00:00+00:00", text)
    with open(path, "w") as f:
        f.write(text)
    scale = IN if inches else 1.0
    with open(os.path.join(folder, name + ".holes.csv"), "w") as f:
        f.write("x_mm,y_mm,diameter_mm,layer\n")
        for x, y, d in holes:
            f.write(f"{x * scale:.6f},{y * scale:.6f},{d * scale:.6f},HOLES\n")


def write_xml(folder, name, holes):
    """The thesis's XML hole map (see README, "Input formats"), in inches."""
    with open(os.path.join(folder, name + ".xml"), "w") as f:
        f.write(f'<?xml version="1.0" encoding="UTF-8"?>\n<holemap units="inch" name="{name.upper()}">\n')
        for x, y, d in holes:
            f.write(f'  <hole x="{x:.4f}" y="{y:.4f}" diameter="{d:.4f}"/>\n')
        f.write("</holemap>\n")


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for exp, n in enumerate([10, 27, 45, 65, 70], start=1):
        w, h, holes = thesis_plate(n, seed=exp)
        write(folder, f"plate{n}", w, h, holes, inches=True)
    w, h, holes = circular21()
    write(folder, "circular21", w, h, holes, inches=True)
    write_xml(folder, "circular21", holes)
    for size in (8, 15):
        for n in (10, 21, 35, 70):
            w, h, holes = square_plate(float(size), n, seed=size * 100 + n)
            write(folder, f"square{size}_{n}", w, h, holes, inches=True)
    w, h, holes = pcb_board()
    write(folder, "pcb_mixed", w, h, holes, inches=False)


if __name__ == "__main__":
    # ezdxf orders some objects through Python's salted string hash: fix the salt
    # so that every run writes the same bytes.
    if os.environ.get("PYTHONHASHSEED") != "0":
        os.execve(sys.executable, [sys.executable] + sys.argv, {**os.environ, "PYTHONHASHSEED": "0"})
    main()
