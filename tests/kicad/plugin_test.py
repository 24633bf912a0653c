#!/usr/bin/python3
"""Issue 47: the KiCad plugin, headless, with Debian's KiCad 6 pcbnew.

Oracles that owe nothing to the plugin's code: pcbnew's own pad and via
list, KiCad's own Excellon writer (for oval holes), GRBL 1.1h's parser
(gvalidate), LinuxCNC's interpreter (rs274) and KiCad's PCM schema.

    ACODRILL=build/bin/acodrill GVALIDATE=build/grbl/gvalidate.exe /usr/bin/python3 tests/kicad/plugin_test.py
"""
import glob
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PLUGIN_DIR = os.path.join(ROOT, "plugins", "kicad")
sys.path.insert(0, PLUGIN_DIR)
ACODRILL = os.environ.get("ACODRILL", os.path.join(ROOT, "build", "bin", "acodrill"))
GVALIDATE = os.environ.get("GVALIDATE", os.path.join(ROOT, "build", "grbl", "gvalidate.exe"))
DEMOS = "/usr/share/kicad/demos"

try:
    import pcbnew
except ImportError:  # scripts/test installs kicad; say so rather than pass
    pcbnew = None

from acodrill_kicad import job  # noqa: E402  (pure: no pcbnew)
if os.environ.get("ACO_REQUIRE_KICAD") and (pcbnew is None):
    sys.exit("KiCad's pcbnew (apt install kicad kicad-demos) or a display (xvfb-run) is missing; scripts/test installs them")
# Issue 69: the same tests on KiCad 9 (ctest's kicad9.*): fail on any other pcbnew rather than test it.
if os.environ.get("ACO_REQUIRE_KICAD_MAJOR") and (pcbnew is None or
                                                   pcbnew.GetBuildVersion().split(".")[0] != os.environ["ACO_REQUIRE_KICAD_MAJOR"]):
    sys.exit(f"KiCad {os.environ['ACO_REQUIRE_KICAD_MAJOR']}'s pcbnew is not the one loaded "
             f"({pcbnew.GetBuildVersion() if pcbnew else 'none'}); scripts/test unpacks it into build-deps/kicad9")


def read(path, mode="r"):
    with open(path, mode) as f:
        return f.read()


def demo(name):
    found = glob.glob(os.path.join(DEMOS, "**", name + ".kicad_pcb"), recursive=True)
    if not found:
        raise unittest.SkipTest(f"KiCad demo board {name} not installed (apt install kicad-demos)")
    return found[0]


def headless(*args, cwd=None):
    env = dict(os.environ, PYTHONPATH=PLUGIN_DIR)
    return subprocess.run(["/usr/bin/python3", "-m", "acodrill_kicad"] + list(args) + ["--acodrill", ACODRILL],
                          capture_output=True, text=True, env=env, cwd=cwd)


def rs274_strokes(program):
    """(x, y, from_z, to_z) of every downward feed at one XY, as LinuxCNC runs the program (mm programs)."""
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "tool.tbl"), "w") as f:
            f.write("".join(f"T{n} P{n} Z0 D1\n" for n in range(1, 60)))
        # HOME of its own too: LinuxCNC 2.9 maps its tool data into $HOME/.tool.mmap, one file for every
        # rs274 of the user, so two runs at once would read each other's tool tables (issue 85).
        done = subprocess.run(["rs274", "-t", "tool.tbl", "-g", os.path.abspath(program)], cwd=d,
                              env=dict(os.environ, HOME=d), capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    strokes, x, y, z = [], 0.0, 0.0, 0.0
    for m in re.finditer(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED)\(([^)]*)\)", done.stdout):
        v = [float(a) for a in m.group(2).split(",")[:3]]
        if m.group(1) == "STRAIGHT_FEED" and abs(v[0] - x) < 1e-9 and abs(v[1] - y) < 1e-9 and v[2] < z:
            strokes.append((v[0], v[1], z, v[2]))
        x, y, z = v
    return strokes


