#!/usr/bin/python3
"""Issue 71: DXF files whose holes are drawn without a CIRCLE, written with
ezdxf (Debian python3-ezdxf) as the CADs named write them, and the holes an
independent reading finds, also by ezdxf:

- NAME.holes.csv: the CIRCLEs (what acodrill reads without --round-contours);
- NAME.round.csv: the CIRCLEs and every closed contour that is round: each
  entity (INSERTs exploded by ezdxf's virtual_entities) flattened into points
  on it by ezdxf.path, open pieces joined end to end, a least-squares circle
  fitted with numpy; round when every point and every chord's middle is
  within 2.5 % of the radius of it; the hole at the fitted centre with twice
  the points' mean distance from it. A contour on a CIRCLE is that CIRCLE.
The reader under test shares no code with this oracle.

    /usr/bin/python3 tests/data/make_round_contours.py tests/data/dxf-contours
"""
import math
import os
import sys

import ezdxf
import numpy as np
from ezdxf import path as ezpath

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_dxf_cases import UNIT_MM, holes_of, pin  # noqa: E402

TOLERANCE = 0.025


def pieces_of(entity, out):
    t = entity.dxftype()
    if t == "INSERT":
        for sub in entity.multi_insert() if entity.mcount > 1 else [entity]:
            for v in sub.virtual_entities():
                pieces_of(v, out)
        return
    if t not in ("LINE", "ARC", "LWPOLYLINE", "POLYLINE", "SPLINE", "ELLIPSE"):
        return
    p = ezpath.make_path(entity)
    pts = [(v.x, v.y) for v in p.flattening(distance=0.0005)]
    closed = (t == "LWPOLYLINE" and entity.closed) or (t == "POLYLINE" and entity.is_closed)
    if t == "ARC" and abs((entity.dxf.end_angle - entity.dxf.start_angle) % 360) < 1e-9:
        closed = True
    if len(pts) >= 2 and math.dist(pts[0], pts[-1]) < 1e-9:
        pts.pop()
        closed = True
    out.append((pts, closed, t, entity.dxf.layer))


def loops_of(pieces):
    loops = [(pts, {t}, layer) for pts, closed, t, layer in pieces if closed]
    open_pieces = [(pts, t, layer) for pts, closed, t, layer in pieces if not closed]
    used = [False] * len(open_pieces)
    for i, (pts, t, layer) in enumerate(open_pieces):
        if used[i]:
            continue
        used[i] = True
        chain, kinds = list(pts), {t}
        while math.dist(chain[0], chain[-1]) > 1e-7:
            nxt = [j for j, (q, _, _) in enumerate(open_pieces) if not used[j] and
                   (math.dist(q[0], chain[-1]) < 1e-7 or math.dist(q[-1], chain[-1]) < 1e-7)]
            if len(nxt) != 1:
                break
            j = nxt[0]
            used[j] = True
            q, tj, _ = open_pieces[j]
            chain += (q if math.dist(q[0], chain[-1]) < 1e-7 else q[::-1])[1:]
            kinds.add(tj)
        else:
            loops.append((chain[:-1], kinds, layer))
    return loops


def round_holes(doc):
    pieces = []
    for e in doc.modelspace():
        pieces_of(e, pieces)
    found = []
    for pts, kinds, layer in loops_of(pieces):
        a = np.array(pts)
        if len(a) < 3:
            continue
        m = a.mean(axis=0)
        u = a - m
        design = np.column_stack([u[:, 0], u[:, 1], np.ones(len(u))])
        sol, *_ = np.linalg.lstsq(design, -(u ** 2).sum(axis=1), rcond=None)
        c = m + np.array([-sol[0] / 2, -sol[1] / 2])
        r = np.linalg.norm(a - c, axis=1).mean()
        mids = (a + np.roll(a, -1, axis=0)) / 2
        dev = max(np.abs(np.linalg.norm(a - c, axis=1) - r).max(), np.abs(np.linalg.norm(mids - c, axis=1) - r).max())
        if dev > TOLERANCE * r:
            continue
        found.append((c[0], c[1], 2 * r, layer))
    return found


def save(doc, folder, name):
    path = os.path.join(folder, name + ".dxf")
    doc.saveas(path)
    pin(path)
    back = ezdxf.readfile(path)
    circles = holes_of(back)
    unit = UNIT_MM.get(back.header.get("$INSUNITS", 0), 1.0)
    contours = []
    for x, y, d, layer in round_holes(back):
        h = (x * unit, y * unit, d * unit, layer)
        if any(math.dist(h[:2], c[:2]) <= TOLERANCE * h[2] / 2 and abs(h[2] - c[2]) <= TOLERANCE * h[2] for c in circles):
            continue  # drawn on a CIRCLE: one hole
        contours.append(h)
    for suffix, rows in (("holes", circles), ("round", circles + contours)):
        with open(os.path.join(folder, f"{name}.{suffix}.csv"), "w") as f:
            f.write("x_mm,y_mm,diameter_mm,layer\n")
            for x, y, d, layer in rows:
                f.write(f"{x:.6f},{y:.6f},{d:.6f},{layer}\n")


