"""Ball-end finishing toolpaths of a bottom face (no FreeCAD needed): parallel planes and guide curves.

    moves, stats = hsmplanner.parallel_finishing(part, "Face4", angle_deg=0.0, tool_diameter=4.0)
    moves, stats = hsmplanner.guide_finishing(part, "Face4", net, tool_diameter=4.0)

`part` is the solid (a FreeCAD shape or BREP text) and the bottom face its FreeCAD name ("Face4") or
number. The result is `moves`, an (N, 4) array of tool-tip positions x, y, z (mm) and a rapid flag (1 for
G0), and `stats` (passes, dropped_points, safe_height, warnings). The rules are in
cpp/toolpath/finishing.hpp: cusp height kept on the real surface, gouge-free drop-cutter positions, G1
points within the tolerance, upward or downward sweeping, zigzag or one-way.
"""
import numpy as np

from . import _core
from .core_settings import core_settings, enum_value
from .curvenet import as_curve
from .geometry import as_brep

SWEEPS = tuple(_core.Sweep.__members__)  # upward, downward


def face_number(face):
    """1-based face number from 'Face4', 4 or '4'."""
    text = str(face)
    number = text[4:] if text.startswith("Face") else text
    if not number.isdigit() or int(number) < 1:
        raise ValueError("bottom face %r is not a face name: use FreeCAD's name, e.g. 'Face4'" % (face,))
    return int(number)


def finishing_settings(tool_diameter=None, cusp_height=None, tolerance=None, sweep=None, zigzag=None, clearance=None,
                       threads=None, extension=None):
    """The core's FinishingSettings with what is given (None keeps the core's default:
    help(hsmplanner._core.FinishingSettings)); sweep is a Sweep or its name."""
    if tool_diameter is not None and not tool_diameter > 0:
        raise ValueError("tool diameter %r mm must be positive" % (tool_diameter,))
    return core_settings(_core.FinishingSettings,
                         tool_radius=None if tool_diameter is None else 0.5 * float(tool_diameter),
                         cusp_height=None if cusp_height is None else float(cusp_height),
                         tolerance=None if tolerance is None else float(tolerance),
                         sweep=None if sweep is None else enum_value(_core.Sweep, sweep, "sweep"),
                         zigzag=None if zigzag is None else bool(zigzag),
                         clearance=None if clearance is None else float(clearance),
                         threads=None if threads is None else int(threads),
                         extension=None if extension is None else float(extension))


def check_finishing(tool_diameter=None, cusp_height=None, tolerance=None, sweep=None, zigzag=None, clearance=None,
                    threads=None, extension=None):
    """ValueError naming a finishing setting outside its limits (a cusp at or above the ball's radius…), as
    every finishing checks first: for a caller about to start many (a strategy study)."""
    _core.check_finishing_settings(finishing_settings(tool_diameter, cusp_height, tolerance, sweep, zigzag, clearance,
                                                      threads, extension))


def parallel_finishing(part, bottom_face, angle_deg=0.0, tool_diameter=None, cusp_height=None, tolerance=None,
                       sweep=None, zigzag=None, clearance=None, threads=None, extension=None, progress=None):
    """Planes containing the tool axis at angle_deg from X, spaced for the cusp height. Settings left out take
    the core's defaults (help(hsmplanner._core.FinishingSettings): Ø4 ball, cusp and tolerance 0.01 mm,
    upward zigzag).

    progress: a callable progress(done) called with the share done (0..1); returning False cancels the
    computation (hsmplanner.Cancelled is raised)."""
    return _core.parallel_finishing(as_brep(part), face_number(bottom_face), float(angle_deg),
                                    finishing_settings(tool_diameter, cusp_height, tolerance, sweep, zigzag,
                                                       clearance, threads, extension), progress)


def guide_areas(areas):
    """Areas as (first, second) core curves, from a CurveNet (its elementary areas, B1 side first) or a list
    of pairs of edges/arrays/curves."""
    if isinstance(areas, _core.CurveNet):
        return [(areas.curves[a].curve, areas.curves[b].curve) for a, b in areas.elementary_areas()]
    pairs = list(areas)
    if not pairs:
        raise ValueError("no area to machine: give a curve net or pairs of guide curves")
    return [(as_curve(a, "guide"), as_curve(b, "guide")) for a, b in pairs]


def guide_finishing(part, bottom_face, areas, direction=(1.0, 0.0, 0.0), tool_diameter=None, cusp_height=None,
                    tolerance=None, sweep=None, zigzag=None, clearance=None, threads=None, extension=None,
                    progress=None):
    """Passes morphed between the guides of each area, areas in the order given (a CurveNet: B1 to B2).
    progress: as for parallel_finishing."""
    direction = np.asarray(tuple(direction), dtype=float)
    if isinstance(areas, _core.CurveNet):
        direction = np.asarray(areas.direction, dtype=float)
    return _core.guide_finishing(as_brep(part), face_number(bottom_face), guide_areas(areas), direction,
                                 finishing_settings(tool_diameter, cusp_height, tolerance, sweep, zigzag, clearance,
                                                    threads, extension), progress)


def path_length(moves, rapid=False):
    """Length (mm) of the feed moves (or of the rapid ones)."""
    moves = np.asarray(moves)
    steps = np.linalg.norm(np.diff(moves[:, :3], axis=0), axis=1)
    kind = moves[1:, 3] == (1.0 if rapid else 0.0)
    return float(steps[kind].sum())


def moves_to_gcode(moves, feed_mm_min):
    """Plain ISO G-code of `moves` (G0 where rapid, G1 at `feed_mm_min`), absolute, mm: what any of our
    machine models reads, with the controller's default rounding tolerance."""
    if not feed_mm_min > 0:
        raise ValueError("feed %r mm/min must be positive" % (feed_mm_min,))
    lines = ["G90 G17", "G1 F%g" % feed_mm_min]
    lines += ["%s X%.4f Y%.4f Z%.4f" % ("G0" if rapid else "G1", x, y, z) for x, y, z, rapid in np.asarray(moves)]
    return "\n".join(lines + ["M30", ""])