def holes_of(strokes):
    """Drilled positions, once each: consecutive strokes at one XY are one hole."""
    holes = []
    for s in strokes:
        if not holes or (abs(holes[-1][0] - s[0]) > 1e-9 or abs(holes[-1][1] - s[1]) > 1e-9):
            holes.append((s[0], s[1]))
    return holes


def match(found, expected, tol):
    """Pairs every found position with a distinct expected one within tol; the unmatched of each side."""
    rest = sorted(expected)
    missing_pairs = []
    for p in sorted(found):
        best = None
        lo = 0
        while lo < len(rest) and rest[lo][0] < p[0] - tol:
            lo += 1
        for k in range(lo, len(rest)):
            if rest[k][0] > p[0] + tol:
                break
            if abs(rest[k][1] - p[1]) <= tol:
                best = k
                break
        if best is None:
            missing_pairs.append(p)
        else:
            rest.pop(best)
    return missing_pairs, rest


def iu_per_mm():
    # KiCad 6: pcbnew.IU_PER_MM; 7 on: pcbnew.pcbIUScale.IU_PER_MM.
    return pcbnew.pcbIUScale.IU_PER_MM if hasattr(pcbnew, "pcbIUScale") else pcbnew.IU_PER_MM


def vector(x_mm, y_mm, kind):
    """A size or point in internal units: VECTOR2I from KiCad 7 on, wxSize/wxPoint on 6."""
    x, y = int(round(x_mm * iu_per_mm())), int(round(y_mm * iu_per_mm()))
    if hasattr(pcbnew, "pcbIUScale"):  # KiCad 7 on (KiCad 6 has a VECTOR2I too, but takes wx types)
        return pcbnew.VECTOR2I(x, y)
    return pcbnew.wxSize(x, y) if kind == "size" else pcbnew.wxPoint(x, y)


def board_round_holes(path):
    """pcbnew's own list: round pad drills (plated or not) and through vias, mm, Y up."""
    b = pcbnew.LoadBoard(path)
    to_mm = 1.0 / iu_per_mm()
    holes, ovals = [], 0
    for fp in b.GetFootprints():
        for pad in fp.Pads():
            s = pad.GetDrillSize()
            if s.x <= 0:
                continue
            if s.x != s.y:
                ovals += 1
                continue
            p = pad.GetPosition()
            holes.append((p.x * to_mm, -p.y * to_mm))
    for t in b.GetTracks():
        if t.Type() == pcbnew.PCB_VIA_T:
            p = t.GetPosition()
            holes.append((p.x * to_mm, -p.y * to_mm))
    return holes, ovals


def kicad_writer_files(path, folder):
    """KiCad's own Excellon files of the board (metric, decimal, PTH and NPTH apart)."""
    b = pcbnew.LoadBoard(path)
    w = pcbnew.EXCELLON_WRITER(b)
    w.SetOptions(False, False, vector(0, 0, "point"), False)
    w.SetFormat(True, pcbnew.GENDRILL_WRITER_BASE.DECIMAL_FORMAT, 3, 3)
    w.CreateDrillandMapFilesSet(folder, True, False)
    files = sorted(glob.glob(os.path.join(folder, "*.drl")))
    # An empty NPTH file has no hits: acodrill says so and plans the rest.
    return files


def gvalidate_refusal(program):
    with tempfile.TemporaryDirectory() as d:
        with open(program) as f:
            text = f.read()
        with open(os.path.join(d, "p.nc"), "w") as f:
            f.write("$C\n" + text)
        done = subprocess.run(["timeout", "120", GVALIDATE, "p.nc"], cwd=d, capture_output=True, text=True)
    return "" if done.returncode == 0 and "error" not in done.stdout else done.stdout[-300:]


