"""Roughing toolpaths as FreeCAD Path commands: the glue between the core's sweep and Path/CAM (pure functions,
no document object is created here).

FreeCAD's Path commands carry A, B, C without a machine: they are the angles of the machine chosen for the Job
(docs/five-axis.md). X Y Z are the tool tip in the workpiece frame, as our 5-axis posts write them (840D
TRAORI, LinuxCNC with TCP kinematics).
"""
import Path

from hsmplanner import roughing

RAPID = roughing.MOVE_KINDS.index("rapid")
ENTRY = (roughing.MOVE_KINDS.index("plunge"), roughing.MOVE_KINDS.index("ramp"))


def sweep_commands(paths, machine, feed_mm_min, entry_feed_mm_min=None):
    """G0/G1 Path commands of a sweep on `machine` (a MachineModel): rapids as G0, cuts and links at
    `feed_mm_min`, plunges and ramps at `entry_feed_mm_min` (default half the feed); the rotary axes written
    only when they move. FreeCAD stores feeds in mm/s."""
    if not feed_mm_min > 0:
        raise ValueError("feed %g mm/min must be positive" % feed_mm_min)
    entry = entry_feed_mm_min if entry_feed_mm_min else 0.5 * feed_mm_min
    tips, angles, names = roughing.machine_axes(paths, machine)
    kinds = paths.moves["kind"] if hasattr(paths, "moves") else paths["kind"]
    commands, last = [], [None, None]
    for kind, tip, angle in zip(kinds, tips, angles):
        words = {"X": float(tip[0]), "Y": float(tip[1]), "Z": float(tip[2])}
        for k, name in enumerate(names):
            if last[k] is None or abs(angle[k] - last[k]) > 1e-9:
                words[name] = float(angle[k])
                last[k] = float(angle[k])
        if kind != RAPID:
            words["F"] = (entry if kind in ENTRY else feed_mm_min) / 60.0
        commands.append(Path.Command("G0" if kind == RAPID else "G1", words))
    return commands


class ProgramSource:
    """What our posts read of an operation: a Label and a Path (for scripts that post a sweep directly)."""

    def __init__(self, label, commands):
        self.Label = label
        self.Path = Path.Path(commands)
