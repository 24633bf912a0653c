#!/usr/bin/python3
"""Issue 82: drawings of hole features written with ezdxf (Debian python3-ezdxf),
and the features each holds as NAME.features.csv. The oracle shares no code
with acodrill: positions come from ezdxf reading the file back (INSERTs
exploded with virtual_entities(), which applies base point, scale, rotation,
mirroring and MINSERT arrays), concentric circles grouped here; what each
group is comes from what the case drew (its `intent`), with the threads' tap
drills from the table below (ISO 2306 / DIN 336 metric; the usual 75 % inch
drills, Machinery's Handbook), written out again here, not read from acodrill.

    /usr/bin/python3 tests/data/make_feature_cases.py tests/data/dxf-features

Columns: x_mm,y_mm,kind,diameter_mm,drill_mm,outer_diameter_mm,thread,depth_mm,angle_deg
(outer, thread, depth and angle empty where they do not apply).
"""
import math
import os
import sys

import ezdxf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_dxf_cases import pin  # noqa: E402  (ezdxf's fresh stamps pinned, as for the reader's cases)

IN = 25.4
# name: (major mm, pitch mm, tap drill mm)
THREADS = {
    "M1.6": (1.6, 0.35, 1.25), "M2": (2.0, 0.4, 1.6), "M2.5": (2.5, 0.45, 2.05), "M3": (3.0, 0.5, 2.5),
    "M4": (4.0, 0.7, 3.3), "M5": (5.0, 0.8, 4.2), "M6": (6.0, 1.0, 5.0), "M8": (8.0, 1.25, 6.8),
    "M10": (10.0, 1.5, 8.5), "M12": (12.0, 1.75, 10.2), "M16": (16.0, 2.0, 14.0), "M20": (20.0, 2.5, 17.5),
    "M10x1.25": (10.0, 1.25, 8.8),
    "#4-40 UNC": (0.112 * IN, IN / 40, 0.089 * IN), "#10-24 UNC": (0.19 * IN, IN / 24, 0.1495 * IN),
    "#10-32 UNF": (0.19 * IN, IN / 32, 0.159 * IN), "1/4-20 UNC": (0.25 * IN, IN / 20, 0.201 * IN),
    "1/4-28 UNF": (0.25 * IN, IN / 28, 0.213 * IN), "1/2-13 UNC": (0.5 * IN, IN / 13, 0.4219 * IN),
}


def minor(name):
    major, pitch, _ = THREADS[name]
    return major - 1.082532 * pitch


def explode(entity, out):
    t = entity.dxftype()
    if t in ("CIRCLE", "ARC"):
        c = entity.ocs().to_wcs(entity.dxf.center)
        span = 360.0 if t == "CIRCLE" else (entity.dxf.end_angle - entity.dxf.start_angle) % 360 or 360.0
        out.append((t, c.x, c.y, 2 * entity.dxf.radius, span))
    elif t == "INSERT":
        for sub in entity.multi_insert() if entity.mcount > 1 else [entity]:
            for v in sub.virtual_entities():
                explode(v, out)


def groups_of(doc):
    """Concentric circles (and arcs) grouped by centre, in mm, in file order of their first circle."""
    unit = {0: 1.0, 1: IN, 4: 1.0}[doc.header.get("$INSUNITS", 0)]
    items = []
    for e in doc.modelspace():
        explode(e, items)
    groups = []
    for kind, x, y, d, span in items:
        x, y, d = x * unit, y * unit, d * unit
        for g in groups:
            if math.hypot(g["x"] - x, g["y"] - y) <= 1e-4:
                break
        else:
            if kind == "ARC":
                continue  # an arc with no circle is no hole
            g = {"x": x, "y": y, "circles": [], "arcs": []}
            groups.append(g)
        if kind == "CIRCLE":
            if all(abs(c - d) > 1e-6 for c in g["circles"]):
                g["circles"].append(d)
        else:
            g["arcs"].append((d, span))
    for g in groups:
        g["circles"].sort()
    return groups


def f6(v):
    return "" if v is None else f"{v:.6f}"


def save(doc, folder, name, intent):
    """intent(hole_mm, larger_mm, arcs) -> (kind, drill_mm, outer_mm, thread, depth_mm, angle_deg)."""
    path = os.path.join(folder, name + ".dxf")
    doc.saveas(path)
    pin(path)
    back = ezdxf.readfile(path)
    with open(os.path.join(folder, name + ".features.csv"), "w") as f:
        f.write("x_mm,y_mm,kind,diameter_mm,drill_mm,outer_diameter_mm,thread,depth_mm,angle_deg\n")
        for g in groups_of(back):
            hole = g["circles"][0]
            kind, drill, outer, thread, depth, angle = intent(round(hole, 4), [round(c, 4) for c in g["circles"][1:]],
                                                              [(round(d, 4), round(s, 3)) for d, s in g["arcs"]])
            f.write(f"{g['x']:.6f},{g['y']:.6f},{kind},{hole:.6f},{drill:.6f},{f6(outer)},{thread or ''},"
                    f"{f6(depth)},{f6(angle)}\n")


