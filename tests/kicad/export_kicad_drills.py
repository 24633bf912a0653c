#!/usr/bin/python3
"""Exports real boards' drill files with KiCad's own Excellon writer, together
with the hole list read from the board itself, as test data for the Excellon
reader. Run by hand (CI needs no KiCad): its output is committed.

    apt-get install kicad kicad-demos        # KiCad 6 and its demo boards
    /usr/bin/python3 tests/kicad/export_kicad_drills.py tests/data/kicad

For each board it writes BOARD-<variant>.drl for four formats (inch and metric,
decimal and zero-suppressed) and BOARD.holes.csv: every round drill of a pad
or via, in mm, with Y negated as KiCad's drill writer does with the default
origin. Oval (slotted) drills are written by KiCad as G85 slots and are not
drill hits, so they are not listed.
"""
import glob
import os
import shutil
import sys
import tempfile

import pcbnew

BOARDS = ["pic_programmer", "video", "kit-dev-coldfire-xilinx_5213", "StickHub"]
VARIANTS = [
    ("inch-decimal", False, pcbnew.GENDRILL_WRITER_BASE.DECIMAL_FORMAT, 2, 4),
    ("mm-decimal", True, pcbnew.GENDRILL_WRITER_BASE.DECIMAL_FORMAT, 3, 3),
    ("inch-suppress-leading", False, pcbnew.GENDRILL_WRITER_BASE.SUPPRESS_LEADING, 2, 4),
    ("mm-suppress-trailing", True, pcbnew.GENDRILL_WRITER_BASE.SUPPRESS_TRAILING, 3, 3),
]


def board_holes(board):
    holes = []
    to_mm = 1.0 / pcbnew.IU_PER_MM
    for fp in board.GetFootprints():
        for pad in fp.Pads():
            size = pad.GetDrillSize()
            if size.x <= 0:
                continue
            if pad.GetDrillShape() != pcbnew.PAD_DRILL_SHAPE_CIRCLE or size.x != size.y:
                continue  # a slot
            p = pad.GetPosition()
            holes.append((p.x * to_mm, -p.y * to_mm, size.x * to_mm))
    for track in board.GetTracks():
        if track.Type() == pcbnew.PCB_VIA_T:
            p = track.GetPosition()
            holes.append((p.x * to_mm, -p.y * to_mm, track.GetDrillValue() * to_mm))
    return holes


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "tests/data/kicad"
    os.makedirs(out, exist_ok=True)
    demos = "/usr/share/kicad/demos"
    for name in BOARDS:
        found = glob.glob(os.path.join(demos, "**", name + ".kicad_pcb"), recursive=True)
        if not found:
            print("not found:", name)
            continue
        board = pcbnew.LoadBoard(found[0])
        holes = board_holes(board)
        with open(os.path.join(out, name + ".holes.csv"), "w") as f:
            f.write("x_mm,y_mm,diameter_mm\n")
            for x, y, d in holes:
                f.write(f"{x:.6f},{y:.6f},{d:.6f}\n")
        for variant, metric, zeros, left, right in VARIANTS:
            tmp = tempfile.mkdtemp()
            writer = pcbnew.EXCELLON_WRITER(board)
            writer.SetOptions(False, False, pcbnew.wxPoint(0, 0), True)  # no mirror, full header, origin, merge PTH/NPTH
            writer.SetFormat(metric, zeros, left, right)
            writer.CreateDrillandMapFilesSet(tmp, True, False)
            files = glob.glob(os.path.join(tmp, "*.drl"))
            if len(files) != 1:
                raise SystemExit(f"{name} {variant}: expected one drill file, got {files}")
            shutil.copy(files[0], os.path.join(out, f"{name}-{variant}.drl"))
            shutil.rmtree(tmp)
        print(f"{name}: {len(holes)} holes")


if __name__ == "__main__":
    main()
