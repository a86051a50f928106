"""How our operations reach their first cut and leave their last, as CAM's own operations do: up to the
clearance height first (G0 Z), across at it (G0 X Y, and the rotary axes of the first move), then down to
where the operation's own moves begin; and back up to the clearance height at the end. A rapid straight from
wherever the tool change or the operation before left the tool to the first point could cross the part."""
import math

import Path

MOTION = ("G0", "G00", "G1", "G01", "G2", "G02", "G3", "G03")
ROTARY = ("A", "B", "C")


def via_clearance(commands, clearance_z):
    """`commands` with the moves to and from `clearance_z` (mm) added; the height is raised to the first move's
    Z where that is higher (the move down is never a move up). Commands without a move come back unchanged."""
    if not math.isfinite(float(clearance_z)):
        raise ValueError("clearance height %r mm is not a number: set the operation's ClearanceHeight" % (clearance_z,))
    moves = [c for c in commands if c.Name in MOTION]
    if not moves:
        return list(commands)
    first = moves[0].Parameters
    height = max(float(clearance_z), first.get("Z", float(clearance_z)))
    across = {axis: first[axis] for axis in ("X", "Y") + ROTARY if axis in first}
    across["Z"] = height
    return ([Path.Command("G0", {"Z": height}), Path.Command("G0", across)] + list(commands)
            + [Path.Command("G0", {"Z": height})])

