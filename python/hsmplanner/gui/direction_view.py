"""Coin scene of a machining direction analysis: at sample points spread over the face, a stroke along the
best local direction coloured by G_pmax as a share of the face's best (red: where the surface is slowest to
finish), and the chosen direction as a double arrow above the face, with a legend."""
import numpy as np
from pivy import coin

from hsmplanner.plots.common import feed_colors

from .feedmap import DIRECTION_LEGEND_SPAN, legend_node, line_set

LIFT = 0.3  # mm above the face, so that the strokes are not hidden in it


def thinned(points, count):
    """Indices of about `count` points spread evenly in plan: the first point in each cell of a square grid."""
    extent = np.maximum(np.ptp(points[:, :2], axis=0), 1e-9)
    cell = np.sqrt(extent[0] * extent[1] / max(count, 1))
    keys = np.floor((points[:, :2] - points[:, :2].min(axis=0)) / cell).astype(np.int64)
    _, first = np.unique(keys[:, 0] * 1_000_003 + keys[:, 1], return_index=True)
    return np.sort(first), cell


def strokes(points, angles_deg, count):
    """About `count` strokes (2 × 3 arrays) centred on points spread over the face, along their angles."""
    points = np.asarray(points, dtype=float)
    chosen, cell = thinned(points, count)
    half = 0.35 * cell
    angles = np.radians(np.asarray(angles_deg, dtype=float)[chosen])
    offset = np.column_stack([np.cos(angles), np.sin(angles), np.zeros(len(chosen))]) * half
    centres = points[chosen] + [0.0, 0.0, LIFT]
    return [np.vstack([c - o, c + o]) for c, o in zip(centres, offset)], chosen


def chosen_arrow(points, angle_deg):
    """A double arrow along angle_deg across the middle of the points, above the highest of them."""
    points = np.asarray(points, dtype=float)
    centre = np.array([*points[:, :2].mean(axis=0), points[:, 2].max() + 2.0])
    half = 0.4 * float(np.ptp(points[:, 0]) + np.ptp(points[:, 1])) / 2.0
    a = np.radians(angle_deg)
    along, across = np.array([np.cos(a), np.sin(a), 0.0]), np.array([-np.sin(a), np.cos(a), 0.0])
    tip, tail = centre + half * along, centre - half * along
    head = 0.15 * half  # large enough to read as arrow heads from the whole face's view
    lines = [np.vstack([tail, tip])]
    for end, sense in ((tip, -1.0), (tail, 1.0)):
        lines += [np.vstack([end, end + head * (sense * along + 0.6 * side)]) for side in (across, -across)]
    return lines


def direction_node(result, chosen_deg, arrows):
    root = coin.SoSeparator()
    if result is None or len(result.points) == 0:
        return root
    lines, chosen = strokes(result.points, result.best_angle_deg, arrows)
    values = np.asarray(result.fitness_max, dtype=float)
    low, high = fitness_scale(values)
    root.addChild(line_set(lines, feed_colors((values[chosen] - low) / (high - low)), width=2.0))
    arrow = chosen_arrow(result.points, chosen_deg)
    root.addChild(line_set(arrow, np.tile([0.85, 0.1, 0.1], (len(arrow), 1)), width=5.0))
    root.addChild(legend_node(low, high, "mm²", title="best local G_p", digits=4, span=DIRECTION_LEGEND_SPAN))
    return root


def fitness_scale(values):
    """The colour scale of G_pmax: from the face's lowest to its highest (from 0 the colours of a face whose
    G_pmax varies by 1 % were all the same green); a uniform face gets a scale of ±1 % around its value."""
    low, high = float(np.min(values)), float(np.max(values))
    if high - low <= 1e-9 * max(abs(high), 1e-12):
        low, high = 0.99 * high, 1.01 * high + 1e-12
    return low, high
