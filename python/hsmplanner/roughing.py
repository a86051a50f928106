"""5-axis roughing by partition of the volume to remove (the roughing paper, §3): the volume, its faces, its
sub-volumes (part 1; cpp/roughing/roughing.hpp), and their toolpaths (part 2; S1–S5,
cpp/roughing/sweep.hpp) with an independent clearance check (cpp/roughing/clearance.hpp).

    wheel = hsmplanner.roughing.impeller(blades=7)
    volume = hsmplanner.roughing.volume_to_remove(wheel.stock_brep, wheel.part_brep)
    channel = volume.solids[0]                      # one per inter-blade channel, largest first
    [c.name for c in channel.face_classes]          # crossable / facing_crossable / not_crossable
    result = hsmplanner.roughing.partition(channel, wheel.part_brep, "S5", step=8.0)
    [(s.slice, s.volume) for s in result.sub_volumes]
    paths = hsmplanner.roughing.sweep(hsmplanner.roughing.partition(channel, wheel.part_brep, "S3"), channel,
                                      wheel.part_brep, wheel.stock_brep)   # Ø8 r1 torus, 70 % radial
    hsmplanner.roughing.check_clearance(paths, wheel.part_brep).minimum   # ≥ allowance − 0.01 mm

Shapes are FreeCAD Part shapes or BREP text; results carry BREP text (`brep`) and plain attributes.
"""
import math

from . import _core
from .core_settings import core_settings, enum_value
from .geometry import as_brep

FaceClass = _core.roughing.FaceClass
CutterKind = _core.roughing.CutterKind
MOVE_KINDS = tuple(_core.roughing.MOVE_KINDS)  # sweep(...).moves["kind"] indexes this
Strategy = _core.roughing.Strategy
SurfaceKind = _core.roughing.SurfaceKind

STRATEGY_LABELS = {
    "S1": "S1 planes parallel to the inlet face (3 axes)",
    "S2": "S2 coaxial cylinders about the outlet face (4 axes)",
    "S3": "S3 planes of a computed setup (3+2 axes)",
    "S4": "S4 offsets of the stock skin (5 axes)",
    "S5": "S5 offsets of the hub / floor (5 axes)",
}


def strategy(value):
    """A Strategy from itself, its name ('S4'), its number (4) or a label of STRATEGY_LABELS."""
    if isinstance(value, int) and not isinstance(value, bool):
        value = "S%d" % value
    if isinstance(value, str):
        value = value.strip().split(" ")[0].upper()
    return enum_value(Strategy, value, "strategy")


def volume_to_remove(stock, part, progress=None):
    """stock − part (OCCT booleans, checked: volumes within 1e-6, validity, one fuzzy retry): a VolumeToRemove
    whose solids (one per region) carry their faces' classes. ValueError for bad inputs (not closed valid
    solids, a stock that does not hold the part, nothing to remove); RuntimeError when the boolean fails."""
    return _core.roughing.volume_to_remove(as_brep(stock), as_brep(part), progress)


def _settings(step=None, setup_resolution_deg=None, setup_grid=None, rest=None):
    return core_settings(_core.roughing.PartitionSettings, step=None if step is None else float(step),
                         setup_resolution_deg=None if setup_resolution_deg is None else float(setup_resolution_deg),
                         setup_grid=None if setup_grid is None else float(setup_grid), rest=rest)


def _solid(volume):
    """A RemovalSolid from itself, or the largest solid of a VolumeToRemove."""
    if isinstance(volume, _core.roughing.VolumeToRemove):
        if not volume.solids:
            raise ValueError("the volume to remove has no solid")
        return volume.solids[0]
    if not isinstance(volume, _core.roughing.RemovalSolid):
        raise TypeError("expected a RemovalSolid (volume_to_remove(...).solids[i]) or a VolumeToRemove, got %s"
                        % type(volume).__name__)
    return volume


def partition(volume, part, strategy_name="S5", step=None, setup_resolution_deg=None, setup_grid=None,
              rest=None, progress=None):
    """The solid (a RemovalSolid, or a VolumeToRemove's largest) cut by one of the five slicings, `step` mm
    apart (default: the core's 8 mm, 100 % of a Ø8 tool): a Partition whose sub_volumes carry their volume,
    BREP, slicing surface and tool axis field. S3 with `rest` (a RestStock): the setup direction that reaches
    the most of the stock a previous operation left in this volume. ValueError for a step ≤ 0 or beyond the
    volume, or a strategy whose reference face this volume lacks."""
    return _core.roughing.partition(_solid(volume), as_brep(part), strategy(strategy_name),
                                    _settings(step, setup_resolution_deg, setup_grid, rest), progress)


