"""Everything the dialog and the headless command do, outside any window:
the choices made into `acodrill plan` arguments, the board's drills written
where acodrill reads them, acodrill run, and its report made into a summary.

Only the installed `acodrill` plans: this package never orders holes itself.
"""
import json
import os
import pathlib
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field
from typing import List, Optional, Sequence, Tuple

from .drills import Drill, excellon_text

# Program zero choices: acodrill's --origin values, and the board's drill/place file origin.
ORIGINS = [
    ("lower-left", "Lower left of the holes"),
    ("center", "Centre of the holes"),
    ("upper-left", "Upper left of the holes"),
    ("drill-origin", "The board's drill/place file origin"),
]
DIALECTS = ["haas", "fanuc", "linuxcnc", "grbl", "marlin"]
PROGRAM_EXTENSIONS = {"linuxcnc": ".ngc", "grbl": ".gcode", "marlin": ".gcode"}


class PlanError(Exception):
    """A failure the user must read: `line` is one `acodrill: error: ...` line; `code` the exit code."""

    def __init__(self, line: str, code: int = 2):
        super().__init__(line)
        self.line = line
        self.code = code


@dataclass
class Choices:
    """What the dialog asks. Empty strings: acodrill's own defaults."""

    machine: str = "router"          # a class of `acodrill machines`, or a machine file
    dialect: str = ""                # "": the machine's
    origin: str = "lower-left"
    plated_apart: bool = False       # plated and non-plated holes with tools of their own, plated first
    time_limit_s: float = 10.0
    program: str = ""                # "": beside the board (default_program)
    write_setup_sheet: bool = True   # PROGRAM-setup.html beside the program
    # The tools on the bench (issue 53): "" / 0 / False leave them to acodrill and the machine profile.
    drills: str = ""                 # the drills owned, "0.6,0.8,1.0,1.2" (--drills)
    end_mill_mm: float = 0.0         # an end mill for what no drill fits (--end-mill)
    from_back: bool = False          # drill the board from its back (--side back)
    probe_plate_mm: float = 0.0      # a touch plate's thickness (--probe-plate)
    extra: List[str] = field(default_factory=list)  # further `acodrill plan` options


def file_url(path: str) -> str:
    """A file:// URL for a local file on any platform, for the browser to open:
    "C:\\Users\\Łukasz\\a b.html" -> "file:///C:/Users/%C5%81ukasz/a%20b.html"
    (a drive letter and backslashes are no URL as they are; letters and blanks escaped)."""
    if re.match(r"^[A-Za-z]:[\\/]", path) or path.startswith("\\\\"):
        return pathlib.PureWindowsPath(path).as_uri()
    return pathlib.Path(os.path.abspath(path)).as_uri()


def default_program(board_path: str, dialect: str) -> str:
    """The program beside the board: BOARD-drill.nc (.ngc for LinuxCNC, .gcode for GRBL and Marlin)."""
    return os.path.splitext(board_path)[0] + "-drill" + PROGRAM_EXTENSIONS.get(dialect, ".nc")


def plan_options(choices: Choices, drill_origin_xy: Optional[Tuple[float, float]] = None) -> List[str]:
    """The `acodrill plan` options for the choices (inputs and outputs aside)."""
    args: List[str] = []
    if choices.machine:
        args += ["--machine", choices.machine]
    if choices.dialect:
        if choices.dialect not in DIALECTS:
            raise PlanError(f"acodrill: error: dialect must be one of {', '.join(DIALECTS)} (got \"{choices.dialect}\")")
        args += ["--dialect", choices.dialect]
    args += ["--origin", resolve_origin(choices.origin, drill_origin_xy)]
    if choices.plated_apart:
        args.append("--keep-files-apart")
    if choices.time_limit_s and choices.time_limit_s > 0:
        args += ["--time-limit", f"{choices.time_limit_s:g}"]
    if choices.drills.strip():
        args += ["--drills", "".join(choices.drills.split())]
    if choices.end_mill_mm and choices.end_mill_mm > 0:
        args += ["--end-mill", f"{choices.end_mill_mm:g}"]
    if choices.from_back:
        args += ["--side", "back"]
    if choices.probe_plate_mm and choices.probe_plate_mm > 0:
        args += ["--probe-plate", f"{choices.probe_plate_mm:g}"]
    return args + list(choices.extra)


def resolve_origin(origin: str, drill_origin_xy: Optional[Tuple[float, float]]) -> str:
    """acodrill's --origin for a choice: "drill-origin" becomes the board's drill/place file origin as X,Y."""
    if origin in ("drill-origin", "aux"):
        if drill_origin_xy is None:
            raise PlanError("acodrill: error: --origin drill-origin needs the board")
        return f"{drill_origin_xy[0]:.6f},{drill_origin_xy[1]:.6f}"
    return origin


