"""Issue 83: FreeCAD CAM's programs, posted by every post FreeCAD 0.20 ships.

Run headless with Debian's FreeCAD (not needed by the tests, which read the
committed files):  freecadcmd tests/data/freecad/make_corpus.py
(on FreeCAD 1.0 the Path workbench is CAM; this script is for 0.20's names).

Each part is a plate of our own with holes; each Job drills them with
FreeCAD's Drilling operation (and "milled" also profiles the plate between
two drillings) (a tool controller per diameter; G81, G82 with a
dwell, G83 with pecks; a stepped block an operation per height; G73 in a
Custom operation), posted with each post into POST/PART.nc (a post that
cannot post headless leaves PART.nc.failed with its traceback). FreeCAD's
own holes -- every feature's centre and depth, its tool and fixture, from the
Job, not from a program -- go into PART.holes.csv: the oracle.
"""
import importlib
import os
import sys
import traceback

import FreeCAD as App
import Part

HERE = os.path.dirname(os.path.abspath(__file__)) if "__file__" in dir() else os.path.join(os.getcwd(), "tests/data/freecad")
sys.path.insert(0, "/usr/share/freecad/Mod/Path")

import PathScripts.PathDrilling as PathDrilling  # noqa: E402
import PathScripts.PathJob as PathJob  # noqa: E402
import PathScripts.PathProfile as PathProfile  # noqa: E402
import PathScripts.PathPost as PathPost  # noqa: E402
import PathScripts.PathToolBit as PathToolBit  # noqa: E402
import PathScripts.PathToolController as PathToolController  # noqa: E402
import PathScripts.PathUtils as PathUtils  # noqa: E402


class ChosenTool:
    """What the GUI asks the user: which tool controller a new operation takes
    (headless, FreeCAD 0.20 fails with several and no one to ask)."""

    def __init__(self, tc):
        self.tc = tc

    def selectedToolController(self):
        return self.tc

POSTS = ["centroid", "dynapath", "fablin", "fanuc", "grbl", "jtech", "KineticNCBeamicon2", "linuxcnc", "mach3_mach4",
         "marlin", "nccad", "philips", "rrf", "smoothie", "uccnc", "heidenhain", "opensbp", "rml", "comparams", "dxf"]
SHAPES = "/usr/share/freecad/Mod/Path/Tools/Shape/drill.fcstd"


def plate(doc, name, size, holes, step=None):
    """A plate size = (x, y, z) mm with through holes [(x, y, diameter)]; with
    step = (x, depth), the part beyond x is lowered by depth (holes at two heights)."""
    body = Part.makeBox(*size)
    if step:
        body = body.cut(Part.makeBox(size[0] - step[0], size[1], step[1] + 1, App.Vector(step[0], 0, size[2] - step[1])))
    body = body.cut(Part.makeCompound([Part.makeCylinder(d / 2, size[2] + 2, App.Vector(x, y, -1)) for x, y, d in holes]))
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = body
    doc.recompute()
    return obj


def tool_controller(job, number, diameter):
    bit = PathToolBit.Factory.Create("Drill%g" % diameter, SHAPES)
    bit.Diameter = diameter
    # The fanuc post still asks a tool its legacy ToolType.
    bit.addProperty("App::PropertyString", "ToolType")
    bit.ToolType = "Drill"
    # Labelled as the GUI labels a new one ("TC: 3.5mm Drill"): the jtech post writes only the label.
    tc = PathToolController.Create("TC: %gmm Drill" % diameter, bit, number)
    tc.SpindleSpeed = 1000.0 + 200 * number
    tc.VertFeed = 100.0
    job.Proxy.addToolController(tc)
    return tc


def end_mill(job, number, diameter):
    bit = PathToolBit.Factory.Create("Endmill%g" % diameter, "/usr/share/freecad/Mod/Path/Tools/Shape/endmill.fcstd")
    bit.Diameter = diameter
    bit.addProperty("App::PropertyString", "ToolType")
    bit.ToolType = "EndMill"
    tc = PathToolController.Create("TC: %gmm Endmill" % diameter, bit, number)
    tc.SpindleSpeed = 10000.0
    tc.VertFeed = 100.0
    tc.HorizFeed = 600.0
    job.Proxy.addToolController(tc)
    return tc