def setup_direction(volume, part, resolution_deg=None, grid=None, progress=None):
    """(unit direction, reached share): the fixed tool axis from which a straight tool reaches the most of the
    volume without crossing the part (S3's setup)."""
    direction, share = _core.roughing.setup_direction(_solid(volume), as_brep(part),
                                                      _settings(None, resolution_deg, grid), progress)
    return tuple(float(x) for x in direction), float(share)


def reachable_share(volume, part, direction, grid=None):
    """Share (0..1) of the volume a straight tool along `direction` (towards the spindle) reaches."""
    return _core.roughing.reachable_share(_solid(volume), as_brep(part), [float(x) for x in direction],
                                          _settings(None, None, grid))


def slanted_slot_block(**parameters):
    """The slanted slot test part (PartAndStock: part_brep, stock_brep); parameters of SlantedSlotParameters
    (length, width, height, slot_width, slot_depth, tilt_deg), mm and degrees."""
    return _core.roughing.slanted_slot_block(core_settings(_core.roughing.SlantedSlotParameters, **parameters))


def slanted_slot_volume(**parameters):
    """The slanted slot's volume to remove in closed form, mm³."""
    return _core.roughing.slanted_slot_volume(core_settings(_core.roughing.SlantedSlotParameters, **parameters))


def impeller(**parameters):
    """The radial compressor impeller test part (PartAndStock); parameters of ImpellerParameters (blades,
    hub_inlet_radius, outlet_radius, height, channel_height, lean_deg, wrap_deg, thickness, base_thickness)."""
    return _core.roughing.impeller(core_settings(_core.roughing.ImpellerParameters, **parameters))


def cutter(kind="torus", diameter=None, corner_radius=None, flute_length=None, shank_diameter=None, stick_out=None,
           holder_diameter=None, holder_length=None):
    """A Cutter (mm): 'torus' (default: the paper's Ø8 r1), 'flat' or 'ball'; a ball's corner radius is half its
    diameter, a flat one's 0. Checked when used."""
    kind = enum_value(CutterKind, kind, "cutter kind")
    result = core_settings(_core.roughing.Cutter, kind=kind, diameter=diameter, corner_radius=corner_radius,
                           flute_length=flute_length, shank_diameter=shank_diameter, stick_out=stick_out,
                           holder_diameter=holder_diameter, holder_length=holder_length)
    if kind == CutterKind.ball:
        result.corner_radius = 0.5 * result.diameter
    elif kind == CutterKind.flat:
        result.corner_radius = 0.0
    return result


def sweep(partition_result, volume, part, stock, tool=None, radial_engagement=None, allowance=None, tolerance=None,
          ramp_angle_deg=None, clearance=None, step_up_minimum=None, step_up_scallop=None, push_out=None, rest=None,
          mesh_deflection=None, progress=None):
    """The sub-volumes of a Partition swept by contour-parallel passes (S1–S5; S4 and S5 on offsets of planes,
    cylinders and surfaces of revolution, not of free-form faces): a
    SweepResult whose `moves` are arrays (tip, axis, kind, sub_volume), with its passes and lengths. `volume`
    is the RemovalSolid the partition came from; `part` and `stock` the shapes. Intermediate levels inside each
    slice where the part leans (step-up): no nearer than `step_up_minimum` mm to each other (0: none, one level
    per slice as the paper), added while the staircase left across a wall exceeds `step_up_scallop` mm.
    `push_out` (mm, 0 off): how far each level's boundary may move from the sweep's keep-out (safe but up to a
    millimetre wide) towards the part, to the cutter's exact clearance on the part's triangles.
    Rest roughing: with `rest` (a RestStock: simulate_removal(..., rest_spacing=…).rest of the operations
    before), each level cuts only where its tool reaches that stock. `mesh_deflection` (mm, default 0.05): how
    far the part's triangles may stray from its faces; the keep-out and the push-out add it to the allowance,
    so a finer mesh leaves a thinner layer beyond the allowance for a longer sweep. ValueError for bad
    settings."""
    settings = core_settings(_core.roughing.SweepSettings, cutter=tool, radial_engagement=radial_engagement,
                             allowance=allowance, tolerance=tolerance, ramp_angle_deg=ramp_angle_deg,
                             clearance=clearance, step_up_minimum=step_up_minimum, step_up_scallop=step_up_scallop,
                             push_out_most=push_out, rest=rest, mesh_deflection=mesh_deflection)
    return _core.roughing.sweep(partition_result, _solid(volume), as_brep(part), as_brep(stock), settings, progress)


