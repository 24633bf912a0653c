#!/usr/bin/python3
"""Writes one DXF per reader feature with ezdxf (Debian python3-ezdxf), and
the holes each holds as NAME.holes.csv, computed by ezdxf itself: model-space
circles, INSERTs exploded with ezdxf's virtual_entities() (which applies base
point, scale, rotation, mirroring, MINSERT arrays and OCS), circles that
become ellipses dropped, $INSUNITS applied, exact duplicates removed. The
reader under test shares no code with this oracle.

    /usr/bin/python3 tests/data/make_dxf_cases.py tests/data/dxf-cases
"""
import math
import os
import re
import sys

import ezdxf
from ezdxf.math import Vec3

UNIT_MM = {0: 1.0, 1: 25.4, 2: 304.8, 4: 1.0, 5: 10.0, 6: 1000.0, 13: 1e-3, 14: 100.0}


def explode(entity, out):
    """Holes of an entity as (x, y, diameter, layer) in drawing units, via ezdxf."""
    t = entity.dxftype()
    if t == "CIRCLE":
        c = entity.dxf.center
        ocs = entity.ocs()
        w = ocs.to_wcs(c)
        normal = Vec3(entity.dxf.extrusion).normalize()
        if abs(abs(normal.z) - 1.0) > 1e-9:
            return  # tilted: an ellipse from above
        out.append((w.x, w.y, 2 * entity.dxf.radius, entity.dxf.layer))
    elif t == "INSERT":
        for sub in entity.multi_insert() if entity.mcount > 1 else [entity]:
            for v in sub.virtual_entities():
                explode(v, out)


def holes_of(doc):
    out = []
    for e in doc.modelspace():
        explode(e, out)
    unit = UNIT_MM.get(doc.header.get("$INSUNITS", 0), 1.0)
    seen = []
    result = []
    for x, y, d, layer in out:
        h = (x * unit, y * unit, d * unit, layer)
        if any(abs(h[0] - s[0]) <= 1e-6 and abs(h[1] - s[1]) <= 1e-6 and abs(h[2] - s[2]) <= 1e-6 for s in seen):
            continue
        seen.append(h)
        result.append(h)
    return result


def pin(path):
    """Pin what ezdxf stamps fresh on every save, so the files regenerate byte for byte."""
    with open(path) as f:
        text = f.read()
    text = re.sub(r"(\$VERSIONGUID\n  2\n)\{[0-9A-F-]+\}", r"\1{00000000-0000-0000-0000-000000000002}", text)
    text = re.sub(r"(\$FINGERPRINTGUID\n  2\n)\{[0-9A-F-]+\}", r"\1{00000000-0000-0000-0000-000000000001}", text)
    text = re.sub(r"(\$TDUPDATE\n 40\n)[0-9.]+", r"\g<1>2460000.5", text)
    text = re.sub(r"(\$TDCREATE\n 40\n)[0-9.]+", r"\g<1>2460000.5", text)
    text = re.sub(r"(\d+\.\d+\.\d+) @ \d{4}-\d\d-\d\dT[0-9:.+]+", r"\1 @ 2024-01-01T00:00:00+00:00", text)
    with open(path, "w") as f:
        f.write(text)


def save(doc, folder, name):
    path = os.path.join(folder, name + ".dxf")
    doc.saveas(path)
    pin(path)
    # The oracle reads the file back, as the reader under test will.
    back = ezdxf.readfile(path)
    with open(os.path.join(folder, name + ".holes.csv"), "w") as f:
        f.write("x_mm,y_mm,diameter_mm,layer\n")
        for x, y, d, layer in holes_of(back):
            f.write(f"{x:.6f},{y:.6f},{d:.6f},{layer}\n")


