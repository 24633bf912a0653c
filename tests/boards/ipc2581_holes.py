#!/usr/bin/env python3
"""Issue 86: an IPC-2581 file's holes listed by a reader of our own (Python's
ElementTree, no code shared with acodrill's): every <Hole> under the
LayerFeatures of the layers whose layerFunction is DRILL, in CadHeader units,
for a file of one step and no StepRepeat. It checks `acodrill holes FILE` lists
the same (within 1 µm):  usage  ipc2581_holes.py ACODRILL FILE[.gz]"""
import gzip
import sys
import xml.etree.ElementTree as ET

from listed import expect_listed  # noqa: E402 (beside this script)


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
    expect_listed(sys.argv[1], sys.argv[2], holes(sys.argv[2]))


if __name__ == "__main__":
    main()