def check_clearance(paths, part, tool=None, limit=None, spacing=1.0, deflection=0.01):
    """How close the tool comes to the part along `paths` (a SweepResult, or a dict of (N, 3) `tip` and `axis`
    arrays), measured independently on the part's triangles every `spacing` mm: a ClearanceReport (minimum,
    positions, too_close under `limit`, default the default allowance − 0.01 mm, worst_move)."""
    moves = paths.moves if hasattr(paths, "moves") else paths
    tool = tool if tool is not None else _core.roughing.Cutter()
    if limit is None:
        limit = _core.roughing.SweepSettings().allowance - 0.01
    if not math.isfinite(float(limit)) or not float(limit) >= 0.0:
        raise ValueError("clearance limit %r mm must be a finite distance of 0 or more: the closest the tool may "
                         "come to the part (e.g. the allowance - 0.01 mm)" % (limit,))
    return _core.roughing.check_clearance(moves["tip"], moves["axis"], as_brep(part), tool, float(limit),
                                          float(spacing), float(deflection))


def join_paths(paths, stock, clearance=None):
    """The sweeps of several regions (SweepResults or moves dicts) as one moves dict, linked safely through the
    air (one plane when every move keeps one axis, else a sphere about the stock; cpp/roughing/sweep.hpp
    joinSweeps): what one program of all an impeller's channels runs."""
    regions = [p.moves if hasattr(p, "moves") else p for p in paths]
    return _core.roughing.join_sweeps(regions, as_brep(stock), 5.0 if clearance is None else float(clearance))


def _moves_of(paths):
    return paths.moves if hasattr(paths, "moves") else paths


def _run(paths, tool, name):
    """(moves dict, Cutter) of one operation; ValueError naming `name` when its paths are not moves."""
    moves = _moves_of(paths)
    if not (hasattr(moves, "keys") and {"tip", "axis", "kind"} <= set(moves.keys())):
        raise ValueError("%s: paths must be a SweepResult or a dict of tip, axis and kind arrays, not %s"
                         % (name, type(paths).__name__))
    return moves, tool if tool is not None else _core.roughing.Cutter()


def _operations(pairs, name):
    """[(moves dict, Cutter)] of `pairs`, a list of (paths, tool); ValueError naming `name` for anything else."""
    runs = []
    for k, pair in enumerate(pairs or ()):
        if not (isinstance(pair, (tuple, list)) and len(pair) == 2):
            raise ValueError("%s[%d] must be a (paths, tool) pair (tool None for the paper's torus)" % (name, k))
        runs.append(_run(pair[0], pair[1], "%s[%d]" % (name, k)))
    return runs


def _runs(paths, tool, then):
    """[(moves dict, Cutter)]: `paths` with `tool`, then each (paths, tool) of `then`."""
    return [_run(paths, tool, "paths")] + _operations(then, "then")


