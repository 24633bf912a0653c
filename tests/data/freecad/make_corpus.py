"""Issue 83: FreeCAD CAM's programs, posted by every post FreeCAD 0.20 ships.

Run headless with Debian's FreeCAD (not needed by the tests, which read the
committed files):  freecadcmd tests/data/freecad/make_corpus.py
(on FreeCAD 1.0 the Path workbench is CAM; this script is for 0.20's names).

Each part is a plate of our own with holes; each Job drills them with
FreeCAD's Drilling operation (a tool controller per diameter; G81, G82 with a
dwell, G83 with pecks), posted with each post into POST/PART.nc. FreeCAD's
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


def plate(doc, name, size, holes):
    """A plate size = (x, y, z) mm with through holes [(x, y, diameter)]."""
    body = Part.makeBox(*size)
    for x, y, d in holes:
        body = body.cut(Part.makeCylinder(d / 2, size[2] + 2, App.Vector(x, y, -1)))
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = body
    doc.recompute()
    return obj


def drilling(doc, job, number, diameter, cycle):
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
    PathUtils.UserInput = ChosenTool(tc)
    op = PathDrilling.Create("Drill%d" % number)
    op.ToolController = tc
    op.Proxy.findAllHoles(op)
    # findAllHoles takes every hole the tool fits; keep this diameter's.
    keep = []
    for base, subs in op.Base:
        mine = [s for s in subs if abs(base.Shape.getElement(s).Surface.Radius * 2 - diameter) < 1e-6] if subs else []
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
    return op, tc


def own_holes(job):
    """FreeCAD's own holes: each op's features, their centre, depth, tool, in each fixture."""
    rows = []
    for fixture in job.Fixtures:
        for op in job.Operations.Group:
            for base, subs in op.Base:
                for s in subs:
                    c = base.Shape.getElement(s).Surface.Center
                    rows.append((fixture, op.ToolController.ToolNumber, c.x, c.y, op.FinalDepth.Value))
    return rows


def make(name, size, holes, cycles, fixtures=("G54",), order="Operation"):
    doc = App.newDocument(name)
    part = plate(doc, name, size, [(x, y, d) for x, y, d in holes])
    job = PathJob.Create("Job", [part], None)
    job.Fixtures = list(fixtures)
    job.OrderOutputBy = order
    for n, (diameter, cycle) in enumerate(cycles, start=1):
        drilling(doc, job, n, diameter, cycle)
    doc.recompute()
    with open(os.path.join(HERE, name + ".holes.csv"), "w") as f:
        f.write("fixture,tool,x_mm,y_mm,bottom_mm\n")
        for fixture, tool, x, y, bottom in own_holes(job):
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


def grid(nx, ny, pitch, x0, y0, d):
    return [(x0 + i * pitch, y0 + j * pitch, d) for i in range(nx) for j in range(ny)]


# A plate with 3 diameters and 3 cycles.
make("plate3", (120, 80, 10), grid(5, 2, 20, 10, 10, 3.5) + grid(4, 2, 22, 15, 45, 6.6) + [(100, 40, 10), (100, 65, 10)],
     [(3.5, 81), (6.6, 82), (10.0, 83)])
# The same on two fixtures, ordered by tool.
make("fixtures2", (120, 80, 10), grid(5, 2, 20, 10, 10, 3.5) + grid(4, 2, 22, 15, 45, 6.6),
     [(3.5, 81), (6.6, 83)], fixtures=("G54", "G55"), order="Tool")
