"""Feed-rate simulation from Python: what the machine really does on a program (no FreeCAD needed).

    result = hsmplanner.simulate("part.ngc", machine="mikron-ucp710-840d", blocks=True)
    result.summary.total_time, result.summary.naive_time, result.blocks["mean_feed"]

A program is a G-code file path, G-code text, or FreeCAD Path commands (a Path, an object with a Path, or a
list of commands: their F is in mm/s, as FreeCAD stores it). Speeds are mm/s inside; reports write mm/min.
"""
import json
import os

import numpy as np

from . import _core
from .resources import RESOURCES_DIR

MACHINES_DIR = os.path.join(RESOURCES_DIR, "machines")
DEFAULT_MACHINE = _core.DEFAULT_MACHINE  # the guidance-curve paper's Mikron UCP 710 / 840D
FEED_CLASS_LABELS = ("<0.3", "0.3-0.5", "0.5-0.7", "0.7-0.9", ">=0.9")
LENGTH_CLASS_EDGES_MM = tuple(_core.LENGTH_CLASS_EDGES_MM)  # block-length classes: < 0.1, 0.1-0.25, … ≥ 10
MOTION_NAMES = ("G0", "G1", "G2", "G3")  # result.blocks["motion"] indexes this


def machine_folders():
    """Where machine files are looked up by name: $HSM_MACHINES_DIR, then resources/machines."""
    folders = [os.environ["HSM_MACHINES_DIR"]] if os.environ.get("HSM_MACHINES_DIR") else []
    return folders + [MACHINES_DIR]


def machine_names():
    return _core.machine_names(machine_folders())


def load_machine(machine):
    """A MachineModel from a preset name, a JSON file path, a dict of the JSON keys, or a MachineModel."""
    if isinstance(machine, _core.MachineModel):
        return machine
    if isinstance(machine, dict):
        return _core.MachineModel.from_json(json.dumps(machine), "machine dict")
    if isinstance(machine, (str, os.PathLike)):
        return _core.MachineModel.load(os.fspath(machine), machine_folders())
    raise TypeError("machine must be a preset name (%s), a JSON file, a dict or a MachineModel, got %s"
                    % (", ".join(machine_names()), type(machine).__name__))


def _path_commands(program):
    """FreeCAD Path commands of `program`, or None when it is not a Path-like object."""
    if hasattr(program, "Path") and hasattr(program.Path, "Commands"):
        program = program.Path
    if hasattr(program, "Commands"):
        return list(program.Commands)
    if isinstance(program, (list, tuple)) and program and all(hasattr(c, "toGCode") for c in program):
        return list(program)
    return None


def path_to_gcode(commands):
    """G-code text of FreeCAD Path commands, with FreeCAD's feeds in mm/s. FreeCAD's paths are in the
    workpiece frame: when moves carry A, B or C (the angles of the Job's machine), X Y Z are the tool tip, so the
    text starts with TRAORI (the simulator's 'tool tip programmed' on any controller)."""
    text = "\n".join(c.toGCode() for c in commands) + "\n"
    if any(letter in c.Parameters for c in commands for letter in "ABC"):
        text = "TRAORI\n" + text
    return text


def _trace_period(trace_period):
    period = float(trace_period or 0.0)
    if period < 0:
        raise ValueError("trace_period %g s must be positive (or None for no trace)" % period)
    return period


def _subroutine_folders(folders):
    if folders is None:
        return []
    if isinstance(folders, (str, os.PathLike)):
        folders = [folders]
    try:
        folders = list(folders)
    except TypeError:
        raise TypeError("subroutine_folders must be a folder or a list of folders, got %r" % (folders,)) from None
    checked = []
    for folder in folders:
        if not isinstance(folder, (str, os.PathLike)):
            raise TypeError("subroutine folder %r is not a path: give folders as str or pathlib.Path" % (folder,))
        if not os.path.isdir(folder):
            raise ValueError("subroutine folder %r is not a folder: give folders that hold the subprogram files"
                             % os.fspath(folder))
        checked.append(os.fspath(folder))
    return checked


