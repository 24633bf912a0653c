"""The holes of a board as pcbnew lists them: every pad with a drill (plated
or not, round or oval) and every via. KiCad 6 to 9: what differs between
them is found by feature (the attributes pcbnew has), not by version."""
import math
from typing import List, Tuple

import pcbnew

from .drills import Drill


# Internal units per mm: pcbnew.IU_PER_MM in KiCad 6, pcbnew.pcbIUScale.IU_PER_MM from KiCad 7 on.
_IU_PER_MM = float(pcbnew.pcbIUScale.IU_PER_MM if hasattr(pcbnew, "pcbIUScale") else pcbnew.IU_PER_MM)


def _mm(iu) -> float:
    return float(iu) / _IU_PER_MM


def _via_type_through() -> int:
    return getattr(pcbnew, "VIATYPE_THROUGH", 3)


def _oblong_drill(pad) -> bool:
    """The pad's drill is oval (a slot), by its drill shape: a round drill of
    unequal sizes is drilled round, at the smaller one, as KiCad's own drill
    writer does. Compared by name: the numbers moved between KiCad 6 and 9."""
    oblong = getattr(pcbnew, "PAD_DRILL_SHAPE_OBLONG", None)
    return oblong is not None and pad.GetDrillShape() == oblong


def board_drills(board) -> Tuple[List[Drill], List[str]]:
    """The board's drills, in mm with Y up (KiCad's Y negated), and warnings
    for what is not drilled (blind, buried and micro vias)."""
    drills: List[Drill] = []
    warnings: List[str] = []
    for fp in board.GetFootprints():
        for pad in fp.Pads():
            size = pad.GetDrillSize()
            if size.x <= 0 or size.y <= 0:
                continue  # a surface-mount pad
            pos = pad.GetPosition()
            x, y = _mm(pos.x), -_mm(pos.y)
            plated = pad.GetAttribute() != pcbnew.PAD_ATTRIB_NPTH
            if size.x == size.y or not _oblong_drill(pad):
                drills.append(Drill(x, y, _mm(min(size.x, size.y)), plated))
                continue
            # An oval drill: a slot as wide as its short side along its long
            # side, turned by the pad's orientation (counter-clockwise as seen
            # from the top, which is counter-clockwise here with Y up).
            width = _mm(min(size.x, size.y))
            half = (_mm(max(size.x, size.y)) - width) / 2
            along_x = size.x > size.y
            angle = math.radians(pad.GetOrientationDegrees())
            ux, uy = (math.cos(angle), math.sin(angle)) if along_x else (-math.sin(angle), math.cos(angle))
            drills.append(Drill(x - half * ux, y - half * uy, width, plated, (x + half * ux, y + half * uy)))
    skipped = 0
    for track in board.GetTracks():
        if track.Type() != pcbnew.PCB_VIA_T:
            continue
        if track.GetViaType() != _via_type_through():
            skipped += 1
            continue
        pos = track.GetPosition()
        drills.append(Drill(_mm(pos.x), -_mm(pos.y), _mm(track.GetDrillValue()), True))
    if skipped:
        warnings.append(f"{skipped} blind, buried or micro via(s) not drilled: they do not go through the board")
    return drills, warnings


def drill_origin(board) -> Tuple[float, float]:
    """The board's drill/place file origin (Board Setup), in the drills' coordinates."""
    ds = board.GetDesignSettings()
    o = ds.GetAuxOrigin() if hasattr(ds, "GetAuxOrigin") else ds.m_AuxOrigin
    return _mm(o.x), -_mm(o.y)