@unittest.skipIf(pcbnew is None, "KiCad's pcbnew module is missing: scripts/test installs kicad")
class DemoBoards(unittest.TestCase):
    BOARDS = ["pic_programmer", "video", "StickHub", "ecc83-pp_v2", "kit-dev-coldfire-xilinx_5213"]

    def test_every_board_plans_to_exactly_its_holes_on_the_router(self):
        for name in self.BOARDS:
            with self.subTest(board=name), tempfile.TemporaryDirectory() as d:
                path = demo(name)
                program = os.path.join(d, "p.gcode")
                drills = os.path.join(d, "drills")
                done = headless(path, "-o", program, "--machine", "router", "--origin", "drawing", "--seed", "1",
                                "--iterations", "5", "--drill-files", drills, "-q")
                self.assertEqual(done.returncode, 0, done.stderr)
                self.assertEqual(done.stderr, "", "quiet on success")
                # GRBL accepts every line.
                self.assertEqual(gvalidate_refusal(program), "", name)
                strokes = rs274_strokes(program)
                drilled = holes_of(strokes)
                # Hobby drilling: one stroke a hole, fed from 1 mm above the board.
                self.assertEqual(len(drilled), len(strokes), f"{name}: a hole is pecked")
                for s in strokes:
                    self.assertLessEqual(s[2], 1.0 + 1e-9)
                    self.assertLess(s[3], -1.6)
                # Every round pad and via as pcbnew lists it, to half the program's last digit.
                round_holes, ovals = board_round_holes(path)
                extra, missing = match(drilled, round_holes, 0.0005 + 1e-7)
                self.assertEqual(missing, [], f"{name}: holes of the board not drilled")
                # The rest are the oval drills, each a row of holes: the same rows as
                # KiCad's own drill files give (they round to 1 um, hence 1.5 um).
                kicad = os.path.join(d, "kicad")
                os.makedirs(kicad)
                ref = os.path.join(d, "ref.gcode")
                r = subprocess.run([ACODRILL, "plan"] + kicad_writer_files(path, kicad) +
                                   ["-o", ref, "--machine", "router", "--origin", "drawing", "--iterations", "2", "-q"],
                                   capture_output=True, text=True)
                self.assertEqual(r.returncode, 0, r.stderr)
                ref_holes = holes_of(rs274_strokes(ref))
                self.assertEqual(len(ref_holes), len(drilled), name)
                a, b = match(drilled, ref_holes, 0.0015)
                self.assertEqual((a, b), ([], []), f"{name}: not the holes KiCad's own drill files give")
                self.assertEqual(len(extra) > 0, ovals > 0, f"{name}: {ovals} oval drills, {len(extra)} slot holes")
                # verify: every hole once, with a drill of its diameter.
                inputs = sorted(glob.glob(os.path.join(drills, "*.drl")))
                v = subprocess.run([ACODRILL, "verify", program, "--holes"] + inputs + ["--origin", "drawing"],
                                   capture_output=True, text=True)
                self.assertEqual(v.returncode, 0, v.stdout + v.stderr)

    def test_owned_drills_and_an_end_mill_pass_through_the_headless_command(self):
        # Issue 53: the pic_programmer board with four drills and a 1 mm end mill.
        with tempfile.TemporaryDirectory() as d:
            path = demo("pic_programmer")
            program, report = os.path.join(d, "p.gcode"), os.path.join(d, "r.json")
            drills = os.path.join(d, "drills")
            owned = ["--drills", "0.6,0.8,1.0,1.2", "--end-mill", "1.0"]
            done = headless(path, "-o", program, "--machine", "router", "--origin", "drawing", "--seed", "1",
                            "--iterations", "5", "--drill-files", drills, "--report", report, "-q", *owned)
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertEqual(gvalidate_refusal(program), "")
            with open(report) as f:
                r = json.load(f)
            self.assertEqual(len(r["tools"]), 5)
            self.assertEqual(r["tools"][-1]["kind"], "end_mill")
            inputs = sorted(glob.glob(os.path.join(drills, "*.drl")))
            v = subprocess.run([ACODRILL, "verify", program, "--holes"] + inputs + ["--origin", "drawing"] + owned,
                               capture_output=True, text=True)
            self.assertEqual(v.returncode, 0, v.stdout + v.stderr)

    def test_linuxcnc_program_at_the_default_origin_and_plated_apart(self):
        with tempfile.TemporaryDirectory() as d:
            path = demo("pic_programmer")
            program, sheet, report = (os.path.join(d, f) for f in ("p.ngc", "s.html", "r.json"))
            drills = os.path.join(d, "drills")
            done = headless(path, "-o", program, "--dialect", "linuxcnc", "--keep-files-apart", "--iterations", "5",
                            "--drill-files", drills, "--setup-sheet", sheet, "--report", report)
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertIn("pic_programmer-PTH.drl", done.stderr)
            self.assertIn("pic_programmer-NPTH.drl", done.stderr)
            self.assertTrue(os.path.exists(sheet))
            r = json.loads(read(report))
            self.assertEqual(r["holes"], len(board_round_holes(path)[0]))
            self.assertEqual([s["file"].endswith(("PTH.drl",)) for s in r["sources"]], [True, True])
            inputs = [os.path.join(drills, "pic_programmer-PTH.drl"), os.path.join(drills, "pic_programmer-NPTH.drl")]
            v = subprocess.run([ACODRILL, "verify", program, "--holes"] + inputs, capture_output=True, text=True)
            self.assertEqual(v.returncode, 0, v.stdout + v.stderr)
            # Apart: the non-plated holes have tools of their own, after the plated ones.
            tools = [t["tool"] for t in r["tools"]]
            self.assertEqual(len(tools), len(set(tools)))
            self.assertIn("M30", read(program))

    def test_program_zero_at_the_drill_origin(self):
        with tempfile.TemporaryDirectory() as d:
            path = demo("pic_programmer")  # its drill/place file origin is at (62.23, 153.67) mm
            program = os.path.join(d, "p.gcode")
            done = headless(path, "-o", program, "--origin", "drill-origin", "--iterations", "2", "-q",
                            "--machine", "router")
            self.assertEqual(done.returncode, 0, done.stderr)
            holes, _ = board_round_holes(path)
            moved = [(x - 62.23, y + 153.67) for x, y in holes]
            extra, missing = match(holes_of(rs274_strokes(program)), moved, 0.0005 + 1e-7)
            self.assertEqual((extra, missing), ([], []))

    def test_errors_are_one_line_exit_2_and_no_program(self):
        with tempfile.TemporaryDirectory() as d:
            program = os.path.join(d, "p.nc")
            bad = os.path.join(d, "bad.kicad_pcb")
            with open(bad, "w") as f:
                f.write("(kicad_pcb (version 20211014)\n (net 0 \"\")\n garbage here\n")
            cases = [
                ([os.path.join(d, "none.kicad_pcb"), "-o", program], "no such board file"),
                ([bad, "-o", program], "KiCad cannot read the board"),
                ([demo("microwave"), "-o", program], "no drilled pads or vias"),
                ([demo("video"), "-o", program, "--dialect", "nope"], "--dialect must be"),
                ([demo("video"), "-o", program, "--machine", "nowhere.json"], "nowhere.json"),
                ([demo("video")], "-o PROGRAM"),
            ]
            for args, says in cases:
                with self.subTest(args=args):
                    done = headless(*args)
                    self.assertEqual(done.returncode, 2, done.stderr)
                    lines = done.stderr.strip().splitlines()
                    self.assertEqual(len(lines), 1, done.stderr)
                    self.assertTrue(lines[0].startswith("acodrill: error: "), lines[0])
                    self.assertIn(says, lines[0])
                    self.assertFalse(os.path.exists(program))
            env = dict(os.environ, PYTHONPATH=PLUGIN_DIR)
            done = subprocess.run(["/usr/bin/python3", "-m", "acodrill_kicad", demo("video"), "-o", program,
                                   "--acodrill", os.path.join(d, "missing-acodrill")], capture_output=True, text=True, env=env)
            self.assertEqual(done.returncode, 2)
            self.assertIn("acodrill is not installed", done.stderr)