def origin_warning(origin: str, drill_origin_xy: Optional[Tuple[float, float]]) -> Optional[str]:
    """A word when program zero is the drill/place file origin and the board never set one."""
    if origin in ("drill-origin", "aux") and drill_origin_xy is not None and drill_origin_xy == (0.0, 0.0):
        return ("the board's drill/place file origin is not set (it is the page's corner): set it in pcbnew "
                "(Place > Drill/Place File Origin) or choose another program zero")
    return None


def machine_classes(acodrill: str = "acodrill") -> List[Tuple[str, str]]:
    """`acodrill machines`: (name, description) a line."""
    out = run_acodrill(acodrill, ["machines"]).stdout
    classes = []
    for line in out.splitlines():
        if "\t" in line:
            name, description = line.split("\t", 1)
            classes.append((name.strip(), description.strip()))
    return classes


def find_acodrill(acodrill: str) -> str:
    """The acodrill binary: a path as given, or a name found on PATH, or the
    one the package carries beside the plugin (KiCad's Windows package)."""
    found = acodrill if os.sep in acodrill or (os.altsep and os.altsep in acodrill) else shutil.which(acodrill)
    if not found and acodrill == "acodrill":
        here = os.path.dirname(os.path.abspath(__file__))
        for name in ("acodrill.exe", "acodrill"):
            beside = os.path.join(here, name)
            if os.path.isfile(beside) and (os.name == "nt" or os.access(beside, os.X_OK)):
                found = beside
                break
    if not found or not os.access(found, os.X_OK):
        raise PlanError(f"acodrill: error: {acodrill}: acodrill is not installed or not executable; "
                        "install it (apt install ./acodrill_*.deb) or give --acodrill PATH")
    return found


def _run(command: Sequence[str]) -> subprocess.CompletedProcess:
    """acodrill started as the plugin needs it: no input, its output read as
    the UTF-8 it writes (not the system's ANSI code page), and on Windows
    without a console window flashing over KiCad at every run."""
    options = {}
    if os.name == "nt":
        options["creationflags"] = getattr(subprocess, "CREATE_NO_WINDOW", 0x08000000)
    return subprocess.run(list(command), stdin=subprocess.DEVNULL, capture_output=True, text=True, encoding="utf-8",
                          errors="replace", **options)


def run_acodrill(acodrill: str, args: Sequence[str]) -> subprocess.CompletedProcess:
    return _run([find_acodrill(acodrill)] + list(args))


def write_drill_files(drills: Sequence[Drill], folder: str, stem: str) -> List[str]:
    """STEM-PTH.drl and STEM-NPTH.drl in `folder` (only those with holes): the
    paths, plated first, as KiCad names its own drill files."""
    paths = []
    for plated, suffix in ((True, "PTH"), (False, "NPTH")):
        text = excellon_text(drills, plated, stem)
        if not text:
            continue
        path = os.path.join(folder, f"{stem}-{suffix}.drl")
        with open(path + ".tmp", "w", encoding="ascii") as f:
            f.write(text)
        os.replace(path + ".tmp", path)
        paths.append(path)
    return paths


@dataclass
class PlanRun:
    code: int
    stdout: str
    stderr: str
    report: Optional[dict]


def plan(drills: Sequence[Drill], board_path: str, program: str, options: Sequence[str], acodrill: str = "acodrill",
         drill_files_dir: Optional[str] = None) -> PlanRun:
    """Writes the board's drill files (into `drill_files_dir`, or a temporary
    folder removed afterwards) and runs `acodrill plan` on them. The run's
    report is read back (a temporary one when the options ask for none)."""
    if not drills:
        raise PlanError(f"acodrill: error: {board_path}: the board has no drilled pads or vias")
    binary = find_acodrill(acodrill)
    stem = os.path.splitext(os.path.basename(board_path))[0]
    work = tempfile.mkdtemp(prefix="acodrill-kicad-")
    try:
        folder = drill_files_dir or work
        os.makedirs(folder, exist_ok=True)
        inputs = write_drill_files(drills, folder, stem)
        options = list(options)
        report_path = _option_value(options, "--report")
        own_report = report_path is None
        if own_report:
            report_path = os.path.join(work, "report.json")
            options += ["--report", report_path]
        done = _run([binary, "plan"] + inputs + ["-o", program] + options)
        stderr = done.stderr
        if own_report:  # the summary's report is ours, not the user's: not named
            stderr = "".join(l for l in stderr.splitlines(True) if l.rstrip("\n") != f"  report: {report_path}")
        # The drill files are acodrill's inputs, not the user's: messages name them, not a temporary folder.
        stderr = stderr.replace(work + os.sep, "")
        report = None
        if done.returncode == 0 and report_path != "-" and os.path.exists(report_path):
            with open(report_path, encoding="utf-8") as f:
                report = json.load(f)
        return PlanRun(done.returncode, done.stdout, stderr, report)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def _option_value(options: Sequence[str], name: str) -> Optional[str]:
    for k, o in enumerate(options):
        if o == name and k + 1 < len(options):
            return options[k + 1]
        if o.startswith(name + "="):
            return o[len(name) + 1:]
    return None


