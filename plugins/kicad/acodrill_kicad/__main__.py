"""The plugin without a screen: what the dialog writes, from a .kicad_pcb.

    /usr/bin/python3 -m acodrill_kicad BOARD.kicad_pcb -o PROGRAM [--acodrill PATH]
        [--drill-files DIR] [any acodrill plan option]

Exit codes and error lines are acodrill's: 0 done, 2 a usage or input error
with one line `acodrill: error: ...` on stderr.
"""
import os
import re
import sys

HELP = """usage: /usr/bin/python3 -m acodrill_kicad BOARD.kicad_pcb -o PROGRAM [--acodrill PATH]
                                        [--drill-files DIR] [acodrill plan options ...]

Plans the drilling of a KiCad board (6 to 9) with acodrill: the holes are the
board's own pads (plated and non-plated, round and oval) and through vias, read
by KiCad's pcbnew at their exact positions, written as Excellon drill files
(BOARD-PTH.drl, BOARD-NPTH.drl) and planned by `acodrill plan` into PROGRAM
(- for standard output). This is what Tools > External Plugins > "Drill with
acodrill" does in pcbnew, for scripts, pipelines and KiCad 6, which has no kicad-cli.

  -o, --output PROGRAM   the program to write (required)
  --acodrill PATH        the acodrill binary (default: acodrill on PATH)
  --drill-files DIR      keep the drill files written from the board in DIR
                         (e.g. for `acodrill verify PROGRAM --holes DIR/BOARD-PTH.drl ...`)
  --origin drill-origin  program zero at the board's drill/place file origin
                         (besides acodrill's lower-left, center, upper-left, X,Y)

Every other option goes to `acodrill plan` as it is: --machine router, --dialect grbl,
--setup-sheet SHEET.html, --report R.json, --keep-files-apart (plated and
non-plated holes with tools of their own), --time-limit S, --slots skip, -q, ...
See `acodrill plan --help`.

Examples:
  /usr/bin/python3 -m acodrill_kicad video.kicad_pcb -o video.gcode --machine router --setup-sheet video.html
  /usr/bin/python3 -m acodrill_kicad board.kicad_pcb -o - --dialect linuxcnc -q > board.ngc
"""


def parse(argv):
    board = program = None
    acodrill = "acodrill"
    drill_files = None
    origin = None
    rest = []
    k = 0

    def value(name):
        nonlocal k
        if k + 1 >= len(argv):
            raise SystemExit(_usage(f"{name} needs a value"))
        k += 1
        return argv[k]

    while k < len(argv):
        a = argv[k]
        if a in ("-h", "--help"):
            sys.stdout.write(HELP)
            raise SystemExit(0)
        if a in ("-o", "--output"):
            program = value(a)
        elif a.startswith("--output="):
            program = a.split("=", 1)[1]
        elif a == "--acodrill":
            acodrill = value(a)
        elif a == "--drill-files":
            drill_files = value(a)
        elif a == "--origin":
            origin = value(a)
        elif a.startswith("--origin="):
            origin = a.split("=", 1)[1]
        elif board is None and a.lower().endswith(".kicad_pcb"):
            board = a
        else:
            rest.append(a)
        k += 1
    if board is None:
        # A board file named otherwise: the first argument that is no option's value.
        plain = [a for a in rest if not a.startswith("-")]
        if rest and not rest[0].startswith("-"):
            board = rest.pop(0)
        elif plain:
            raise SystemExit(_usage("give the board first, or a file ending in .kicad_pcb"))
    if board is None:
        raise SystemExit(_usage("give the board: BOARD.kicad_pcb"))
    if program is None:
        raise SystemExit(_usage("give the program to write: -o PROGRAM"))
    return board, program, acodrill, drill_files, origin, rest


def _usage(message):
    sys.stderr.write(f"acodrill: error: {message} (see /usr/bin/python3 -m acodrill_kicad --help)\n")
    return 2


def main(argv=None):
    from . import job

    board_path, program, acodrill, drill_files, origin, rest = parse(sys.argv[1:] if argv is None else argv)
    try:
        if not os.path.isfile(board_path):
            raise job.PlanError(f"acodrill: error: {board_path}: no such board file")
        job.find_acodrill(acodrill)  # before loading KiCad: a missing binary is said at once
        board = load_board(board_path)
        from .board import board_drills, drill_origin

        drills, warnings = board_drills(board)
        options = list(rest)
        if origin is not None:
            options += ["--origin", job.resolve_origin(origin, drill_origin(board))]
            unset_origin = job.origin_warning(origin, drill_origin(board))
            if unset_origin:
                warnings.append(unset_origin)
        quiet = "-q" in rest or "--quiet" in rest
        if not quiet:
            for w in warnings:
                sys.stderr.write(f"acodrill: warning: {board_path}: {w}\n")
        done = job.plan(drills, board_path, program, options, acodrill, drill_files)
    except job.PlanError as e:
        sys.stderr.write(e.line + "\n")
        return e.code
    sys.stdout.write(done.stdout)
    sys.stderr.write(done.stderr)
    return done.code


def load_board(path):
    from . import job

    try:
        import pcbnew
    except ImportError:
        raise job.PlanError("acodrill: error: KiCad's pcbnew Python module is not installed "
                            "(apt install kicad; run with /usr/bin/python3)")
    try:
        board = pcbnew.LoadBoard(path)
    except Exception as e:  # pcbnew raises IOError and others with KiCad's own message
        message = " ".join(str(e).split()) or type(e).__name__
        line = re.search(r"\bline (\d+)", message)
        where = f"{path}:{line.group(1)}" if line else path
        raise job.PlanError(f"acodrill: error: {where}: KiCad cannot read the board: {message}")
    if board is None:
        raise job.PlanError(f"acodrill: error: {path}: KiCad cannot read the board")
    return board


if __name__ == "__main__":
    sys.exit(main())