@unittest.skipIf(pcbnew is None, "KiCad's pcbnew module is missing: scripts/test installs kicad")
class DialogLogic(unittest.TestCase):
    """What the dialog's Plan button does (job.plan_for_dialog), without a window."""

    def test_plan_writes_beside_the_board_and_summarises(self):
        from acodrill_kicad.board import board_drills, drill_origin

        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "video.kicad_pcb")
            shutil.copy(demo("video"), path)
            board = pcbnew.LoadBoard(path)
            drills, warnings = board_drills(board)
            choices = job.Choices(machine="router", time_limit_s=1, extra=["--seed", "1"])
            out = job.plan_for_dialog(drills, warnings, drill_origin(board), path, choices, ACODRILL)
            self.assertTrue(out.ok, out.text)
            self.assertEqual(out.program, os.path.join(d, "video-drill.gcode"))  # the router's dialect: GRBL
            self.assertEqual(out.setup_sheet, os.path.join(d, "video-drill-setup.html"))
            self.assertTrue(os.path.exists(out.program) and os.path.exists(out.setup_sheet))
            self.assertIn("1720 holes, 11 tools", out.text)
            before, after = re.search(r"Time: +([0-9.]+) min in the board's order -> ([0-9.]+) min", out.text).groups()
            self.assertLess(float(after), float(before))
            self.assertIn("drilling", out.text)
            # A failure is acodrill's own line, and nothing is written.
            os.remove(out.program)
            bad = job.Choices(machine=os.path.join(d, "nowhere.json"), write_setup_sheet=False)
            failed = job.plan_for_dialog(drills, warnings, drill_origin(board), path, bad, ACODRILL)
            self.assertFalse(failed.ok)
            self.assertTrue(failed.text.startswith("acodrill: error: "), failed.text)
            self.assertFalse(os.path.exists(out.program))