def simulate(program, machine=DEFAULT_MACHINE, blocks=False, trace_period=None, refuse_unknown_words=False,
             skip_unknown=False, subroutine_folders=()):
    """Simulate `program` on `machine`; returns a SimulationResult (summary, blocks, trace).

    The program is read in the machine's dialect (LinuxCNC, grbl, Fanuc, Haas, Siemens 840D: its file's
    "dialect"). blocks=True keeps one result per block (arrays in result.blocks); trace_period (s) samples t, x, y,
    z, speed along the run into result.trace. Without them memory does not grow with the program. A word that
    would move the machine and that the reader does not understand stops the reading with a ValueError naming
    its line; skip_unknown=True skips and counts it instead (refuse_unknown_words=True refuses any unknown word).
    Subprogram files (LinuxCNC NAME.ngc, Fanuc O1234.nc, 840D NAME.SPF) are looked for beside a program file, then
    in subroutine_folders, in order.
    """
    model, period = load_machine(machine), _trace_period(trace_period)
    folders = _subroutine_folders(subroutine_folders)
    commands = _path_commands(program)
    if commands is not None:
        return _core.simulate_text(path_to_gcode(commands), model, bool(blocks), period, refuse_unknown_words, True,
                                   bool(skip_unknown))
    if isinstance(program, os.PathLike) or (isinstance(program, str) and "\n" not in program
                                            and os.path.isfile(program)):
        return _core.simulate_file(os.fspath(program), model, bool(blocks), period, refuse_unknown_words, False,
                                   bool(skip_unknown), folders)
    if isinstance(program, str):
        if "\n" not in program and program.strip() and not any(c in program for c in " ;("):
            raise ValueError("program %r is neither an existing file nor G-code text: check the path" % program)
        return _core.simulate_text(program, model, bool(blocks), period, refuse_unknown_words, False,
                                   bool(skip_unknown), folders)
    raise TypeError("program must be a G-code file, G-code text or FreeCAD Path commands, got %s"
                    % type(program).__name__)


def simulate_moves(moves, feed_mm_min, machine=DEFAULT_MACHINE, blocks=False, trace_period=None):
    """Simulate a toolpath's moves ((N, 4) x, y, z, rapid flag, as the finishing generators return them) run
    as G0/G1 at `feed_mm_min`, without writing G-code text; returns a SimulationResult as simulate does."""
    if not feed_mm_min > 0:
        raise ValueError("feed %r mm/min must be positive" % (feed_mm_min,))
    moves = np.asarray(moves, dtype=float)
    if moves.ndim != 2 or moves.shape[1] != 4:
        raise ValueError("moves must be an (N, 4) array of x, y, z and a rapid flag, got shape %s" % (moves.shape,))
    return _core.simulate_moves(moves, float(feed_mm_min) / 60.0, load_machine(machine), bool(blocks),
                                _trace_period(trace_period))


SPEED_LIMITS = tuple(_core.SPEED_LIMITS)  # what held the speed: result.blocks["limit"] indexes this


def speed_limit_shares(summary):
    """{limit: share of the simulated motion time} for the limits that held the speed at all, largest first:
    {"C": 0.18, ...} says the C axis held it 18 % of the time."""
    total = sum(summary.limit_time)
    shares = {name: t / total for name, t in zip(SPEED_LIMITS, summary.limit_time) if total > 0 and t > 0}
    return dict(sorted(shares.items(), key=lambda item: -item[1]))


def write_blocks_csv(result, path):
    """One row per block, feeds in mm/min (needs simulate(..., blocks=True))."""
    if len(result.blocks["line"]) == 0:
        raise ValueError("the result holds no blocks: simulate with blocks=True to write them")
    with open(path, "w") as stream:
        stream.write(result.blocks_csv())
    return path


def write_report(result, folder, stem="feedrate", program="", machine=None):
    """JSON summary, per-block CSV, histogram and feed-map PNGs of a result kept with blocks=True, and the
    rotary axes over time when `machine` (a name or MachineModel) has any. Returns the paths written."""
    from .plots.feedrate import save_feed_histograms, save_feed_map

    if machine is not None:
        machine = load_machine(machine)
    os.makedirs(folder, exist_ok=True)
    base = os.path.join(folder, stem)
    with open(base + ".json", "w") as stream:
        stream.write(result.summary.to_json(program))
    paths = [base + ".json", write_blocks_csv(result, base + "_blocks.csv"),
             save_feed_histograms(result.summary, base + "_histograms.png"),
             save_feed_map(result.blocks, base + "_map.png",
                           "%s on %s: feed-rate map" % (program or stem, result.summary.machine))]
    if machine is not None and machine.rotary_axes:
        from .plots.feedrate import save_rotary_axes
        paths.append(save_rotary_axes(result.blocks, result.summary, [a.name for a in machine.rotary_axes],
                                      base + "_rotary_axes.png",
                                      "%s on %s: rotary axes" % (program or stem, result.summary.machine)))
    return paths
