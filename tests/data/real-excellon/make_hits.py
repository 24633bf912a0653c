#!/usr/bin/env python3
"""An independent reading of the drill files acodrill's own reader cannot
be checked against gerbv on (gerbv misreads them): each file's hits in mm,
with its number format given here by hand from what the file and its
nc_param.txt say, not guessed.  Writes FILE.hits.csv (x_mm,y_mm,diameter_mm,tool).

  /usr/bin/python3 make_hits.py      # from tests/data/real-excellon
"""
import re

FILES = {
    # file: (inch, integer digits, decimal digits, leading zeros kept)
    'pads_noheader_inch_lz.drl': (True, 2, 4, True),            # PADS: no header; numbers like X015Y0165
    'allegro/ncdrill-1-4.drl': (True, 2, 4, True),              # nc_param: ENGLISH 2.4, no suppression
    'allegro-2/MinnowMax_RevA1_NCDRILL.drl': (True, 3, 5, True),  # nc_param: ENGLISH 3.5, no suppression
    'unknown_m71_g93_tzsupp.exc': (False, 3, 3, True),          # M71; trailing zeros suppressed (the file's name)
    # jaseg/gerbonara's corpus where gerbv misreads (tests/data/gerbonara-drill/README.md):
    '../gerbonara-drill/altium-composite-drill/NC Drill/LimeSDR-QPCIe_1v2-RoundHoles.TXT': (False, 4, 4, True),  # FILE_FORMAT=4:4, METRIC,LZ
    '../gerbonara-drill/easyeda/Gerber_Drill_PTH.DRL': (True, 2, 4, True),   # INCH,LZ, FILE_FORMAT=2:4
    '../gerbonara-drill/easyeda/Gerber_Drill_NPTH.DRL': (True, 2, 4, True),
    '../gerbonara-drill/orcad/arena_12-12_v6_L1-L6.drl': (False, 3, 3, True),  # METRIC; fixed width: X-108128
}


def number(text, ints, decs, lz):
    if '.' in text:
        return float(text)
    neg = text.startswith('-')
    digits = text.lstrip('+-')
    value = int(digits.ljust(ints + decs, '0')) if lz else int(digits)
    value /= 10 ** decs
    return -value if neg else value


def read(path, inch, ints, decs, lz):
    unit = 25.4 if inch else 1.0
    tools, hits, tool, x, y = {}, [], None, 0.0, 0.0
    for raw in open(path):
        line = raw.strip()
        m = re.match(r';T(\d+) Holesize [\d.]+ = ([\d.]+) .* (MILS|MM|INCH) ', line)
        if m:
            size = float(m.group(2))
            tools[int(m.group(1))] = size * {'MILS': 0.0254, 'MM': 1.0, 'INCH': 25.4}[m.group(3)]
            continue
        if not line or line.startswith(';') or line in ('%', 'M48', 'M30', 'G90', 'G05', 'M71', 'M72') or line[:5] in (
                'INCH,', 'METRI'):
            continue  # the format is given by hand, not read
        m = re.match(r'T(\d+)(?:F\d+)?(?:S\d+)?C([\d.]+)', line)
        if m:
            tools[int(m.group(1))] = float(m.group(2)) * unit
            tool = int(m.group(1))  # without a header (PADS) the definition selects it too
            continue
        m = re.match(r'T(\d+)$', line)
        if m:
            tool = int(m.group(1))
            continue
        if line.startswith('G93'):
            continue  # only X0Y0 in these files
        m = re.match(r'(?:R(\d+))?(?:X([-+]?[\d.]+))?(?:Y([-+]?[\d.]+))?$', line)
        if not m or not (m.group(2) or m.group(3)):
            raise SystemExit(f'{path}: cannot read {line!r}')
        dx = number(m.group(2), ints, decs, lz) if m.group(2) else None
        dy = number(m.group(3), ints, decs, lz) if m.group(3) else None
        if m.group(1):  # R n: n more hits, each stepped by X Y from the last
            for _ in range(int(m.group(1))):
                x += dx or 0.0
                y += dy or 0.0
                hits.append((x * unit, y * unit, tools[tool], tool))
            continue
        if dx is not None:
            x = dx
        if dy is not None:
            y = dy
        hits.append((x * unit, y * unit, tools[tool], tool))
    return hits


for name, spec in FILES.items():
    with open(name + '.hits.csv', 'w') as out:
        out.write('x_mm,y_mm,diameter_mm,tool\n')
        for x, y, d, t in read(name, *spec):
            out.write(f'{x:.6f},{y:.6f},{d:.6f},T{t}\n')
