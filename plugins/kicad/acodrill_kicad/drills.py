"""A board's drilled holes, written as the Excellon file acodrill plans from.

Pure Python (no pcbnew): board.py fills `Drill` records from the board, this
module writes them. The positions are pcbnew's own (nanometres), written with
six decimals of a millimetre, so nothing is rounded on the way: KiCad's own
drill writer rounds every position to 1 um, and half the demo boards have
holes off that grid (up to 0.5 um).
"""
from dataclasses import dataclass
from typing import Iterable, List, Optional, Tuple


@dataclass(frozen=True)
class Drill:
    """One drilled hole or slot, in mm, Y up (KiCad's Y negated, as in its drill files)."""

    x_mm: float
    y_mm: float
    diameter_mm: float  # a slot's width
    plated: bool
    # A slot (oval drill): the other end of its centre line; (x_mm, y_mm) is the first end.
    slot_end: Optional[Tuple[float, float]] = None


def _number(v: float) -> str:
    text = f"{v:.6f}"
    return "0.000000" if text == "-0.000000" else text


def excellon_text(drills: Iterable[Drill], plated: bool, board_name: str) -> str:
    """The Excellon file of the plated (or non-plated) drills: metric, decimal,
    one tool per diameter (ascending), slots as G85; "" when there are none."""
    mine: List[Drill] = [d for d in drills if d.plated == plated]
    if not mine:
        return ""
    diameters = sorted({round(d.diameter_mm, 6) for d in mine})
    tool = {d: k + 1 for k, d in enumerate(diameters)}
    function = "Plated,1,2,PTH" if plated else "NonPlated,1,2,NPTH"
    lines = [
        "M48",
        f"; DRILL file of {board_name}, written by acodrill's KiCad plugin from the board's pads and vias",
        "; FORMAT={-:-/ absolute / metric / decimal}",
        f"; #@! TF.FileFunction,{function}",
        "METRIC",
    ]
    lines += [f"T{tool[d]}C{d:.6f}" for d in diameters]
    lines += ["%", "G90", "G05"]
    for d in diameters:
        lines.append(f"T{tool[d]}")
        for h in mine:
            if round(h.diameter_mm, 6) != d:
                continue
            text = f"X{_number(h.x_mm)}Y{_number(h.y_mm)}"
            if h.slot_end is not None:
                text += f"G85X{_number(h.slot_end[0])}Y{_number(h.slot_end[1])}"
            lines.append(text)
    lines += ["T0", "M30"]
    return "\n".join(lines) + "\n"