def error_line(stderr: str) -> str:
    """acodrill's own error line from its stderr (the last `acodrill: error:` line), or its last line."""
    lines = [l for l in stderr.splitlines() if l.strip()]
    errors = [l for l in lines if l.startswith("acodrill: error:")]
    return errors[-1] if errors else (lines[-1] if lines else "acodrill: error: acodrill failed without a message")


def summary(report: dict) -> str:
    """The plan as a shop engineer reads it: holes and tools, travel and time
    before and after, and where the time goes."""
    tools = report.get("tools", [])
    travel = report.get("travel_mm", {})
    time_s = report.get("machining_time_s", {})
    split = report.get("time_split_s", {}).get("optimized", {})

    def minutes(s):
        return f"{s / 60:.1f} min"

    def saved(before, after):
        return f"{100.0 * (before - after) / before:.1f} %" if before > 0 else "-"

    drills = ", ".join(f"{t['diameter_mm']:.3f} mm{' end mill' if t.get('kind') == 'end_mill' else ''} x {t['holes']}"
                       for t in tools)
    before_t, after_t = time_s.get("input_order", 0.0), time_s.get("optimized", 0.0)
    before_d, after_d = travel.get("input_order", 0.0), travel.get("optimized", 0.0)
    lines = [
        f"{report.get('holes', 0)} holes, {len(tools)} tool{'s' if len(tools) != 1 else ''}: {drills}",
        f"Time:   {minutes(before_t)} in the board's order -> {minutes(after_t)} optimized (saves {saved(before_t, after_t)})",
        f"Travel: {before_d:.0f} mm -> {after_d:.0f} mm (saves {saved(before_d, after_d)}; nearest neighbour "
        f"{travel.get('nearest_neighbor', 0.0):.0f} mm)",
        "Where the time goes: " + ", ".join(f"{label} {minutes(split.get(key, 0.0))}" for key, label in
                                            (("moves", "moves"), ("drilling", "drilling"),
                                             ("tool_changes", "tool changes"), ("pauses", "pauses"))),
    ]
    # The tools you own: which drill makes which designed diameter, and by how much it differs.
    for d in report.get("drill_map", []):
        made = (f"milled with the {d['tool_diameter_mm']:.3f} mm end mill" if d.get("made_as") == "milled" else
                f"{d['tool_diameter_mm']:.3f} mm drill ({d.get('oversize_mm', 0.0):+.3f})")
        lines.append(f"  {d['designed_mm']:.3f} mm x {d['holes']}: T{d['tool']} {made}")
    return "\n".join(lines)


def machine_dialect(machine: str, acodrill: str = "acodrill") -> str:
    """The dialect a machine's control reads: from its profile file, or `acodrill machines --show NAME`."""
    try:
        if os.path.isfile(machine):
            with open(machine, encoding="utf-8") as f:
                return json.load(f).get("dialect", "haas")
        done = run_acodrill(acodrill, ["machines", "--show", machine])
        return json.loads(done.stdout).get("dialect", "haas") if done.returncode == 0 else "haas"
    except (OSError, ValueError, AttributeError):
        return "haas"  # acodrill names the bad profile when it plans


@dataclass
class Outcome:
    """What the dialog shows after Plan: the summary, or acodrill's own error line."""

    ok: bool
    text: str
    program: str = ""
    setup_sheet: str = ""


def plan_for_dialog(drills: Sequence[Drill], warnings: Sequence[str], drill_origin_xy: Tuple[float, float],
                    board_path: str, choices: Choices, acodrill: str = "acodrill") -> Outcome:
    """The dialog's Plan button: the program (and setup sheet) beside the board
    unless the choices name other paths, then the summary."""
    try:
        dialect = choices.dialect or machine_dialect(choices.machine, acodrill)
        program = choices.program or default_program(board_path, dialect)
        # The sheet goes beside the program: BOARD-drill.nc, BOARD-drill-setup.html.
        sheet = os.path.splitext(program)[0] + "-setup.html" if choices.write_setup_sheet else ""
        options = plan_options(choices, drill_origin_xy) + ["--quiet"]
        if sheet:
            options += ["--setup-sheet", sheet]
        done = plan(drills, board_path, program, options, acodrill)
    except PlanError as e:
        return Outcome(False, e.line)
    if done.code != 0:
        return Outcome(False, error_line(done.stderr))
    text = summary(done.report or {})
    text += f"\nProgram: {program}" + (f"\nSetup sheet: {sheet}" if sheet else "")
    unset_origin = origin_warning(choices.origin, drill_origin_xy)
    for w in list(warnings) + ([unset_origin] if unset_origin else []):
        text += f"\nWarning: {w}"
    return Outcome(True, text, program, sheet)
