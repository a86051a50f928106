"""Roughing toolpaths as FreeCAD Path commands: the glue between the core's sweep and Path/CAM (pure functions,
no document object is created here).

FreeCAD's Path commands carry A, B, C without a machine: they are the angles of the machine chosen for the Job
(docs/five-axis.md). X Y Z are the tool tip in the workpiece frame, as our 5-axis posts write them (840D
TRAORI, LinuxCNC with TCP kinematics). On a 3-axis machine a path of one tilted tool axis (S3) is written 3+2:
X Y Z in the work plane turned so that the axis is Z, with comments saying how to set the part up, for
FreeCAD's own 3-axis posts; a path whose axis turns is refused with the reason.
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
    commands, last = work_plane_comments(paths, machine), [None, None]
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


def work_plane_comments(paths, machine):
    """On a 3-axis machine, a tilted path (3+2) is written in the work plane turned so that its tool axis is Z:
    comments saying how to set the part up (what a 3-axis post cannot write as G-code). Empty otherwise."""
    if machine.rotary_axes:
        return []
    plane = roughing.work_plane(paths)
    if plane is None or plane[1] < 1e-9:
        return []
    _, tilt, about = plane
    axis = (paths.moves if hasattr(paths, "moves") else paths)["axis"][0]
    return [Path.Command("(3+2 work plane: X Y Z below are the part's frame turned %.4f deg about [%.4f %.4f %.4f])"
                         % (tilt, about[0], about[1], about[2])),
            Path.Command("(set the part up so that its direction [%.4f %.4f %.4f] points along the spindle +Z)"
                         % tuple(float(a) for a in axis))]


def program_moves(commands, names=()):
    """The straight moves (G0/G1) of Path commands as a controller reads them, each word modal from the last
    (X Y Z and the rotary axes `names` from 0 until first written): (the index in `commands` of each move's
    command (n,), its tool tip X Y Z (n, 3), its angles (n, len(names)), whether it is a feed (n,) booleans).
    Our commands are absolute G0/G1 (sweep_commands); arcs and canned cycles are not moves here."""
    import numpy as np

    position, angles = {"X": 0.0, "Y": 0.0, "Z": 0.0}, {name: 0.0 for name in names}
    index, tips, turns, feeds = [], [], [], []
    for number, command in enumerate(commands):
        if command.Name not in ("G0", "G1", "G00", "G01"):
            continue
        for key, value in command.Parameters.items():
            if key in position:
                position[key] = value
            elif key in angles:
                angles[key] = value
        index.append(number)
        tips.append([position["X"], position["Y"], position["Z"]])
        turns.append([angles[name] for name in names])
        feeds.append(command.Name in ("G1", "G01"))
    return (np.asarray(index, dtype=np.int64), np.asarray(tips, dtype=float).reshape(-1, 3),
            np.asarray(turns, dtype=float).reshape(len(tips), len(names)), np.asarray(feeds, dtype=bool))


def tool_axis_ticks(commands, machine, every_mm=5.0, length_mm=4.0):
    """Segments (N, 2, 3) along the tool axis, `length_mm` long from the tip, every `every_mm` of the feed moves
    of `commands` (Path commands with A/B/C of `machine`, as sweep_commands writes them): what the 3D view draws
    to show a 4- or 5-axis path turn the tool. Bounded: at most 20,000 ticks (wider apart on long paths)."""
    import numpy as np

    if not (every_mm > 0 and length_mm > 0):
        raise ValueError("tick spacing %g mm and length %g mm must be positive" % (every_mm, length_mm))
    names = [a.name for a in machine.rotary_axes]
    _, tips, turns, feeds = program_moves(commands, names)
    if len(tips) < 2:
        return np.zeros((0, 2, 3))
    lengths = np.where(feeds[1:], np.linalg.norm(np.diff(tips, axis=0), axis=1), 0.0)
    every = max(every_mm, float(np.sum(lengths)) / 20000.0)
    travelled = np.concatenate([[0.0], np.cumsum(lengths)])
    segments = []
    for mark in np.arange(every, travelled[-1] + 1e-9, every):
        # On the feed move where the mark falls, tip and angles in proportion (the angles as a controller
        # interpolates them).
        index = max(1, min(int(np.searchsorted(travelled, mark)), len(tips) - 1))
        share = (mark - travelled[index - 1]) / max(lengths[index - 1], 1e-12)
        tip = tips[index - 1] + share * (tips[index] - tips[index - 1])
        axis = _axes_of(machine, (turns[index - 1] + share * (turns[index] - turns[index - 1]))[None, :])[0]
        segments.append([tip, tip + length_mm * axis / np.linalg.norm(axis)])
    return np.asarray(segments).reshape(-1, 2, 3)


MAX_CHECKED_POSITIONS = 1_000_000
# Pieces of a block whose rotary axes turn by at most this: between the ends of a piece the check turns the axis
# on the great circle, within 40 mm · (1°)² / 8 = 0.0015 mm of the machine's own path at a 40 mm stick-out,
# under the part mesh's 0.01 mm; finer pieces only multiply the positions checked (0.05° made 57,000 of 2,800
# blocks on three impeller channels, 12 times the time).
MAX_TURN_DEG = 1.0


def _axes_of(machine, angles):
    """The tool axis in the workpiece frame at each row of `angles` (the machine's rotary axes, degrees)."""
    import numpy as np

    from hsmplanner import _core

    if angles.shape[1] == 0:
        return np.tile(np.asarray(machine.tool_axis, dtype=float), (len(angles), 1))
    padded = np.zeros((len(angles), 2))
    padded[:, :angles.shape[1]] = angles
    axes = [_core.forward_kinematics(machine, [0.0, 0.0, 0.0], list(row))[1] for row in padded]
    return np.asarray(axes, dtype=float).reshape(-1, 3)


def interpolated_program(commands, machine, orientation="angles", max_turn_deg=MAX_TURN_DEG):
    """The tool tips and axes of Path commands as the controller moves the tool between their blocks: the tip
    straight (TCP: X Y Z are the tip), and the axis by the machine's own A/B/C interpolated linearly
    (`orientation="angles"`: LinuxCNC, the 840D's ORIAXES), blocks cut so that no axis turns more than
    `max_turn_deg` in one; or on the great circle between the blocks' axes ("vectors": the 840D's ORIVECT).
    A dict of (N, 3) `tip` and `axis` arrays and `move`, the index in `commands` of the block each comes from."""
    _check_interpolation(orientation, max_turn_deg)
    if isinstance(commands, (str, bytes)) or not hasattr(commands, "__iter__"):
        raise TypeError("commands must be FreeCAD Path commands (a posted program's text goes to posted_program), "
                        "got %s" % type(commands).__name__)
    index, tips, turns, _ = program_moves(commands, [axis.name for axis in machine.rotary_axes])
    return _interpolated(index, tips, turns, machine, orientation, max_turn_deg)


def posted_program(program, machine, orientation="angles", max_turn_deg=MAX_TURN_DEG):
    """interpolated_program of a posted program (G-code text or file) as the controller reads it: its blocks
    interpreted by the feed-rate simulator on `machine` (TRAORI, modal words, the post's own syntax), `move`
    being each block's line number. ValueError for an arc (roughing programs are straight moves)."""
    import numpy as np

    from hsmplanner import feedsim

    _check_interpolation(orientation, max_turn_deg)
    blocks = feedsim.simulate(program, machine, blocks=True, refuse_unknown_words=True).blocks
    motion = np.asarray(blocks["motion"])
    if np.any(motion >= 2):
        line = int(np.asarray(blocks["line"])[np.argmax(motion >= 2)])
        raise ValueError("line %d is an arc: the clearance of a posted program is checked on straight moves" % line)
    # From the first block's end: where the machine stands before the program is not the program's.
    count = len(machine.rotary_axes)
    return _interpolated(np.asarray(blocks["line"], dtype=np.int64), np.asarray(blocks["end"]),
                         np.asarray(blocks["rotary_end"])[:, :count], machine, orientation, max_turn_deg)


def _check_interpolation(orientation, max_turn_deg):
    if orientation not in ("angles", "vectors"):
        raise ValueError("orientation %r must be 'angles' (A/B/C interpolated linearly) or 'vectors' (great circle)"
                         % (orientation,))
    if not 1e-4 <= max_turn_deg <= 10.0:
        raise ValueError("max_turn_deg %g must be within [0.0001, 10] degrees" % max_turn_deg)


def _interpolated(index, tips, turns, machine, orientation, max_turn_deg):
    import numpy as np

    bad = ~(np.isfinite(tips).all(axis=1) & np.isfinite(turns).all(axis=1))
    if bad.any():
        raise ValueError("block %d has a position or angle that is not a finite number: fix the program"
                         % int(index[np.argmax(bad)]))
    pieces = np.ones(len(tips), dtype=np.int64)
    if orientation == "angles" and turns.shape[1] and len(tips) > 1:
        largest = np.max(np.abs(np.diff(turns, axis=0)), axis=1)
        pieces[1:] = np.maximum(1, np.ceil(largest / max_turn_deg - 1e-9)).astype(np.int64)
    if int(pieces.sum()) > MAX_CHECKED_POSITIONS:
        raise ValueError("the program turns its rotary axes through %d steps of %g deg, more than %d: use a larger "
                         "max_turn_deg" % (int(pieces.sum()), max_turn_deg, MAX_CHECKED_POSITIONS))
    # Block i from i - 1: `pieces[i]` points at shares k / pieces[i], k = 1 … pieces[i] (the first block whole).
    block = np.repeat(np.arange(len(tips)), pieces)
    start = np.repeat(np.cumsum(pieces) - pieces, pieces)
    share = (np.arange(len(block)) - start + 1) / pieces[block]
    before = np.maximum(block - 1, 0)
    tip = tips[before] + share[:, None] * (tips[block] - tips[before])
    angles = turns[before] + share[:, None] * (turns[block] - turns[before])
    return {"tip": tip, "axis": _axes_of(machine, angles), "move": index[block]}


def program_clearance(program, machine, part, tool=None, limit=None, orientation="angles", spacing=1.0,
                      max_turn_deg=MAX_TURN_DEG):
    """How close the tool comes to the part along a program (Path commands, or a posted program's G-code text
    or file) as `machine`'s controller runs it (interpolated_program, posted_program), checked independently
    on the part's triangles: (the ClearanceReport, the closest block: its index in the commands, or its line
    in the posted text; -1 when nothing was checked)."""
    if isinstance(program, (str, bytes)) or hasattr(program, "__fspath__"):
        moves = posted_program(program, machine, orientation, max_turn_deg)
    else:
        moves = interpolated_program(program, machine, orientation, max_turn_deg)
    report = roughing.check_clearance(moves, part, tool, limit, spacing)
    return report, int(moves["move"][report.worst_move]) if report.worst_move >= 0 else -1


class ProgramSource:
    """What our posts read of an operation: a Label and a Path (for scripts that post a sweep directly)."""

    def __init__(self, label, commands):
        self.Label = label
        self.Path = Path.Path(commands)