def simulate_removal(paths, stock, part, tool=None, resolution=None, chip_section=None, stick_out_spacing=None,
                     threads=None, allowance=None, stock_mesh_stride=None, rest_spacing=None, then=None,
                     progress=None):
    """The moves of `paths` (a SweepResult, or a dict of (N, 3) `tip` and `axis` and (N,) `kind` arrays) swept
    through stock − part by the cutter `tool` (default the paper's Ø8 r1 torus) on a tri-dexel model
    `resolution` mm fine (default 0.2; cpp/roughing/removal.hpp): a RemovalResult with V_r (remaining_share,
    %; beyond_allowance_share without the `allowance` layer left on the part, default 0.5 mm), the path, feed and in-material lengths, the least stick-out for the holder, any gouge (volume, first
    move, where) and the stock left on the part (thickness at surface_points, its weighted mean, max and
    standard deviation), every rapid that cuts the stock left (rapid_faults: move, where, volume; a fault) and, with `stock_mesh_stride` k > 0, the stock left as a closed mesh of blocks of k × k
    rays (stock_mesh: points, triangles; save_stl writes it). With `rest_spacing` (mm), the stock left beyond
    the allowance as points that far apart (rest: a RestStock for sweep's rest roughing). `then`: operations run
    after these on the same stock, [(paths, tool)] (rest roughing with a smaller tool); move indices count
    through them all. ValueError for bad settings or moves; Cancelled when `progress` returns False."""
    settings = core_settings(_core.roughing.RemovalSettings, resolution=resolution, chip_section=chip_section,
                             stick_out_spacing=stick_out_spacing, threads=threads, allowance=allowance,
                             stock_mesh_stride=stock_mesh_stride, rest_spacing=rest_spacing)
    return _core.roughing.simulate_removal_runs(_runs(paths, tool, then), as_brep(stock), as_brep(part), settings,
                                                progress)


def split_what_is_left(partition_result, volume, part, paths, tool=None, allowance=None, resolution=0.25,
                       threads=0):
    """What the moves of `paths` (one region's sweep of `partition_result`, before joining) leave, by cause,
    measured apart from the sweep on a grid of `resolution` mm (cpp/roughing/reach.hpp): a LeftSplit with the
    region's material (volume), what no tool along the path's own axes reaches without coming nearer the part
    than the allowance (unreachable) and what it reaches only from heights between the path's levels
    (between_levels), mm³; the rest of a removal simulation's stock left is the path's own."""
    moves = _moves_of(paths)
    tool = tool if tool is not None else _core.roughing.Cutter()
    allowance = _core.roughing.SweepSettings().allowance if allowance is None else float(allowance)
    return _core.roughing.split_what_is_left(partition_result, _solid(volume), as_brep(part), tool, allowance,
                                             moves["tip"], moves["axis"], moves["kind"], float(resolution),
                                             int(threads))


def keep_rapids_out_of_stock(paths, stock, part, tool=None, resolution=0.2, margin=1.0, threads=None,
                             after=None, progress=None):
    """The moves of `paths` (a SweepResult or a moves dict, e.g. join_paths') simulated through the stock at
    `resolution` mm — after the operations `after`, [(paths, tool)], on what they left — every rapid that would
    cut the stock left at its time split: a rapid to `margin` mm (and the sampling) before the stock, then the
    rest as a plunge at the entry feed. (moves dict, [RapidFault] mended: the move, where, the volume the rapid
    would have taken out). A final simulate_removal of the moves returned reports no rapid fault."""
    moves = _moves_of(paths)
    settings = core_settings(_core.roughing.RemovalSettings, resolution=resolution, threads=threads)
    tool = tool if tool is not None else _core.roughing.Cutter()
    before = _operations(after, "after")
    return _core.roughing.keep_rapids_out_of_stock(moves["tip"], moves["axis"], moves["kind"], tool, as_brep(stock),
                                                   as_brep(part), settings, float(margin), progress, before)


def rapid_note(fed):
    """What keep_rapids_out_of_stock mended (a non-empty list of RapidFault), in words: how many, the largest."""
    worst = max(fed, key=lambda f: f.volume)
    return ("%d rapid%s would have cut stock left (the most %.3g mm³ at move %d, tip %.1f %.1f %.1f): they feed "
            "into it from just above it" % (len(fed), "" if len(fed) == 1 else "s", worst.volume, worst.move,
                                            worst.at[0], worst.at[1], worst.at[2]))


