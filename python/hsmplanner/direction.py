"""The machining direction of parallel-plane finishing, chosen by directional beams (Quinsat & Sabourin).

    result = hsmplanner.optimal_direction(face, tool_diameter=10, scallop=0.01, feed_mm_min=6000,
                                          spindle_rpm=15000, teeth=2, machine="mikron-ucp710-840d")
    result.angle_deg, result.alpha, result.acceptable

The feed may be given per tooth instead (feed_per_tooth=0.2: feed = fz·Z·N). The acceleration is the slowest
of the machine's X and Y axes (the paper's a_max), or acceleration_m_s2; use_jerk=True adds the jerk limit
∛(J·Rc²) of the same axes to the real feed. The rules are in cpp/direction/direction.hpp.
"""
import numpy as np

from . import _core
from .feedsim import load_machine
from .geometry import as_brep


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
    jerk = float(min(model.max_jerk[0], model.max_jerk[1])) if use_jerk and model is not None else 0.0
    return dict(tool_radius=0.5 * float(tool_diameter), scallop=float(scallop), feed=float(feed_mm_min) / 60.0,
                spindle_speed=float(spindle_rpm) / 60.0, teeth=int(teeth), acceleration=acceleration, jerk=jerk)


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