def profile(doc, tc):
    """A Profile operation round the whole part (its outline, from the top down), as a shop cuts a plate free."""
    PathUtils.UserInput = ChosenTool(tc)
    op = PathProfile.Create("Profile")
    op.ToolController = tc
    doc.recompute()
    return op


def drilling(doc, tc, cycle, where=None):
    """A Drilling operation of the holes of tc's diameter (and, given `where`, of those at its centres)."""
    diameter = tc.Tool.Diameter.Value
    PathUtils.UserInput = ChosenTool(tc)
    op = PathDrilling.Create("Drill%d" % tc.ToolNumber)
    op.ToolController = tc
    op.Proxy.findAllHoles(op)
    # findAllHoles takes every hole the tool fits; keep this diameter's.
    keep = []
    for base, subs in op.Base:
        mine = [s for s in subs if abs(base.Shape.getElement(s).Surface.Radius * 2 - diameter) < 1e-6
                and (where is None or where(base.Shape.getElement(s).Surface.Center))] if subs else []
        if mine:
            keep.append((base, mine))
    op.Base = keep
    if cycle == 82:
        op.DwellEnabled = True
        op.DwellTime = 0.5
    if cycle == 83:
        op.PeckEnabled = True
        op.PeckDepth = 2.5
    doc.recompute()
    return op


def custom_g73(doc, tc, holes, top, bottom):
    """A Custom operation drilling with G73 (chip breaking), which 0.20's Drilling cannot: as a shop writes it."""
    import PathScripts.PathCustom as PathCustom
    PathUtils.UserInput = ChosenTool(tc)
    op = PathCustom.Create("CustomG73")
    op.ToolController = tc
    lines = ["G0 Z%.3f" % (top + 5)]
    for x, y in holes:
        lines += ["G0 X%.3f Y%.3f" % (x, y), "G73 X%.3f Y%.3f Z%.3f R%.3f Q1.500 F120" % (x, y, bottom, top + 2)]
    lines += ["G80", "G0 Z%.3f" % (top + 5)]
    op.Gcode = lines
    op.Proxy.custom_holes = [(x, y, bottom) for x, y in holes]
    doc.recompute()
    return op


def own_holes(job, custom):
    """FreeCAD's own holes: each Drilling op's features, their centre, depth, tool, in each fixture;
    a Custom op's, as its G-code gives them."""
    rows = []
    for fixture in job.Fixtures:
        for op in job.Operations.Group:
            if op.Name.startswith("CustomG73"):
                rows += [(fixture, op.ToolController.ToolNumber, x, y, z) for x, y, z in custom]
                continue
            for base, subs in op.Base:
                for s in subs:
                    c = base.Shape.getElement(s).Surface.Center
                    rows.append((fixture, op.ToolController.ToolNumber, c.x, c.y, op.FinalDepth.Value))
    return rows


def make(name, size, holes, cycles, fixtures=("G54",), order="Operation", step=None, g73=None, profile_after=None):
    """cycles: (diameter, cycle) a tool each; with step (x, depth), each tool drills the holes on
    each height in an operation of its own; g73: holes a Custom op drills with G73 and the last tool;
    profile_after: after that tool's drilling, a 6 mm end mill (T9) profiles the part."""
    if PARTS and name not in PARTS:
        return
    doc = App.newDocument(name)
    part = plate(doc, name, size, [(x, y, d) for x, y, d in holes], step)
    job = PathJob.Create("Job", [part], None)
    job.Fixtures = list(fixtures)
    job.OrderOutputBy = order
    custom = []
    for n, (diameter, cycle) in enumerate(cycles, start=1):
        tc = tool_controller(job, n, diameter)
        if step:
            drilling(doc, tc, cycle, lambda c: c.x <= step[0])
            drilling(doc, tc, cycle, lambda c: c.x > step[0])
        else:
            drilling(doc, tc, cycle)
        if profile_after == n:
            profile(doc, end_mill(job, 9, 6.0))
    if g73:
        op = custom_g73(doc, tc, g73, size[2], 0.0)
        custom = op.Proxy.custom_holes
    doc.recompute()
    with open(os.path.join(HERE, name + ".holes.csv"), "w") as f:
        f.write("fixture,tool,x_mm,y_mm,bottom_mm\n")
        for fixture, tool, x, y, bottom in own_holes(job, custom):
            f.write("%s,%d,%.4f,%.4f,%.4f\n" % (fixture, tool, x, y, bottom))
    postlist = PathPost.CommandPathPost().buildPostList(job)
    objs = [o for sub in postlist for o in sub]
    for o in objs:
        # The GUI's fixture objects lack what some posts look up (KineticNCBeamicon2, heidenhain).
        if not hasattr(o, "InList"):
            o.InList = []
        if not hasattr(o, "Proxy"):
            o.Proxy = None
    for post in POSTS:
        os.makedirs(os.path.join(HERE, post), exist_ok=True)
        # Posted from the post's folder to a bare name: some posts write the file's path into the program.
        os.chdir(os.path.join(HERE, post))
        out = name + ".nc"
        for stale in (out, out + ".failed"):
            if os.path.exists(stale):
                os.remove(stale)
        try:
            module = importlib.import_module("PathScripts.post.%s_post" % post)
            importlib.reload(module)
            # jtech's export writes its text to a file it opens in binary ("wb"): given text mode here.
            module.pythonopen = lambda path, mode: open(path, mode.replace("b", ""))
            # As the Job's Post button does, to a file; no editor to pop up headless
            # (the posts that take no such argument are posted without it).
            try:
                module.export(objs, out, "--no-show-editor")
            except SystemExit:
                importlib.reload(module)
                module.export(objs, out, "")
        except Exception:  # noqa: BLE001 -- a post that cannot post this job: recorded, not fatal
            with open(out + ".failed", "w") as f:
                f.write(traceback.format_exc())
    App.closeDocument(name)


