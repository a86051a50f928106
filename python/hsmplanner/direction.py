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
from .feedsim import load_machine, simulate
from .geometry import as_brep
from .toolpaths import moves_to_gcode, parallel_finishing


def cutting_conditions(tool_diameter, scallop, feed_mm_min=None, spindle_rpm=15000.0, teeth=2,
                       feed_per_tooth=None, machine="mikron-ucp710-840d", acceleration_m_s2=None, use_jerk=False):
    """Keyword arguments of the core in its units (mm, s), from the ones people type."""
    if feed_per_tooth is not None:
        feed_mm_min = float(feed_per_tooth) * teeth * spindle_rpm
    if feed_mm_min is None:
        raise ValueError("give the programmed feed (feed_mm_min) or the feed per tooth (feed_per_tooth)")
    model = load_machine(machine) if machine is not None else None
    if acceleration_m_s2 is not None:
        acceleration = 1000.0 * float(acceleration_m_s2)
    elif model is not None:
        acceleration = float(min(model.max_acceleration[0], model.max_acceleration[1]))
    else:
        raise ValueError("give a machine or acceleration_m_s2 (the slowest axis)")
    stop_jerk = float(min(model.max_jerk[0], model.max_jerk[1])) if model is not None else 0.0
    return dict(tool_radius=0.5 * float(tool_diameter), scallop=float(scallop), feed=float(feed_mm_min) / 60.0,
                spindle_speed=float(spindle_rpm) / 60.0, teeth=int(teeth), acceleration=acceleration,
                jerk=stop_jerk if use_jerk else 0.0, stop_jerk=stop_jerk)


def optimal_direction(face, tool_diameter=10.0, scallop=0.01, feed_mm_min=None, spindle_rpm=15000.0, teeth=2,
                      feed_per_tooth=None, machine="mikron-ucp710-840d", acceleration_m_s2=None, use_jerk=False,
                      grid=50, angle_step=1.0, alpha=0.95):
    """The optimal direction θ (degrees from X) of parallel planes over `face`, its α and the acceptable
    directions (those within `alpha` of the local optimum at every point, or within α* when α* < alpha)."""
    conditions = cutting_conditions(tool_diameter, scallop, feed_mm_min, spindle_rpm, teeth, feed_per_tooth, machine,
                                    acceleration_m_s2, use_jerk)
    return _core.optimal_direction(as_brep(face), grid_u=int(grid), grid_v=int(grid), angle_step=float(angle_step),
                                   report_alpha=float(alpha), **conditions)


def directions_over_feeds(face, feeds_mm_min, **kwargs):
    """(feed, optimal angle, acceptable angles) for each programmed feed: the paper's Fig. 10."""
    rows = []
    for feed in feeds_mm_min:
        result = optimal_direction(face, feed_mm_min=feed, **kwargs)
        rows.append((float(feed), result.angle_deg, np.asarray(result.acceptable)))
    return rows


def simulated_directions(part, face, angles_deg=range(0, 181, 10), tool_diameter=10.0, scallop=0.01,
                         feed_mm_min=6000.0, machine="mikron-ucp710-840d", tolerance=0.01, progress=None):
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
        summary = simulate(moves_to_gcode(moves, feed_mm_min), machine).summary
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
