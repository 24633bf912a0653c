"""What the independent readers (odb_holes.py, ipc2581_holes.py) share: their
holes against `acodrill holes FILE`, within 1 µm."""
import csv
import io
import subprocess


def expect_listed(acodrill, path, mine):
    """`mine`: (x, y, diameter) mm. acodrill drops exact duplicates; so does the comparison."""
    mine = sorted(set((round(x, 6), round(y, 6), round(d, 6)) for x, y, d in mine))
    listed = subprocess.run([acodrill, "holes", path, "--format", "csv", "-q"], capture_output=True, text=True, check=True)
    theirs = sorted((float(r["x_mm"]), float(r["y_mm"]), float(r["diameter_mm"])) for r in csv.DictReader(io.StringIO(listed.stdout)))
    assert len(mine) == len(theirs), (len(mine), len(theirs))
    worst = max(max(abs(a - b) for a, b in zip(m, t)) for m, t in zip(mine, theirs))
    assert worst <= 0.001, worst
    print(f"{path}: {len(mine)} holes, the same within {worst * 1000:.4f} µm")