class Choices(unittest.TestCase):
    def test_choices_become_plan_options(self):
        c = job.Choices(machine="vf2", dialect="fanuc", origin="drill-origin", plated_apart=True, time_limit_s=30,
                        extra=["--units", "inch"])
        self.assertEqual(job.plan_options(c, (62.23, -153.67)),
                         ["--machine", "vf2", "--dialect", "fanuc", "--origin", "62.230000,-153.670000",
                          "--keep-files-apart", "--time-limit", "30", "--units", "inch"])
        self.assertEqual(job.plan_options(job.Choices(time_limit_s=0)), ["--machine", "router", "--origin", "lower-left"])
        owned = job.Choices(time_limit_s=0, drills=" 0.6, 0.8,1.0 ", end_mill_mm=1.0, from_back=True, probe_plate_mm=0.5)
        self.assertEqual(job.plan_options(owned), ["--machine", "router", "--origin", "lower-left", "--drills", "0.6,0.8,1.0",
                                                   "--end-mill", "1", "--side", "back", "--probe-plate", "0.5"])
        with self.assertRaises(job.PlanError):
            job.plan_options(job.Choices(dialect="mach3"))
        self.assertEqual(job.default_program("/b/x.kicad_pcb", "linuxcnc"), "/b/x-drill.ngc")
        self.assertEqual(job.default_program("/b/x.kicad_pcb", "haas"), "/b/x-drill.nc")

    def test_headless_arguments_in_any_order(self):
        from acodrill_kicad.__main__ import parse

        self.assertEqual(parse(["--machine", "router", "b.kicad_pcb", "-o", "x.nc", "--drill-files", "d"]),
                         ("b.kicad_pcb", "x.nc", "acodrill", "d", None, ["--machine", "router"]))
        self.assertEqual(parse(["board.pcb", "--acodrill", "/opt/acodrill", "--output=x.nc", "--origin=drill-origin"]),
                         ("board.pcb", "x.nc", "/opt/acodrill", None, "drill-origin", []))
        with self.assertRaises(SystemExit):
            parse(["--dialect", "grbl", "board.pcb", "-o", "x.nc"])

    def test_an_unset_drill_origin_is_named(self):
        self.assertIn("not set", job.origin_warning("drill-origin", (0.0, 0.0)))
        self.assertIsNone(job.origin_warning("drill-origin", (62.23, -153.67)))
        self.assertIsNone(job.origin_warning("lower-left", (0.0, 0.0)))

    def test_machine_list_is_acodrills(self):
        classes = dict(job.machine_classes(ACODRILL))
        self.assertIn("router", classes)
        self.assertIn("vf2", classes)
        self.assertEqual(job.machine_dialect("router", ACODRILL), "grbl")
        self.assertEqual(job.machine_dialect("vf2", ACODRILL), "haas")

    def test_summary_reads_the_report(self):
        report = {"holes": 3, "tools": [{"tool": 1, "diameter_mm": 0.8, "holes": 3}],
                  "travel_mm": {"input_order": 200.0, "nearest_neighbor": 120.0, "optimized": 100.0},
                  "machining_time_s": {"input_order": 600.0, "optimized": 300.0},
                  "time_split_s": {"optimized": {"moves": 60, "drilling": 120, "tool_changes": 60, "pauses": 60}}}
        text = job.summary(report)
        self.assertIn("3 holes, 1 tool: 0.800 mm x 3", text)
        self.assertIn("10.0 min in the board's order -> 5.0 min optimized (saves 50.0 %)", text)
        self.assertIn("Travel: 200 mm -> 100 mm (saves 50.0 %; nearest neighbour 120 mm)", text)
        self.assertIn("drilling 2.0 min", text)


