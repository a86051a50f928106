"""Shapes in, arrays out: adapters between FreeCAD/Part shapes and the core's BREP interface."""
import numpy as np

from . import _core


def as_brep(shape):
    """BREP text of a FreeCAD Part shape (edge, wire, face, solid…) or of BREP text itself."""
    if isinstance(shape, str):
        return shape
    export = getattr(shape, "exportBrepToString", None)
    if export is None:
        raise TypeError(
            "expected a FreeCAD Part shape (edge, wire, face…) or BREP text, got %s: pass obj.Shape "
            "or Shape.exportBrepToString()" % type(shape).__name__
        )
    if getattr(shape, "isNull", lambda: False)():
        raise ValueError("shape is null: pass a shape that holds geometry")
    return export()


FREECAD_LIB = "/usr/lib/freecad-python3/lib"


def shape_from_brep(text):
    """The FreeCAD Part shape of BREP text (as_brep's inverse; needs FreeCAD's Part module)."""
    import sys

    if FREECAD_LIB not in sys.path:  # a plain /usr/bin/python3 (a study's worker): FreeCAD's modules, Debian's place
        sys.path.append(FREECAD_LIB)
    import FreeCAD  # noqa: F401 (before Part: Part alone crashes outside freecadcmd)
    import Part

    shape = Part.Shape()
    shape.importBrepFromString(text)
    return shape


def shape_summary(shape):
    """Topology counts, volume (mm³), area (mm²), edge length (mm), bounds and validity of a shape."""
    return _core.summarize_brep(as_brep(shape))


def sample_curve(curve, count):
    """(count, 3) numpy array of points equally spaced by arc length along an edge or a wire."""
    return np.asarray(_core.sample_curve_brep(as_brep(curve), int(count)))


def drop_on_face(face, points, axis=(0.0, 0.0, 1.0)):
    """Points moved onto `face` along `axis` (plan position kept): ((N,3) array, (N,) bool inside the face)."""
    dropped, inside = _core.drop_on_face(as_brep(face), np.asarray(points, dtype=float).reshape(-1, 3),
                                         np.asarray(tuple(axis), dtype=float))
    return np.asarray(dropped), np.asarray(inside, dtype=bool)
