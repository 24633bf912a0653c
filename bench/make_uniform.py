#!/usr/bin/env python3
"""Writes N holes at uniform random places on a 1 000 000 x 1 000 000 plate,
in random order, as a TSPLIB instance (EUC_2D, whole coordinates): the kind
of instance the scale section of scripts/benchmarks measures. The same N and
seed give the same file (Python's Mersenne Twister).

    python3 bench/make_uniform.py /tmp/u100k.tsp 100000 1
"""
import random
import sys


def main():
    if len(sys.argv) != 4 or any(a in ("-h", "--help") for a in sys.argv[1:]):
        print(__doc__)
        sys.exit(0 if len(sys.argv) > 1 and sys.argv[1] in ("-h", "--help") else 2)
    path, n, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rng = random.Random(seed)
    lines = [f"NAME : uniform{n}s{seed}", "TYPE : TSP", f"DIMENSION : {n}", "EDGE_WEIGHT_TYPE : EUC_2D",
             "NODE_COORD_SECTION"]
    lines += [f"{i + 1} {rng.randrange(1000000)} {rng.randrange(1000000)}" for i in range(n)]
    lines.append("EOF")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
