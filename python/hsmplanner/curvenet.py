"""Curve nets between the two boundaries of a bottom feature (guidance-curve paper §3, §4.3).

Curves are given as FreeCAD edges or wires, BREP text, or (N, 3) arrays of points along the curve. Every
curve returned has sample(n) (an (n, 3) numpy array) and to_brep() (BREP text of an edge:
Part.Shape().importBrepFromString(text) or Part.Edge of it in FreeCAD). The rules the core follows where the
paper is silent are written in cpp/curvenet/curvenet.hpp and in docs/curve-nets.md.
"""
import numpy as np

from . import _core
from .core_settings import core_settings, enum_value
from .geometry import as_brep

MODES = tuple(_core.NetMode.__members__)  # b1_to_b2, b2_to_b1, median, median_to_boundaries, boundaries_to_median


def as_curve(curve, name="curve"):
    """A core B-spline from an edge/wire, BREP text, an (N,3) point array or a core curve."""
    if isinstance(curve, _core.BSplineCurve):
        return curve
    if isinstance(curve, _core.NetCurve):
        return curve.curve
    if isinstance(curve, str) or hasattr(curve, "exportBrepToString"):
        return _core.curve_from_brep(as_brep(curve))
    try:
        points = np.asarray(curve, dtype=float)
    except (TypeError, ValueError):
        points = None
    if points is None or points.ndim != 2 or points.shape[1] != 3:
        raise TypeError("%s must be a FreeCAD edge or wire, BREP text or an (N, 3) array of points, got %s"
                        % (name, type(curve).__name__))
    return _core.curve_from_points(points)


def _direction(direction):
    if direction is None:
        return None
    vector = np.asarray(tuple(direction), dtype=float)  # accepts FreeCAD.Vector, tuples, arrays
    if vector.shape != (3,):
        raise ValueError("direction must have 3 components (x, y, z), got %r" % (direction,))
    return vector


def _face(face):
    return None if face is None else as_brep(face)


def net_settings(step=None, direction=None, min_gap=None, fit_tolerance=None):
    """The core's NetSettings with what is given (None keeps the core's default: help(_core.NetSettings))."""
    return core_settings(_core.NetSettings, step=None if step is None else float(step), direction=_direction(direction),
                         min_gap=None if min_gap is None else float(min_gap),
                         fit_tolerance=None if fit_tolerance is None else float(fit_tolerance))


def intermediate_curve(a, b, k, step=None, direction=None, face=None, fit_tolerance=None):
    """The curve at ratio k from curve a towards curve b, built in planes spaced by at most `step` mm (eq. 1-2).

    direction: the machining direction (default: the curves' length direction); face: the bottom face the
    curve is put on along Z. Returns a NetCurve.
    """
    return _core.intermediate_curve(as_curve(a, "a"), as_curve(b, "b"), float(k),
                                    net_settings(step, direction, fit_tolerance=fit_tolerance), _face(face))


def curve_net(b1, b2, k, step=None, direction=None, mode=_core.NetMode.b1_to_b2, face=None, min_gap=None,
              fit_tolerance=None, progress=None):
    """A net of curves between boundaries b1 and b2; mode is a NetMode or its name (MODES). Returns a CurveNet.

    The net grows from its starting curve until a new curve would come closer than min_gap (mm) to its target.
    net.curves runs across the feature from B1 to B2; net.composed_areas() gives MA_1, MA_2… of the paper.
    progress: a callable progress(done) (share done, 0..1) that cancels by returning False. Defaults of
    step, min_gap and fit_tolerance are the core's (help(hsmplanner._core.NetSettings)).
    """
    return _core.curve_net(as_curve(b1, "b1"), as_curve(b2, "b2"), float(k), enum_value(_core.NetMode, mode, "mode"),
                           net_settings(step, direction, min_gap, fit_tolerance), _face(face), progress)


def guidance_curves(b1, b2, direction=None, face=None, step=None, k_median=None, k=None, min_gap=None,
                    fit_tolerance=None, min_step=None):
    """The paper's 4-step method (steps 1-3): median, adapted planes, one K=0.75 curve per half.

    Returns (CurveNet, GuidanceReport): the net B1, C1, Cmed, C2, B2 (fewer where a half needs no curve) and
    what the method chose (inflection planes, step range, which guide started each half). Defaults are the
    core's (help(hsmplanner._core.GuidanceSettings)).
    """
    settings = core_settings(_core.GuidanceSettings, k_median=None if k_median is None else float(k_median),
                             k=None if k is None else float(k), min_step=None if min_step is None else float(min_step))
    settings.net = net_settings(step, direction, min_gap, fit_tolerance)
    return _core.guidance_curves(as_curve(b1, "b1"), as_curve(b2, "b2"), settings, _face(face))


def area_regions(net, face):
    """Per elementary area of `net`: (lower index, upper index, BREP of its part of `face`, area in mm²)."""
    return net.regions(as_brep(face))