@unittest.skipIf(pcbnew is None, "KiCad's pcbnew is not installed")
class DrillShapes(unittest.TestCase):
    """Issue 69: a slot is a pad whose drill shape is oblong, not any drill of
    unequal sizes: a round drill given 1 x 2 mm is drilled round at 1 mm, as
    KiCad's own drill writer drills it."""

    def test_a_round_drill_of_unequal_sizes_is_drilled_round_at_the_smaller(self):
        from acodrill_kicad.board import board_drills
        board = pcbnew.BOARD()
        fp = pcbnew.FOOTPRINT(board)
        board.Add(fp)
        for shape, x in ((pcbnew.PAD_DRILL_SHAPE_CIRCLE, 10), (pcbnew.PAD_DRILL_SHAPE_OBLONG, 20)):
            pad = pcbnew.PAD(fp)
            pad.SetAttribute(pcbnew.PAD_ATTRIB_PTH)
            pad.SetDrillShape(shape)
            pad.SetDrillSize(vector(1.0, 2.0, "size"))
            pad.SetSize(vector(2.0, 3.0, "size"))
            pad.SetPosition(vector(x, 10, "point"))
            fp.Add(pad)
        drills, _ = board_drills(board)
        by_x = {round(d.x_mm): d for d in drills}
        self.assertEqual(len(drills), 2)
        self.assertIsNone(by_x[10].slot_end, "round: no slot")
        self.assertAlmostEqual(by_x[10].diameter_mm, 1.0)
        self.assertAlmostEqual(by_x[10].y_mm, -10.0)
        self.assertIsNotNone(by_x[20].slot_end, "oblong: a slot")
        self.assertAlmostEqual(by_x[20].diameter_mm, 1.0)


@unittest.skipIf(pcbnew is None, "KiCad's pcbnew is not installed")
class AcrossKiCadVersions(unittest.TestCase):
    """Issue 69: whatever KiCad runs the plugin, the demo boards give the holes
    KiCad 6 gave (tests/data/kicad/BOARD.holes.csv, its round drills), and a
    board saved in this KiCad's own format (KiCad 9: front/inner/back pad
    stacks) gives the same drills as the file it was loaded from."""

    def test_the_demo_boards_give_kicad_6s_round_holes(self):
        from acodrill_kicad.board import board_drills
        for name in ("pic_programmer", "video", "StickHub", "kit-dev-coldfire-xilinx_5213"):
            with self.subTest(board=name):
                want = [tuple(float(v) for v in l.split(",")[:3]) for l in read(os.path.join(ROOT, "tests", "data", "kicad",
                                                                                                name + ".holes.csv")).splitlines()[1:]]
                drills, _ = board_drills(pcbnew.LoadBoard(demo(name)))
                got = [(d.x_mm, d.y_mm, d.diameter_mm) for d in drills if d.slot_end is None]
                self.assertEqual(len(got), len(want))
                unmatched, left = match([g[:2] for g in got], [w[:2] for w in want], 0.0011)
                self.assertEqual((unmatched, left), ([], []))
                self.assertEqual(sorted(round(g[2], 3) for g in got), sorted(round(w[2], 3) for w in want))

    def test_a_board_saved_in_this_kicads_format_gives_the_same_drills(self):
        from acodrill_kicad.board import board_drills
        board = pcbnew.LoadBoard(demo("video"))
        before, _ = board_drills(board)
        with tempfile.TemporaryDirectory() as t:
            path = os.path.join(t, "video-saved.kicad_pcb")
            pcbnew.SaveBoard(path, board)
            after, _ = board_drills(pcbnew.LoadBoard(path))
        self.assertEqual(sorted((round(d.x_mm, 6), round(d.y_mm, 6), round(d.diameter_mm, 6)) for d in after),
                         sorted((round(d.x_mm, 6), round(d.y_mm, 6), round(d.diameter_mm, 6)) for d in before))


