"""The machining direction of parallel-plane finishing, chosen by directional beams (Quinsat & Sabourin).

    result = hsmplanner.optimal_direction(face, tool_diameter=10, scallop=0.01, feed_mm_min=6000,
                                          spindle_rpm=15000, teeth=2, machine="mikron-ucp710-840d")
    result.angle_deg, result.alpha, result.acceptable

The feed may be given per tooth instead (feed_per_tooth=0.2: feed = fz·Z·N). The acceleration is the slowest
of the machine's X and Y axes (the paper's a_max), or acceleration_m_s2; use_jerk=True adds the jerk limit
∛(J·Rc²) of the same axes to the real feed. The rules are in cpp/direction/direction.hpp.

Three answers, from the quickest to the surest: result.angle_deg (the paper's beams: the worst point keeps
the largest share α* of its best fitness), result.fastest_angle_deg (the same model's cutting time summed
over the face) and, by simulation, fastest(simulated_directions(part, face, …)) (planes every 10°, finished
and simulated on the machine model: the paper's Fig. 12 as a tool).
"""
import numpy as np

from . import _core
from .core_settings import core_settings, default
from .feedsim import DEFAULT_MACHINE, load_machine, simulate_moves
from .geometry import as_brep
from .toolpaths import parallel_finishing


def cutting_conditions(tool_diameter=None, scallop=None, feed_mm_min=None, spindle_rpm=None, teeth=None,
                       feed_per_tooth=None, use_jerk=False):
    """The core's CuttingConditions (mm, s) from the units people type; what is not given keeps the core's
    default (help(hsmplanner._core.CuttingConditions))."""
    teeth = default(_core.CuttingConditions, "teeth") if teeth is None else int(teeth)
    spindle_speed = None if spindle_rpm is None else float(spindle_rpm) / 60.0
    if feed_per_tooth is not None:
        rev_s = spindle_speed or default(_core.CuttingConditions, "spindle_speed")
        feed_mm_min = float(feed_per_tooth) * teeth * rev_s * 60.0
    if feed_mm_min is None:
        raise ValueError("give the programmed feed (feed_mm_min) or the feed per tooth (feed_per_tooth)")
    return core_settings(_core.CuttingConditions, tool_radius=None if tool_diameter is None else 0.5 * float(tool_diameter),
                         scallop=None if scallop is None else float(scallop), programmed_feed=float(feed_mm_min) / 60.0,
                         spindle_speed=spindle_speed, teeth=teeth, jerk_limits_feed=bool(use_jerk))


def direction_machine(machine=DEFAULT_MACHINE, acceleration_m_s2=None):
    """The machine whose slowest plan axes limit the feed: a preset/file/dict/MachineModel, or, with
    acceleration_m_s2, an acceleration-limited machine with that a_max on every axis (the paper's model)."""
    if acceleration_m_s2 is not None:
        if not float(acceleration_m_s2) > 0:
            raise ValueError("acceleration_m_s2 = %r must be positive (the slowest axis, m/s²)" % (acceleration_m_s2,))
        model = _core.MachineModel()
        model.name = "a_max %g m/s²" % acceleration_m_s2
        model.controller = _core.ControllerKind.linuxcnc  # trapezoidal: acceleration only, no jerk
        model.max_acceleration = [1000.0 * float(acceleration_m_s2)] * 3
        return model
    if machine is None:
        raise ValueError("give a machine or acceleration_m_s2 (the slowest axis)")
    return load_machine(machine)


def optimal_direction(face, tool_diameter=None, scallop=None, feed_mm_min=None, spindle_rpm=None, teeth=None,
                      feed_per_tooth=None, machine=DEFAULT_MACHINE, acceleration_m_s2=None, use_jerk=False,
                      grid=None, angle_step=None, alpha=None):
    """The optimal direction θ (degrees from X) of parallel planes over `face`, its α and the acceptable
    directions (those within `alpha` of the local optimum at every point, or within α* when α* < alpha).
    Defaults (tool, scallop, spindle, teeth, grid, angle step, alpha) are the core's: help(optimal_direction)."""
    conditions = cutting_conditions(tool_diameter, scallop, feed_mm_min, spindle_rpm, teeth, feed_per_tooth, use_jerk)
    settings = core_settings(_core.DirectionSettings, grid_u=None if grid is None else int(grid),
                             grid_v=None if grid is None else int(grid),
                             angle_step=None if angle_step is None else float(angle_step),
                             report_alpha=None if alpha is None else float(alpha))
    return _core.optimal_direction(as_brep(face), conditions, direction_machine(machine, acceleration_m_s2), settings)


def directions_over_feeds(face, feeds_mm_min, **kwargs):
    """(feed, optimal angle, acceptable angles) for each programmed feed: the paper's Fig. 10."""
    rows = []
    for feed in feeds_mm_min:
        result = optimal_direction(face, feed_mm_min=feed, **kwargs)
        rows.append((float(feed), result.angle_deg, np.asarray(result.acceptable)))
    return rows


def simulated_directions(part, face, angles_deg=range(0, 181, 10), tool_diameter=10.0, scallop=0.01,
                         feed_mm_min=6000.0, machine=DEFAULT_MACHINE, tolerance=0.01, progress=None):
    """Parallel planes at each angle over `face` of `part` (a face on its own: part=face, face='Face1'),
    finished for the scallop and simulated on `machine`: one dict per angle (angle_deg, passes, length_mm,
    simulated_s, length_over_feed_s). The check of the paper's Fig. 12, and the surest choice: it sees the
    pass count, the links and the part's outline, which no criterion at points sees. progress: a callable
    progress(done) over all the angles; returning False cancels (hsmplanner.Cancelled)."""
    rows, angles = [], list(angles_deg)
    for index, angle in enumerate(angles):
        share = None if progress is None else (lambda done, i=index: progress((i + done) / len(angles)))
        moves, stats = parallel_finishing(part, face, angle_deg=float(angle), tool_diameter=tool_diameter,
                                          cusp_height=scallop, tolerance=tolerance, progress=share)
        summary = simulate_moves(moves, feed_mm_min, machine).summary
        rows.append(dict(angle_deg=float(angle), passes=int(stats["passes"]), length_mm=summary.cutting_length,
                         simulated_s=summary.total_time, length_over_feed_s=summary.naive_time))
    return rows


def fastest(rows):
    """The row of least simulated time."""
    return min(rows, key=lambda row: row["simulated_s"])


def angle_ranges(angles_deg):
    """Contiguous runs of sampled directions as (first, last) pairs; a run through 0°/180° is one pair whose
    first angle is above its last (e.g. (153, 27))."""
    angles = sorted(float(a) for a in angles_deg)
    if not angles:
        return []
    steps = np.diff(angles)
    step = float(np.min(steps)) if len(steps) else 1.0
    runs = [[angles[0], angles[0]]]
    for angle in angles[1:]:
        if angle - runs[-1][1] <= step * 1.5:
            runs[-1][1] = angle
        else:
            runs.append([angle, angle])
    if len(runs) > 1 and runs[0][0] < step * 0.5 and runs[-1][1] > 180.0 - step * 1.5:
        runs[0][0] = runs.pop()[0]  # θ and θ + 180° are the same planes
    return [tuple(run) for run in runs]


def format_ranges(angles_deg):
    """'153°–27°, 60°–70°' for people to read."""
    return ", ".join("%g°" % a if a == b else "%g°–%g°" % (a, b) for a, b in angle_ranges(angles_deg))