def save_stl(mesh, path, name="stock left"):
    """A triangle mesh ((N, 3) points, (M, 3) triangles: a RemovalResult's stock_mesh) as a binary STL file."""
    import numpy as np

    points, triangles = (np.asarray(a) for a in mesh)
    if points.ndim != 2 or points.shape[1:] != (3,) or triangles.size % 3:
        raise ValueError("save_stl takes ((N, 3) points, (M, 3) triangles), got arrays of shapes %s and %s"
                         % (points.shape, triangles.shape))
    triangles = triangles.reshape(-1, 3)
    if triangles.size and (not np.issubdtype(triangles.dtype, np.integer) or triangles.min() < 0
                           or triangles.max() >= len(points)):
        raise ValueError("save_stl: triangle corners must be indices of the %d points (0 to %d), got %s to %s"
                         % (len(points), len(points) - 1, triangles.min(), triangles.max()))
    corners = points[triangles].reshape(-1, 3, 3)
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    normals = normals / np.where(lengths > 0, lengths, 1.0)[:, None]
    records = np.zeros(len(corners), dtype=[("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])
    records["normal"], records["corners"] = normals, corners
    with open(path, "wb") as stream:
        stream.write(name.encode("ascii", "replace")[:80].ljust(80, b" "))
        stream.write(np.uint32(len(records)).tobytes())
        stream.write(records.tobytes())
    return path


def work_plane(paths, tolerance=1e-9):
    """For a sweep whose tool axis never turns (S1; S3 and planar S4/S5 as 3+2): (R, tilt_deg, about), the
    rotation R (3x3) that turns the part so that its tool axis points up (+Z) — the least one, about the
    horizontal `about` (unit) by `tilt_deg` — or None when the axis turns along the path (S2, S4, S5 on
    curved faces: 4 and 5 axes). R is the identity for a vertical axis."""
    import numpy as np

    moves = paths.moves if hasattr(paths, "moves") else paths
    axes = np.asarray(moves["axis"], dtype=float)
    if not len(axes):
        return np.eye(3), 0.0, np.array([1.0, 0.0, 0.0])
    axis = axes[0] / np.linalg.norm(axes[0])
    if np.any(axes @ axis < 1.0 - tolerance):
        return None
    up = np.array([0.0, 0.0, 1.0])
    about = np.cross(axis, up)
    sine, cosine = np.linalg.norm(about), float(axis @ up)
    if sine < 1e-12:
        if cosine > 0:
            return np.eye(3), 0.0, np.array([1.0, 0.0, 0.0])
        return np.diag([1.0, -1.0, -1.0]), 180.0, np.array([1.0, 0.0, 0.0])
    about /= sine
    k = np.array([[0, -about[2], about[1]], [about[2], 0, -about[0]], [-about[1], about[0], 0]])
    rotation = np.eye(3) + sine * k + (1.0 - cosine) * (k @ k)  # Rodrigues: turns `axis` onto +Z
    return rotation, float(np.degrees(np.arctan2(sine, cosine))), about


def machine_axes(paths, machine):
    """The moves of a sweep (a SweepResult or its `moves` dict) on a machine (a MachineModel): the tool tip
    (workpiece frame, for a tool-tip-programmed post) and the rotary angles (deg, the machine's axes in chain
    order, each nearest the previous: the inverse kinematics' choice rule). A 3-axis machine takes a path of one
    tool axis, the tips then in the work plane turned so that this axis is Z (3+2; work_plane gives the turn);
    a path whose axis turns, or a move the machine cannot orient, raises ValueError naming the move and the
    machine.
    Returns (tips (N, 3), angles (N, 2), the rotary axes' names)."""
    import numpy as np

    moves = paths.moves if hasattr(paths, "moves") else paths
    tips, axes = np.asarray(moves["tip"], dtype=float), np.asarray(moves["axis"], dtype=float)
    names = [a.name for a in machine.rotary_axes]
    angles = np.zeros((len(tips), 2))
    if not names:
        plane = work_plane(moves)
        if plane is None:
            turns = int(np.where(axes @ axes[0] < 1.0 - 1e-9)[0][0])
            raise ValueError("move %d turns the tool axis (%s, then %s): a 4- or 5-axis path, and machine '%s' has no "
                             "rotary axes: a 3-axis machine and its post run one tool axis only (S1, or S3 as 3+2 "
                             "with the work plane rotated); use a 4- or 5-axis machine and post (hsm_siemens840d, "
                             "hsm_linuxcnc5x)" % (turns, tuple(np.round(axes[0], 4)), tuple(np.round(axes[turns], 4)),
                                                  machine.name))
        # 3+2: the tips in the work plane turned so that the tool axis is the machine's Z (see work_plane).
        return tips @ plane[0].T, angles, names
    previous = [0.0, 0.0]
    for i, (tip, axis) in enumerate(zip(tips, axes)):
        try:
            _, found, _ = _core.inverse_kinematics(machine, tip, axis, previous)
        except ValueError as error:
            raise ValueError("move %d: %s" % (i, error)) from None
        angles[i] = found
        previous = list(found)
    return tips, angles, names
