#!/usr/bin/env python3
"""Issue 86: an IPC-2581 file's holes listed by a reader of our own (Python's
ElementTree, no code shared with acodrill's): every <Hole> under the
LayerFeatures of the layers whose layerFunction is DRILL, in CadHeader units,
for a file of one step and no StepRepeat. It checks `acodrill holes FILE` lists
the same (within 1 µm):  usage  ipc2581_holes.py ACODRILL FILE[.gz]"""
import csv
import gzip
import io
import subprocess
import sys
import xml.etree.ElementTree as ET


def local(tag):
    return tag.rsplit("}", 1)[-1]


def holes(path):
    data = gzip.open(path).read() if path.endswith(".gz") else open(path, "rb").read()
    root = ET.fromstring(data)
    unit = {"MILLIMETER": 1.0, "MICRON": 0.001, "INCH": 25.4}
    scale = 1.0
    drill_layers = set()
    steps = []
    for e in root.iter():
        name = local(e.tag)
        if name == "CadHeader":
            scale = unit[e.get("units", "MILLIMETER")]
        elif name == "Layer" and e.get("layerFunction") == "DRILL":
            drill_layers.add(e.get("name"))
        elif name == "Step":
            steps.append(e)
    assert len(steps) == 1 and not any(local(c.tag) == "StepRepeat" for c in steps[0]), "one flat step"
    out = []
    for feature in steps[0]:
        if local(feature.tag) != "LayerFeature" or feature.get("layerRef") not in drill_layers:
            continue
        for h in feature.iter():
            if local(h.tag) == "Hole":
                out.append((float(h.get("x")) * scale, float(h.get("y")) * scale, float(h.get("diameter")) * scale))
    return out


def main():
    acodrill, path = sys.argv[1], sys.argv[2]
    mine = sorted(set((round(x, 6), round(y, 6), round(d, 6)) for x, y, d in holes(path)))
    listed = subprocess.run([acodrill, "holes", path, "--format", "csv", "-q"], capture_output=True, text=True, check=True)
    theirs = sorted((float(r["x_mm"]), float(r["y_mm"]), float(r["diameter_mm"])) for r in csv.DictReader(io.StringIO(listed.stdout)))
    assert len(mine) == len(theirs), (len(mine), len(theirs))
    worst = max(max(abs(a - b) for a, b in zip(m, t)) for m, t in zip(mine, theirs))
    assert worst <= 0.001, worst
    print(f"{path}: {len(mine)} holes, the same within {worst * 1000:.4f} µm")


if __name__ == "__main__":
    main()