class Links(unittest.TestCase):
    def test_the_setup_sheet_link_is_a_file_url_on_every_platform(self):
        self.assertEqual(job.file_url("C:\\Users\\Łukasz\\Documents\\a b.html"),
                         "file:///C:/Users/%C5%81ukasz/Documents/a%20b.html")
        self.assertEqual(job.file_url("/home/ola/płytka x.html"), "file:///home/ola/p%C5%82ytka%20x.html")

    def test_the_pcm_metadata_admits_kicad_9(self):
        meta = json.loads(read(os.path.join(PLUGIN_DIR, "metadata.json")))
        top = meta["versions"][0]["kicad_version_max"]
        self.assertGreaterEqual(tuple(int(p) for p in top.split(".")), (9, 0))
        with open(os.path.join(PLUGIN_DIR, "acodrill_kicad", "__main__.py"), encoding="utf-8") as f:
            self.assertIn("6 to 9", f.read())


class StartingAcodrill(unittest.TestCase):
    """Issue 73: on Windows no console window flashes over KiCad, and the
    output is read as UTF-8 whatever the system's code page."""

    def test_acodrill_starts_without_a_console_window_and_its_output_is_read_as_utf8(self):
        seen = []

        def fake_run(command, **kwargs):
            seen.append(kwargs)
            return subprocess.CompletedProcess(command, 0, "", "")

        real_run, real_name = job.subprocess.run, job.os.name
        try:
            job.subprocess.run = fake_run
            job.os.name = "nt"
            job._run(["acodrill", "machines"])
        finally:
            job.subprocess.run, job.os.name = real_run, real_name
        self.assertEqual(seen[0].get("creationflags"), 0x08000000)  # CREATE_NO_WINDOW
        self.assertEqual(seen[0].get("encoding"), "utf-8")
        # And for real: a name outside any ANSI code page comes back whole.
        with tempfile.TemporaryDirectory() as t:
            path = os.path.join(t, "基板_Łódź.csv")
            with open(path, "w", encoding="utf-8") as f:
                f.write("x,y,d\n0,0,1\n10,0,1\n")
            done = job.run_acodrill(ACODRILL, ["plan", path, "-o", os.path.join(t, "a.nc")])
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertIn("基板_Łódź.csv", done.stderr)