def new(units=4):
    doc = ezdxf.new("R2018", setup=False)
    doc.header["$INSUNITS"] = units
    return doc


def tapped(name):
    major, _, drill = THREADS[name]
    return ("tapped", drill, major, name, None, None)


def plain(hole):
    return ("plain", hole, None, None, None, None)


def undecided(hole, larger):
    return ("undecided", hole, larger[0], None, None, None)


def thread_by_drawing(table):
    """intent for drawings whose tapped holes are those of `table` {(hole, arc): name}."""
    def intent(hole, larger, arcs):
        for d, span in arcs:
            name = table.get((hole, d))
            if name and 240 <= span <= 300:
                return tapped(name)
        return undecided(hole, larger) if larger else plain(hole)
    return intent


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "tests/data/dxf-features"
    os.makedirs(folder, exist_ok=True)

    # Metric threads M1.6-M20, the arc open in each quadrant, the hole drawn at the minor diameter
    # (Fusion 360) or at the tap drill; M10x1.25 told from M10 by its hole; arcs of 240 and 300
    # degrees are threads, 235 and 305 are not.
    doc = new()
    doc.layers.add("Thread Lines")
    msp = doc.modelspace()
    table = {}
    names = ["M1.6", "M2", "M2.5", "M3", "M4", "M5", "M6", "M8", "M10", "M12", "M16", "M20", "M10x1.25"]
    for row, name in enumerate(names):
        major = THREADS[name][0]
        for col, start in enumerate([0, 90, 180, 270]):
            hole = round(minor(name), 4) if col % 2 == 0 else THREADS[name][2]
            c = (40 * col, 30 * row)
            msp.add_circle(c, hole / 2)
            msp.add_arc(c, major / 2, start, start + 270, dxfattribs={"layer": "Thread Lines"})
            table[(round(hole, 4), round(major, 4))] = name
    for col, span in enumerate([240, 300, 235, 305]):
        c = (200 + 40 * col, 0)
        msp.add_circle(c, 5.0 / 2)
        msp.add_arc(c, 6.0 / 2, 30, 30 + span, dxfattribs={"layer": "Thread Lines"})
    spans = {(5.0, 6.0)}

    def quadrants(hole, larger, arcs):
        for d, span in arcs:
            if (hole, d) in spans:
                return tapped("M6") if 240 <= span <= 300 else plain(hole)
        return thread_by_drawing(table)(hole, larger, arcs)
    save(doc, folder, "tapped_metric_quadrants", quadrants)

    # A tapped hole in a block: rotated, mirrored, scaled (an M3 drawn at twice its size is an M6) and arrayed.
    doc = new()
    m6 = doc.blocks.new("M6_TAPPED")
    m6.add_circle((0, 0), round(minor("M6"), 4) / 2)
    m6.add_arc((0, 0), 3.0, 45, 315)
    m3 = doc.blocks.new("M3_TAPPED", base_point=(1, 1))
    m3.add_circle((1, 1), THREADS["M3"][2] / 2)
    m3.add_arc((1, 1), 1.5, 100, 370)
    msp = doc.modelspace()
    msp.add_blockref("M6_TAPPED", (10, 10), dxfattribs={"rotation": 30})
    msp.add_blockref("M6_TAPPED", (40, 10), dxfattribs={"xscale": -1})
    msp.add_blockref("M3_TAPPED", (70, 10), dxfattribs={"xscale": 2, "yscale": 2, "rotation": 200})
    msp.add_blockref("M6_TAPPED", (10, 50), dxfattribs={"column_count": 3, "row_count": 2, "column_spacing": 20,
                                                        "row_spacing": 15, "rotation": 10})
    save(doc, folder, "tapped_in_blocks", thread_by_drawing({(round(minor("M6"), 4), 6.0): "M6", (5.0, 6.0): "M6"}))

    # An inch drawing: UNC and UNF, told apart by the drawn hole (#10-24 and #10-32, 1/4-20 and 1/4-28).
    doc = new(units=1)
    msp = doc.modelspace()
    table = {}
    for col, name in enumerate(["#4-40 UNC", "#10-24 UNC", "#10-32 UNF", "1/4-20 UNC", "1/4-28 UNF", "1/2-13 UNC"]):
        major, _, drill = THREADS[name]
        c = (1.0 * col, 0.5)
        msp.add_circle(c, drill / IN / 2)
        msp.add_arc(c, major / IN / 2, 10, 280)
        table[(round(drill, 4), round(major, 4))] = name
    save(doc, folder, "tapped_inch", thread_by_drawing(table))

    # Counterbores and countersinks by the larger circle's layer: whole words only.
    doc = new()
    msp = doc.modelspace()
    layers = [("CBORE", 6.6, 11.0, "counterbore"), ("C'BORE M5", 5.5, 10.0, "counterbore"), ("csk", 4.5, 9.0, "countersink"),
              ("SPOTFACE", 9.0, 15.0, "counterbore"), ("COUNTERSINK_90", 6.4, 12.4, "countersink"),
              ("Countersinks", 3.4, 6.5, "undecided"), ("CBORES", 2.9, 5.8, "undecided")]
    kinds = {}
    for col, (layer, hole, outer, kind) in enumerate(layers):
        doc.layers.add(layer)
        for row in range(2):
            c = (30 * col, 25 * row)
            msp.add_circle(c, hole / 2, dxfattribs={"layer": "HOLES"})
            msp.add_circle(c, outer / 2, dxfattribs={"layer": layer})
        kinds[hole] = (kind, outer)
    save(doc, folder, "by_layer",
         lambda hole, larger, arcs: (kinds[hole][0], hole, kinds[hole][1], None, None, None))

    # Callouts: an MTEXT in the GD&T font beside one of four identical holes decides all four;
    # Unicode symbols; a TEXT with %%c; a TEXT in a style whose font is gdt.shx; a LEADER's
    # arrow at a hole with its MTEXT far off; a callout too far from its holes; two that disagree.
    doc = new()
    doc.styles.new("GDT", dxfattribs={"font": "gdt.shx"})
    msp = doc.modelspace()
    for k in range(4):
        msp.add_circle((20 * k, 0), 3.4 / 2)
        msp.add_circle((20 * k, 0), 6.5 / 2)
    msp.add_mtext("{\\Fgdt;n}3.4 THRU\\P{\\Fgdt;v}{\\Fgdt;n}6.5 {\\Fgdt;x}3.0", dxfattribs={"insert": (5, 12), "char_height": 2.5})
    for k in range(3):
        msp.add_circle((20 * k, 50), 4.5 / 2)
        msp.add_circle((20 * k, 50), 9.0 / 2)
    msp.add_mtext("3X \u23004.5 THRU\\P\u2335 \u23009.0 X 90\u00b0", dxfattribs={"insert": (48, 56), "char_height": 2.5})
    for k in range(2):
        msp.add_circle((20 * k, 100), 5.5 / 2)
        msp.add_circle((20 * k, 100), 10.0 / 2)
    msp.add_text("%%c5.5 THRU, C'BORE %%c10 X 5.4 DEEP", dxfattribs={"insert": (-10, 110), "height": 2.5})
    msp.add_circle((100, 0), 6.6 / 2)
    msp.add_circle((100, 0), 11.0 / 2)
    msp.add_text("n6.6 THRU v n11 x 6.5", dxfattribs={"insert": (95, 10), "height": 2.5, "style": "GDT"})
    msp.add_circle((150, 0), 8.0 / 2)
    msp.add_circle((150, 0), 14.0 / 2)
    far = msp.add_mtext("%%c8 THRU \\U+2335 %%c14 X 90%%d", dxfattribs={"insert": (200, 80), "char_height": 2.5})
    msp.add_circle((150, 100), 13.5 / 2)
    msp.add_circle((150, 100), 20.0 / 2)
    note = msp.add_mtext("\\U+2300 13.5 THRU \\U+2334 \\U+2300 20 \\U+21A7 12.6", dxfattribs={"insert": (230, 160), "char_height": 2.5})
    msp.add_leader([(150 + 10 * math.cos(0.8), 100 + 10 * math.sin(0.8)), (180, 150), (228, 160)],
                   dxfattribs={"annotation_handle": note.dxf.handle, "has_arrowhead": 1})
    msp.add_circle((100, 100), 2.9 / 2)
    msp.add_circle((100, 100), 5.8 / 2)
    msp.add_text("%%c2.9 CBORE %%c5.8", dxfattribs={"insert": (90, 106), "height": 2})
    msp.add_text("%%c2.9 CSK %%c5.8", dxfattribs={"insert": (90, 92), "height": 2})
    del far
    decided = {3.4: ("counterbore", 6.5, 3.0, None), 4.5: ("countersink", 9.0, None, 90.0), 5.5: ("counterbore", 10.0, 5.4, None),
               6.6: ("counterbore", 11.0, 6.5, None), 13.5: ("counterbore", 20.0, 12.6, None)}

    def callouts(hole, larger, arcs):
        if hole in decided:
            kind, outer, depth, angle = decided[hole]
            return (kind, hole, outer, None, depth, angle)
        return undecided(hole, larger)
    save(doc, folder, "callouts", callouts)

    # Concentric circles that are no counterbore: a boss, a bearing seat's steps, a washer's outline.
    doc = new()
    msp = doc.modelspace()
    for d in (10.0, 30.0):
        msp.add_circle((0, 0), d / 2)
    for d in (22.0, 26.0, 35.0):
        msp.add_circle((60, 0), d / 2, dxfattribs={"layer": "BEARING"})
    for k in range(4):
        msp.add_circle((100 + 20 * k, 0), 6.6 / 2)
        msp.add_circle((100 + 20 * k, 0), 12.0 / 2, dxfattribs={"layer": "WASHER"})
    save(doc, folder, "undecided", lambda hole, larger, arcs: undecided(hole, larger))

    # Arcs that are no thread: a lobe of 308 degrees, an arc of no standard major, an M6 arc
    # around a hole far below M6's minor diameter.
    doc = new()
    msp = doc.modelspace()
    for c, hole, arc, span in [((0, 0), 6.2, 10.0, 308), ((30, 0), 5.0, 7.3, 270), ((60, 0), 3.0, 6.0, 270)]:
        msp.add_circle(c, hole / 2)
        msp.add_arc(c, arc / 2, 0, span)
    save(doc, folder, "arcs_not_threads", lambda hole, larger, arcs: plain(hole))

    # The first drawing: a 3D printer's build plate as Fusion 360 draws it (AutoCAD 2018 DXF):
    # four M3 counterbored holes (3.4 with 6.5) and their GD&T callout, two M3 tapped holes (2.459
    # with a 3.0 arc of 270 degrees on "Thread Lines", callout M3x0.5 - 6H); and the same without the callout.
    for name, with_callout in [("build_plate", True), ("build_plate_no_callout", False)]:
        doc = new()
        for layer in ("Visible (ANSI)", "Thread Lines", "Center Lines", "Dimensions"):
            doc.layers.add(layer)
        msp = doc.modelspace()
        msp.add_lwpolyline([(0, 0), (120, 0), (120, 120), (0, 120)], close=True, dxfattribs={"layer": "Visible (ANSI)"})
        for x, y in [(10, 10), (110, 10), (110, 110), (10, 110)]:
            msp.add_circle((x, y), 3.4 / 2, dxfattribs={"layer": "Visible (ANSI)"})
            msp.add_circle((x, y), 6.5 / 2, dxfattribs={"layer": "Visible (ANSI)"})
        for x, y in [(45, 60), (75, 60)]:
            msp.add_circle((x, y), 2.459 / 2, dxfattribs={"layer": "Visible (ANSI)"})
            msp.add_arc((x, y), 1.5, 0, 270, dxfattribs={"layer": "Thread Lines"})
        msp.add_mtext("M3x0.5 - 6H", dxfattribs={"insert": (50, 70), "char_height": 2.5, "layer": "Dimensions"})
        if with_callout:
            msp.add_mtext("{\\fAIGDT|b0|i0|c0|p0;n}3.4 THRU\\P{\\fAIGDT|b0|i0|c0|p0;v} {\\fAIGDT|b0|i0|c0|p0;n}6.5 "
                          "{\\fAIGDT|b0|i0|c0|p0;x} 3.0", dxfattribs={"insert": (18, 24), "char_height": 2.5, "layer": "Dimensions"})

        def plate(hole, larger, arcs, with_callout=with_callout):
            if arcs:
                return tapped("M3")
            return ("counterbore", hole, 6.5, None, 3.0, None) if with_callout else undecided(hole, larger)
        save(doc, folder, name, plate)

    # The second drawing: M6 tapped (5.0 with a 6.0 arc) and M6 counterbored (6.6 with 11), four each.
    doc = new()
    msp = doc.modelspace()
    for k in range(4):
        msp.add_circle((20 * k, 0), 5.0 / 2)
        msp.add_arc((20 * k, 0), 3.0, 200, 470)
        msp.add_circle((20 * k, 30), 6.6 / 2)
        msp.add_circle((20 * k, 30), 11.0 / 2)
    save(doc, folder, "m6_tapped_and_counterbored",
         lambda hole, larger, arcs: tapped("M6") if arcs else undecided(hole, larger))


if __name__ == "__main__":
    if os.environ.get("PYTHONHASHSEED") != "0":
        os.execve(sys.executable, [sys.executable] + sys.argv, {**os.environ, "PYTHONHASHSEED": "0"})
    main()
