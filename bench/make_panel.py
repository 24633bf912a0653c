#!/usr/bin/env python3
"""Writes a PCB-panel DXF with many holes in a few hundred bytes: a 10 x 10
block of 0.8 mm holes at 2.54 mm pitch, MINSERTed as an array. The default,
100 x 100 cells, is the million-hole panel of the scale test:

    python3 bench/make_panel.py /tmp/panel1m.dxf            # 1 000 000 holes
    python3 bench/make_panel.py /tmp/panel10k.dxf 10 10     #    10 000 holes
    acodrill plan /tmp/panel1m.dxf -o panel.nc --machine big.json --material pcb
"""
import sys


def main():
    if any(a in ("-h", "--help") for a in sys.argv[1:]):
        print(__doc__)
        return
    path = sys.argv[1] if len(sys.argv) > 1 else "panel1m.dxf"
    cols = int(sys.argv[2]) if len(sys.argv) > 2 else 100
    rows = int(sys.argv[3]) if len(sys.argv) > 3 else 100
    cell = "".join(f"0\nCIRCLE\n8\n0\n10\n{i * 2.54:.3f}\n20\n{j * 2.54:.3f}\n30\n0\n40\n0.4\n"
                   for i in range(10) for j in range(10))
    text = ("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n"
            "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nCELL\n70\n0\n10\n0\n20\n0\n30\n0\n" + cell +
            "0\nENDBLK\n8\n0\n0\nENDSEC\n"
            "0\nSECTION\n2\nENTITIES\n"
            f"0\nINSERT\n8\nDRILL\n2\nCELL\n10\n5\n20\n5\n30\n0\n70\n{cols}\n71\n{rows}\n44\n26\n45\n26\n"
            "0\nENDSEC\n0\nEOF\n")
    with open(path, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
