#!/usr/bin/env python3
"""Writes a panel of COLS x ROWS copies of a TSPLIB instance as one instance:
a board's drilling repeated on a panel, with GAP units between copies. The
metric (EDGE_WEIGHT_TYPE) is kept. The scale section of scripts/benchmarks
tiles pla7397 (a programmed logic array's drilling) five times, 36 985 holes:

    python3 bench/make_tiled.py bench/tsplib/pla7397.tsp /tmp/pla7397x5.tsp 5 1

No optimum is known for the panel; COLS x ROWS times the board's optimum is
a reference, not a bound: it leaves out the moves between copies, and copies
side by side may share a cheaper route than one board's.
"""
import sys


def main():
    if len(sys.argv) not in (5, 6) or any(a in ("-h", "--help") for a in sys.argv[1:]):
        print(__doc__)
        sys.exit(0 if any(a in ("-h", "--help") for a in sys.argv[1:]) else 2)
    src, dst, cols, rows = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    gap = float(sys.argv[5]) if len(sys.argv) == 6 else 20000.0
    name, metric, points, in_coords = "tiled", "EUC_2D", [], False
    with open(src) as f:
        for number, line in enumerate(f, 1):
            words = line.replace(":", " : ", 1).split()
            if not words:
                continue
            if in_coords:
                if words[0] == "EOF":
                    break
                try:
                    points.append((float(words[1]), float(words[2])))
                except (IndexError, ValueError):
                    sys.exit(f"{src}:{number}: expected 'number x y'")
            elif words[0] == "NAME":
                name = words[-1]
            elif words[0] == "EDGE_WEIGHT_TYPE":
                metric = words[-1]
            elif words[0] == "NODE_COORD_SECTION":
                in_coords = True
    if not points:
        sys.exit(f"{src}: no NODE_COORD_SECTION")
    min_x, min_y = min(x for x, _ in points), min(y for _, y in points)
    width = max(x for x, _ in points) - min_x + gap
    height = max(y for _, y in points) - min_y + gap
    lines = [f"NAME : {name}x{cols}x{rows}", "TYPE : TSP", f"DIMENSION : {len(points) * cols * rows}",
             f"EDGE_WEIGHT_TYPE : {metric}", "NODE_COORD_SECTION"]
    def text(v):  # whole numbers as they were given; others in full
        return str(int(v)) if v == int(v) else repr(v)

    k = 1
    for i in range(cols):
        for j in range(rows):
            for x, y in points:
                lines.append(f"{k} {text(x - min_x + i * width)} {text(y - min_y + j * height)}")
                k += 1
    lines.append("EOF")
    with open(dst, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
