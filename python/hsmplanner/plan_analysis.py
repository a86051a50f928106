"""Plan-view (XY) shape measures of a curve sampled as points: signed curvature, radius, inflections.

The guidance-curve method looks at boundaries from above: their small radii and inflection points set the
discretisation step and the order of construction (paper §4.3). Numpy only; no FreeCAD.
"""
import numpy as np


def signed_curvature_xy(points):
    """Signed curvature (1/mm) of the XY projection at each point, by central differences on arc length.

    Positive turns left (counter-clockwise). End points copy their neighbours. Needs points spaced evenly
    enough along the curve (e.g. hsmplanner.sample_curve) and at least 5 of them.
    """
    xy = np.asarray(points, dtype=float)[:, :2]
    if len(xy) < 5:
        raise ValueError("plan curvature needs at least 5 points, got %d: sample the curve more finely" % len(xy))
    step = np.linalg.norm(np.diff(xy, axis=0), axis=1)
    if np.any(step <= 0.0):
        raise ValueError("plan curvature: consecutive points coincide in plan view; is the curve vertical?")
    s = np.concatenate([[0.0], np.cumsum(step)])
    dx, dy = np.gradient(xy[:, 0], s), np.gradient(xy[:, 1], s)
    ddx, ddy = np.gradient(dx, s), np.gradient(dy, s)
    kappa = (dx * ddy - dy * ddx) / np.power(dx * dx + dy * dy, 1.5)
    kappa[0], kappa[-1] = kappa[1], kappa[-2]
    return kappa


def min_radius_xy(points):
    """(smallest plan radius in mm, index of the point where it occurs)."""
    kappa = np.abs(signed_curvature_xy(points))
    index = int(np.argmax(kappa))
    return (float("inf") if kappa[index] == 0.0 else 1.0 / kappa[index]), index


def inflection_indices(points, min_curvature=1e-3):
    """Indices where the plan curvature changes sign between turns of at least `min_curvature` (1/mm).

    The threshold keeps numerical noise on straight stretches from counting as inflections.
    """
    kappa = signed_curvature_xy(points)
    significant = [(i, np.sign(k)) for i, k in enumerate(kappa) if abs(k) >= min_curvature]
    return [j for (i, a), (j, b) in zip(significant, significant[1:]) if a != b]