def new(version="R2010", units=4):
    doc = ezdxf.new(version, setup=False)
    doc.header["$INSUNITS"] = units
    return doc


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "tests/data/dxf-cases"
    os.makedirs(folder, exist_ok=True)

    # Blocks: base point, scale, rotation, mirror, nesting.
    doc = new()
    pattern = doc.blocks.new("PATTERN", base_point=(5, 5))
    for a in range(0, 360, 60):
        pattern.add_circle((5 + 4 * math.cos(math.radians(a)), 5 + 4 * math.sin(math.radians(a))), 0.5, dxfattribs={"layer": "0"})
    outer = doc.blocks.new("FLANGE")
    outer.add_blockref("PATTERN", (0, 0), dxfattribs={"rotation": 15})
    outer.add_blockref("PATTERN", (30, 0), dxfattribs={"xscale": -1, "yscale": 1})
    outer.add_circle((15, 15), 3)
    msp = doc.modelspace()
    msp.add_blockref("FLANGE", (100, 50), dxfattribs={"rotation": 30, "xscale": 2, "yscale": 2, "layer": "DRILL"})
    msp.add_blockref("FLANGE", (300, 50), dxfattribs={"xscale": 1.5, "yscale": -1.5, "rotation": 200})
    save(doc, folder, "blocks_nested_scaled_rotated_mirrored")

    # MINSERT arrays, rotated.
    doc = new()
    cell = doc.blocks.new("CELL")
    cell.add_circle((0, 0), 0.4)
    cell.add_circle((2.54, 0), 0.4)
    msp = doc.modelspace()
    msp.add_blockref("CELL", (10, 10), dxfattribs={"column_count": 4, "row_count": 3, "column_spacing": 10,
                                                   "row_spacing": 7, "rotation": 30})
    save(doc, folder, "minsert_rotated_array")

    # OCS: circles and inserts with extrusion (0, 0, -1) and a near-(0,0,-1) normal.
    doc = new()
    b = doc.blocks.new("B")
    b.add_circle((3, 1), 0.75)
    msp = doc.modelspace()
    msp.add_circle((20, 10), 1.5, dxfattribs={"extrusion": (0, 0, -1)})
    msp.add_circle((40, 10), 1.5, dxfattribs={"extrusion": (2.6e-24, 1.7e-20, -1)})
    msp.add_blockref("B", (50, 20), dxfattribs={"extrusion": (0, 0, -1), "rotation": 45})
    msp.add_circle((60, 10), 1.5, dxfattribs={"extrusion": (0.6, 0, 0.8)})  # tilted: not a hole
    save(doc, folder, "ocs_extrusions")

    # Non-uniform scale turns a circle into an ellipse: skipped; the uniform copy stays.
    doc = new()
    b = doc.blocks.new("HOLE")
    b.add_circle((0, 0), 2)
    msp = doc.modelspace()
    msp.add_blockref("HOLE", (0, 0), dxfattribs={"xscale": 2, "yscale": 1})
    msp.add_blockref("HOLE", (20, 0), dxfattribs={"xscale": 3, "yscale": 3})
    save(doc, folder, "non_uniform_scale_ellipse")

    # Paper space and unused block definitions are not holes.
    doc = new()
    doc.blocks.new("UNUSED").add_circle((1, 1), 1)
    doc.modelspace().add_circle((5, 5), 1)
    doc.layout().add_circle((7, 7), 1)  # the active paper-space layout
    save(doc, folder, "paper_space_and_unused_blocks")

    # Units: feet, centimetres, metres.
    for code, name in [(2, "feet"), (5, "centimetres"), (6, "metres")]:
        doc = new(units=code)
        doc.modelspace().add_circle((1.25, 0.5), 0.01)
        doc.modelspace().add_circle((0.5, 1.25), 0.02)
        save(doc, folder, f"units_{name}")

    # Layers, and duplicates: exact copies dropped, concentric kept.
    doc = new()
    msp = doc.modelspace()
    for layer in ["DRILL_3MM", "drill_6mm", "MILL"]:
        doc.layers.add(layer)
    msp.add_circle((10, 10), 1.5, dxfattribs={"layer": "DRILL_3MM"})
    msp.add_circle((10, 10), 1.5, dxfattribs={"layer": "DRILL_3MM"})
    msp.add_circle((10, 10), 3, dxfattribs={"layer": "drill_6mm"})
    msp.add_circle((50, 10), 10, dxfattribs={"layer": "MILL"})
    save(doc, folder, "layers_duplicates_concentric")

    # Old versions: R12 with blocks.
    doc = new("R12", units=0)
    b = doc.blocks.new("R12B")
    b.add_circle((1, 1), 0.25)
    doc.modelspace().add_blockref("R12B", (10, 10), dxfattribs={"rotation": 90})
    doc.modelspace().add_circle((3, 4), 0.5)
    save(doc, folder, "r12_blocks")


if __name__ == "__main__":
    if os.environ.get("PYTHONHASHSEED") != "0":
        os.execve(sys.executable, [sys.executable] + sys.argv, {**os.environ, "PYTHONHASHSEED": "0"})
    main()
