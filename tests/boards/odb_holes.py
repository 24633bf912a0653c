#!/usr/bin/env python3
"""Issue 86: an ODB++ job's holes listed by a reader of our own, apart from
acodrill's: a flat job (no step-and-repeat) whose drill layers hold round
pads. It lists them, then checks `acodrill holes JOB` lists the same
(within 1 µm): usage  odb_holes.py ACODRILL JOB_FOLDER
"""
import os
import re
import sys

from listed import expect_listed  # noqa: E402 (beside this script)


def drill_layers(job):
    text = open(os.path.join(job, "matrix", "matrix"), encoding="utf-8").read()
    layers = []
    for block in re.findall(r"LAYER\s*\{(.*?)\}", text, re.S):
        fields = dict(line.strip().split("=", 1) for line in block.splitlines() if "=" in line)
        if fields.get("TYPE") == "DRILL" and fields.get("CONTEXT") == "BOARD":
            layers.append(fields["NAME"].lower())
    steps = re.findall(r"STEP\s*\{[^}]*NAME=(\S+)", text)
    return layers, [s.lower() for s in steps]


def holes(job):
    layers, steps = drill_layers(job)
    assert len(steps) == 1, steps
    out = []
    for layer in layers:
        path = os.path.join(job, "steps", steps[0], "layers", layer, "features")
        unit, symbols = 25.4, {}
        for line in open(path, encoding="utf-8"):
            words = line.split(";")[0].split()
            if not words:
                continue
            if words[0].startswith("UNITS="):
                unit = 1.0 if words[0][6:] == "MM" else 25.4
            elif words[0].startswith("$"):
                symbols[int(words[0][1:])] = words[1]
            elif words[0] == "P":
                symbol = symbols[int(words[3])]
                assert symbol.startswith("r"), symbol
                size = float(symbol[1:]) * (0.001 if unit == 1.0 else 0.0254)
                out.append((float(words[1]) * unit, float(words[2]) * unit, size))
    return sorted(out)


def main():
    expect_listed(sys.argv[1], sys.argv[2], holes(sys.argv[2]))


if __name__ == "__main__":
    main()