class Package(unittest.TestCase):
    def test_pcm_package_is_valid_and_loads_as_kicad_installs_it(self):
        import jsonschema

        schema = json.loads(read(os.path.join(ROOT, "tests", "data", "kicad", "pcm.v1.schema.json")))
        with tempfile.TemporaryDirectory() as d:
            zpath = os.path.join(d, "pcm.zip")
            subprocess.run(["/usr/bin/python3", os.path.join(PLUGIN_DIR, "make_pcm.py"), zpath], check=True)
            with zipfile.ZipFile(zpath) as archive:
                contents = {n: archive.read(n) for n in archive.namelist()}
            names = set(contents)
            for needed in ("metadata.json", "plugins/__init__.py", "plugins/action.py", "plugins/icon.png",
                           "resources/icon.png"):
                self.assertIn(needed, names)
            meta = json.loads(contents["metadata.json"])
            jsonschema.validate(meta, schema)
            broken = dict(meta)
            del broken["identifier"]
            with self.assertRaises(jsonschema.ValidationError):
                jsonschema.validate(broken, schema)
            cmake = read(os.path.join(ROOT, "CMakeLists.txt"))
            version = re.search(r"project\(acodrill VERSION ([0-9.]+)", cmake).group(1)
            self.assertEqual(meta["versions"][0]["version"], version, "metadata.json follows the project's version")
            # Rebuilt, the same bytes.
            again = os.path.join(d, "again.zip")
            subprocess.run(["/usr/bin/python3", os.path.join(PLUGIN_DIR, "make_pcm.py"), again], check=True)
            self.assertEqual(read(zpath, "rb"), read(again, "rb"))
            if pcbnew is None:
                return
            # KiCad's PCM puts plugins/ into 3rdparty/plugins/<identifier, dots as _>; pcbnew then loads it.
            third = os.path.join(d, "3rdparty")
            target = os.path.join(third, "plugins", meta["identifier"].replace(".", "_"))
            os.makedirs(target)
            for n in names:
                if n.startswith("plugins/"):
                    with open(os.path.join(target, n[len("plugins/"):]), "wb") as f:
                        f.write(contents[n])
            code = (
                "import pcbnew, sys\n"
                "seen = []\n"
                # Headless there is no KiCad program to hold the action: record the registration.
                "pcbnew.PYTHON_ACTION_PLUGINS.register_action = staticmethod(lambda p: seen.append(p))\n"
                f"pcbnew.LoadPlugins('{d}/none', '{d}/user', '{third}/plugins')\n"
                "print([(p.GetName(), p.GetCategoryName()) for p in seen])\n"
                "print(pcbnew.NOT_LOADED_WIZARDS)\n")
            done = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True, cwd=d)
            self.assertIn("[('Drill with acodrill', 'Fabrication')]", done.stdout, done.stdout + done.stderr)

    def test_windows_package_carries_acodrill_and_the_plugin_finds_it_beside_itself(self):
        # Issue 54: scripts/windows packs acodrill.exe with the plugin; here the
        # Linux binary stands in for it (the packing and the finding are the same).
        import jsonschema

        schema = json.loads(read(os.path.join(ROOT, "tests", "data", "kicad", "pcm.v1.schema.json")))
        with tempfile.TemporaryDirectory() as d:
            binary = os.path.join(d, "acodrill.exe")
            shutil.copy(ACODRILL, binary)
            zpath = os.path.join(d, "win.zip")
            subprocess.run(["/usr/bin/python3", os.path.join(PLUGIN_DIR, "make_pcm.py"), zpath, "--platform", "windows",
                            "--binary", binary], check=True)
            with zipfile.ZipFile(zpath) as archive:
                contents = {n: archive.read(n) for n in archive.namelist()}
            self.assertIn("plugins/acodrill.exe", contents)
            self.assertEqual(contents["plugins/acodrill.exe"], read(ACODRILL, "rb"))
            meta = json.loads(contents["metadata.json"])
            jsonschema.validate(meta, schema)
            self.assertEqual(meta["versions"][0]["platforms"], ["windows"])
            self.assertNotIn("Debian package", meta["description_full"])
            # Unpacked as the PCM does, with no acodrill on PATH: the plugin runs the one beside it.
            folder = os.path.join(d, "plugin")
            os.makedirs(folder)
            for n, data in contents.items():
                if n.startswith("plugins/"):
                    with open(os.path.join(folder, n[len("plugins/"):]), "wb") as f:
                        f.write(data)
            os.chmod(os.path.join(folder, "acodrill.exe"), 0o755)
            os.makedirs(os.path.join(d, "pkg"))
            os.symlink(folder, os.path.join(d, "pkg", "acodrill_kicad"))
            code = ("import sys; sys.path.insert(0, sys.argv[1]); from acodrill_kicad import job\n"
                    "print(job.find_acodrill('acodrill')); print(dict(job.machine_classes())['router'][:7])\n")
            done = subprocess.run(["/usr/bin/python3", "-c", code, os.path.join(d, "pkg")], capture_output=True, text=True,
                                  env={"PATH": os.path.join(d, "empty")})
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertEqual(done.stdout.splitlines(), [os.path.join(d, "pkg", "acodrill_kicad", "acodrill.exe"), "desktop"])


if __name__ == "__main__":
    unittest.main(verbosity=2)