# PARTS=milled,plate3 makes only those parts (each program names the time it was posted).
PARTS = [p for p in os.environ.get("PARTS", "").split(",") if p]


def grid(nx, ny, pitch, x0, y0, d):
    return [(x0 + i * pitch, y0 + j * pitch, d) for i in range(nx) for j in range(ny)]


def scattered(count, seed, x_tenths, y_tenths, origin, gap, diameter):
    """count holes placed pseudo-randomly (an LCG, the same every run) on a grid of 0.1 mm:
    x, y = origin + (0 .. x_tenths, 0 .. y_tenths) / 10, none closer than gap to another;
    diameter(k) the k-th hole's."""
    holes = []
    while len(holes) < count:
        seed = (seed * 1103515245 + 12345) % 2147483648
        x = origin + (seed % x_tenths) / 10.0
        seed = (seed * 1103515245 + 12345) % 2147483648
        y = origin + (seed % y_tenths) / 10.0
        if all((x - a) ** 2 + (y - b) ** 2 > gap * gap for a, b, _ in holes):
            holes.append((x, y, diameter(len(holes))))
    return holes


# A plate with 3 diameters and 3 cycles.
make("plate3", (120, 80, 10), grid(5, 2, 20, 10, 10, 3.5) + grid(4, 2, 22, 15, 45, 6.6) + [(100, 40, 10), (100, 65, 10)],
     [(3.5, 81), (6.6, 82), (10.0, 83)])
# The same on two fixtures, ordered by tool.
make("fixtures2", (120, 80, 10), grid(5, 2, 20, 10, 10, 3.5) + grid(4, 2, 22, 15, 45, 6.6),
     [(3.5, 81), (6.6, 83)], fixtures=("G54", "G55"), order="Tool")
# A block with a step: holes on its top (Z 20) and on the step (Z 10), an operation per height.
make("stepped", (100, 60, 20), grid(3, 2, 15, 10, 15, 5.0) + grid(3, 2, 15, 60, 15, 5.0), [(5.0, 81)], step=(50, 10))
# A board of 333 holes of 1 mm, placed as a pseudo-random pattern, and a
# Custom operation drilling six more with G73.
make("board333", (160, 100, 1.6), scattered(333, 12345, 1500, 900, 5, 3, lambda k: 1.0), [(1.0, 81)], g73=[(20 + 20 * i, 97.5) for i in range(6)])
# Issue 83: a Job that mills too. Holes of two sizes scattered over a plate, the first drilled
# with G81, then the plate profiled by an end mill, then the second drilled with G83:
# acodrill plan --keep-milling reorders each drilling and keeps the profile as posted.
make("milled", (120, 70, 8), scattered(22, 777, 1040, 540, 8, 10, lambda k: 3.5 if k < 14 else 6.6), [(3.5, 81), (6.6, 83)], profile_after=1)