def new(version="R2010", units=4):
    doc = ezdxf.new(version, setup=False)
    doc.header["$INSUNITS"] = units
    return doc


def polygon(center, r, n, phase=0.0):
    return [(center[0] + r * math.cos(phase + 2 * math.pi * k / n), center[1] + r * math.sin(phase + 2 * math.pi * k / n))
            for k in range(n)]


def add_line_loop(layout, pts, attribs=None):
    for a, b in zip(pts, pts[1:] + pts[:1]):
        layout.add_line(a, b, dxfattribs=attribs or {})


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "tests/data/dxf-contours"
    os.makedirs(folder, exist_ok=True)
    k = 4 / 3 * math.tan(math.pi / 8)  # a quarter circle as one cubic Bezier

    # Fusion 360: a circle projected from a body, four cubic SPLINEs; a rounded
    # square of splines and lines is no hole; a CIRCLE beside them.
    doc = new()
    msp = doc.modelspace()
    for cx, cy, r in ((20, 15, 2.5), (45, 15, 1.6), (70, 40, 4.0)):
        for q in range(4):
            a0 = q * math.pi / 2
            ca, sa, cb, sb = math.cos(a0), math.sin(a0), math.cos(a0 + math.pi / 2), math.sin(a0 + math.pi / 2)
            ctrl = [(cx + r * ca, cy + r * sa), (cx + r * (ca - k * sa), cy + r * (sa + k * ca)),
                    (cx + r * (cb + k * sb), cy + r * (sb - k * cb)), (cx + r * cb, cy + r * sb)]
            msp.add_open_spline(ctrl, degree=3, dxfattribs={"layer": "PROJECTED"})
    msp.add_circle((90, 10), 1.5)
    # A rounded square: four Bezier corners joined by lines.
    x0, y0, s, r = 100, 30, 20, 3
    corners = [((x0 + s - r, y0 + r), 0), ((x0 + s - r, y0 + s - r), 1), ((x0 + r, y0 + s - r), 2), ((x0 + r, y0 + r), 3)]
    for (cx, cy), q in corners:
        a0 = (q - 1) * math.pi / 2
        ca, sa, cb, sb = math.cos(a0), math.sin(a0), math.cos(a0 + math.pi / 2), math.sin(a0 + math.pi / 2)
        msp.add_open_spline([(cx + r * ca, cy + r * sa), (cx + r * (ca - k * sa), cy + r * (sa + k * ca)),
                             (cx + r * (cb + k * sb), cy + r * (sb - k * cb)), (cx + r * cb, cy + r * sb)], degree=3)
    msp.add_line((x0 + r, y0), (x0 + s - r, y0))
    msp.add_line((x0 + s, y0 + r), (x0 + s, y0 + s - r))
    msp.add_line((x0 + s - r, y0 + s), (x0 + r, y0 + s))
    msp.add_line((x0, y0 + s - r), (x0, y0 + r))
    save(doc, folder, "fusion360_spline_circles")

    # OpenSCAD's older exporter (R12): every hole a polygon of LINEs; a hexagon
    # (a nut) and a rectangle are no holes.
    doc = new("R12", units=0)
    msp = doc.modelspace()
    add_line_loop(msp, polygon((10, 10), 1.5, 30))
    add_line_loop(msp, polygon((30, 10), 4.0, 20, 0.1))
    add_line_loop(msp, polygon((50, 10), 3.0, 6))
    add_line_loop(msp, [(60, 0), (80, 0), (80, 15), (60, 15)])
    add_line_loop(msp, polygon((10, 40), 2.0, 16))
    save(doc, folder, "openscad_r12_line_polygons")

    # R12 POLYLINEs (VERTEX ... SEQEND): a closed 24-gon, a closed pair of bulged
    # vertices, and an open one that stays no hole; a loop of LINEs and ARCs
    # joined end to end: a 24-gon with every other edge an ARC on the circle.
    doc = new("R12", units=4)
    msp = doc.modelspace()
    msp.add_polyline2d(polygon((10, 10), 2.0, 24), close=True)
    bulged = msp.add_polyline2d([(30, 10), (34, 10)], close=True)
    for v in bulged.vertices:
        v.dxf.bulge = 1.0
    msp.add_polyline2d(polygon((50, 10), 2.0, 24)[:12])
    cx, cy, r = 70, 10, 3.0
    corners = polygon((cx, cy), r, 24)
    for k in range(24):
        a, b = corners[k], corners[(k + 1) % 24]
        if k % 2:
            msp.add_arc((cx, cy), r, math.degrees(2 * math.pi * k / 24), math.degrees(2 * math.pi * (k + 1) / 24))
        else:
            msp.add_line(a, b)
    save(doc, folder, "r12_polylines_and_line_arc_loops")

    # OpenSCAD's current exporter: closed LWPOLYLINE polygons.
    doc = new("R2010")
    msp = doc.modelspace()
    msp.add_lwpolyline(polygon((10, 10), 1.5, 30), close=True)
    msp.add_lwpolyline(polygon((25, 10), 2.5, 48), close=True)
    msp.add_lwpolyline([(40, 0), (50, 0), (50, 10), (40, 10)], close=True)
    msp.add_lwpolyline(polygon((60, 10), 3.0, 8), close=True)  # an octagon: 7.6 % off a circle
    save(doc, folder, "openscad_lwpolyline_polygons")

    # Inkscape: polygons of 32 LINEs (R12) and closed 37-vertex LWPOLYLINEs,
    # the first vertex repeated (R14), on a layer of their own.
    doc = new("R12", units=4)
    msp = doc.modelspace()
    for i, (x, y, r) in enumerate(((15, 15, 1.6), (35, 15, 1.6), (15, 35, 2.75), (35, 35, 2.75))):
        add_line_loop(msp, polygon((x, y), r, 32, 0.05 * i), {"layer": "HOLES"})
    msp.add_line((0, 0), (50, 0), dxfattribs={"layer": "OUTLINE"})
    msp.add_line((50, 0), (50, 50), dxfattribs={"layer": "OUTLINE"})
    msp.add_line((50, 50), (0, 50), dxfattribs={"layer": "OUTLINE"})
    msp.add_line((0, 50), (0, 0), dxfattribs={"layer": "OUTLINE"})
    save(doc, folder, "inkscape_r12_line_polygons")

    doc = new("R2000", units=4)
    msp = doc.modelspace()
    for x, y, r in ((15, 15, 1.6), (35, 15, 1.6), (25, 35, 3.2)):
        pts = polygon((x, y), r, 36)
        msp.add_lwpolyline(pts + pts[:1], close=True, dxfattribs={"layer": "HOLES"})
    save(doc, folder, "inkscape_r14_lwpolyline_polygons")

    # A circle as one LWPOLYLINE of two bulge-1 arcs, as two ARCs, as a
    # full-circle ARC, as a circular ELLIPSE; a flattened ELLIPSE and a
    # slot (two half ARCs joined by LINEs) are no holes.
    doc = new("R2010")
    msp = doc.modelspace()
    msp.add_lwpolyline([(10, 10, 0, 0, 1), (14, 10, 0, 0, 1)], format="xyseb", close=True)
    msp.add_arc((30, 12), 2.5, 0, 180)
    msp.add_arc((30, 12), 2.5, 180, 360)
    msp.add_arc((50, 12), 1.25, 30, 30 + 360)
    msp.add_ellipse((70, 12), major_axis=(3, 0), ratio=1.0)
    msp.add_ellipse((90, 12), major_axis=(3, 0), ratio=0.5)
    msp.add_arc((110, 12), 2, 90, 270)
    msp.add_line((110, 14), (120, 14))
    msp.add_arc((120, 12), 2, 270, 90)
    msp.add_line((120, 10), (110, 10))
    save(doc, folder, "arcs_bulges_ellipses")

    # In blocks, placed, scaled, rotated and mirrored; a non-uniform scale
    # makes an ellipse (no hole); a polygon drawn on a CIRCLE is that CIRCLE.
    doc = new("R2010")
    b = doc.blocks.new("BOSS")
    add_line_loop(b, polygon((0, 0), 1.0, 24))
    b.add_lwpolyline([(5, 0, 0, 0, 1), (7, 0, 0, 0, 1)], format="xyseb", close=True)
    msp = doc.modelspace()
    msp.add_blockref("BOSS", (20, 20), dxfattribs={"rotation": 30, "xscale": 2, "yscale": 2})
    msp.add_blockref("BOSS", (50, 20), dxfattribs={"xscale": -1.5, "yscale": 1.5})
    msp.add_blockref("BOSS", (80, 20), dxfattribs={"xscale": 2, "yscale": 1})
    msp.add_circle((10, 50), 2.0)
    add_line_loop(msp, polygon((10, 50), 2.0, 40))
    save(doc, folder, "blocks_and_drawn_twice")

    # Onshape: $INSUNITS 1 (inch) on a drawing made in mm.
    doc = new("R2013", units=1)
    msp = doc.modelspace()
    for x in (10, 60, 110, 160):
        for y in (10, 90):
            msp.add_circle((x, y), 2.6)
    save(doc, folder, "onshape_inch_header_mm_drawing")


if __name__ == "__main__":
    if os.environ.get("PYTHONHASHSEED") != "0":
        os.execve(sys.executable, [sys.executable] + sys.argv, {**os.environ, "PYTHONHASHSEED": "0"})
    main()
