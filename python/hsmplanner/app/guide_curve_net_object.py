"""Parametric "Guide curve net" document object (Part::FeaturePython).

Thin: links and numbers are wired to hsmplanner.app.guide_curve_net.build_guide_curve_net. Its Shape is what
the 3D view shows: a compound of the region faces (one or more per elementary area) followed by the curve
edges (display_edge_roles says which edge is which). The curves themselves, for whoever machines or reads
them, are the read-only CurveShapes: a compound of one edge per curve, B1 … B2, saved with the document
(net_curve_edges gives them as a list).
"""
import FreeCAD
import Part

from .properties import add_results
from .guide_curve_net import DEFAULT_MODE, MODES, NetParameters, build_guide_curve_net
from .progress import freecad_progress
from .property_limits import PropertyLimits
from .compat import set_shape
from .proxy_state import NoSavedState

TYPE_NAME = "Part::FeaturePython"

_INPUTS = [
    # (type, name, tooltip, default)
    ("App::PropertyLinkSub", "Boundary1", "first boundary: edge(s) between the bottom and a flank", None),
    ("App::PropertyLinkSub", "Boundary2", "second boundary: edge(s) on the other side of the bottom", None),
    ("App::PropertyLinkSub", "BottomFace", "the bottom face the curves lie on and the areas divide (optional)", None),
    ("App::PropertyFloat", "K", "ratio from the starting curve, in ]0,1[ (4-step method: after the median)",
     NetParameters.k),
    ("App::PropertyFloat", "KMedian", "ratio of the median curve (4-step method)", NetParameters.k_median),
    ("App::PropertyLength", "Step", "P: largest spacing of the planes (4-step method: initial step)",
     NetParameters.step),
    ("App::PropertyVector", "Direction", "machining direction; (0,0,0) = length direction of the boundaries",
     FreeCAD.Vector(0, 0, 0)),
    ("App::PropertyLength", "MinGap", "a net stops before a curve comes closer than this to its target",
     NetParameters.min_gap),
    ("App::PropertyLength", "FitTolerance", "B-spline approximation of the intermediate points",
     NetParameters.fit_tolerance),
]
_OUTPUTS = [
    ("App::PropertyStringList", "Curves", "labels of the curves, from boundary 1 to boundary 2"),
    ("App::PropertyStringList", "CurveRoles", "boundary, median or intermediate, per curve"),
    ("Part::PropertyPartShape", "CurveShapes", "the curves, one edge each, from boundary 1 to boundary 2"),
    ("App::PropertyStringList", "ComposedAreas", "composed machining areas MA1, MA2… as pairs of curves"),
    ("App::PropertyFloatList", "AreaSurfaces", "surface of each elementary area on the bottom face, mm²"),
    ("App::PropertyIntegerList", "FaceAreas", "elementary area of each face of the shape"),
    ("App::PropertyVector", "ChosenDirection", "machining direction used"),
    ("App::PropertyString", "PlaneSpacing", "spacing of the planes used, mm"),
    ("App::PropertyStringList", "Warnings", "what the construction had to decide"),
]


def linked_shape(link, name, faces=False):
    """The shape of a PropertyLinkSub value: its sub-elements (several edges make a chain) or the whole."""
    if not link or link[0] is None:
        raise ValueError("%s is not set: pick %s in the 3D view" % (name, "a face" if faces else "an edge"))
    obj, subs = link
    if isinstance(subs, str):
        subs = [subs]
    shapes = [obj.Shape.getElement(s) for s in subs if s] or [obj.Shape]
    if faces:
        found = [f for s in shapes for f in s.Faces]
        if len(found) != 1:
            raise ValueError("%s must be one face, got %d: pick a single face" % (name, len(found)))
        return found[0]
    return shapes[0] if len(shapes) == 1 else Part.Compound(shapes)


# The task panel's ranges (mm); the core's own limits are wider (P down to 0.01 mm).
LIMITS = {"K": (0.01, 0.99), "KMedian": (0.01, 0.99), "Step": (0.5, 40.0), "MinGap": (0.01, 50.0),
          "FitTolerance": (0.0001, 1.0)}


class GuideCurveNet(PropertyLimits, NoSavedState):
    LIMITS = LIMITS

    def __init__(self, obj):
        for prop_type, name, tooltip, default in _INPUTS:
            obj.addProperty(prop_type, name, "Guide curve net", tooltip)
            if default is not None:
                setattr(obj, name, default)
        obj.addProperty("App::PropertyEnumeration", "Mode", "Guide curve net", "how the net is built")
        obj.Mode = list(MODES)
        obj.Mode = DEFAULT_MODE
        add_results(obj, _OUTPUTS)
        obj.Proxy = self

    def onDocumentRestored(self, obj):
        """Documents saved before CurveShapes existed get it, filled from their Shape, whose curve edges
        came last (the only layout those files have): their nets machine as before without a recompute."""
        if "CurveShapes" in obj.PropertiesList:
            return
        prop_type, name, tooltip = next(output for output in _OUTPUTS if output[1] == "CurveShapes")
        obj.addProperty(prop_type, name, "Result", tooltip)
        obj.setEditorMode(name, 1)
        count = len(obj.Curves)
        if count and len(obj.Shape.Edges) >= count:
            obj.CurveShapes = Part.Compound(obj.Shape.Edges[-count:])

    @staticmethod
    def parameters(obj):
        direction = tuple(obj.Direction)
        return NetParameters(mode=obj.Mode, k=obj.K, step=obj.Step.Value,
                             direction=None if obj.Direction.Length < 1e-12 else direction,
                             min_gap=obj.MinGap.Value, fit_tolerance=obj.FitTolerance.Value, k_median=obj.KMedian)

    @staticmethod
    def inputs(obj):
        face = linked_shape(obj.BottomFace, "BottomFace", faces=True) if obj.BottomFace else None
        return linked_shape(obj.Boundary1, "Boundary1"), linked_shape(obj.Boundary2, "Boundary2"), face

    def execute(self, obj):
        b1, b2, face = self.inputs(obj)
        with freecad_progress("%s: curve net" % obj.Label) as progress:
            result = build_guide_curve_net(b1, b2, face, self.parameters(obj), progress=progress)
        faces, face_areas = [], []
        for index, (lower, upper, shape, _) in enumerate(result.regions):
            faces += shape.Faces
            face_areas += [index] * len(shape.Faces)
        obj.CurveShapes = Part.Compound(result.edges)
        set_shape(obj, Part.Compound(faces + result.edges))
        obj.Curves = result.labels
        obj.CurveRoles = [c.role.name for c in result.net.curves]
        obj.ComposedAreas = result.composed_area_names()
        obj.AreaSurfaces = [area for _, _, _, area in result.regions]
        obj.FaceAreas = face_areas
        obj.ChosenDirection = FreeCAD.Vector(*result.net.direction)
        stations = result.net.stations
        spacing = [b - a for a, b in zip(stations, stations[1:])]
        obj.PlaneSpacing = "%d planes, %.2f to %.2f mm apart" % (len(stations), min(spacing), max(spacing))
        obj.Warnings = list(result.net.warnings)


def net_curve_edges(obj):
    """The curves of a guide curve net object as Part edges, B1 … B2 (its CurveShapes, in their order)."""
    compound = getattr(obj, "CurveShapes", None)
    edges = [] if compound is None or compound.isNull() else compound.childShapes()
    if len(edges) < 2 or any(edge.ShapeType != "Edge" for edge in edges):
        raise ValueError("the guide curve net %s has no curves: recompute it" % obj.Label)
    return edges


def display_edge_roles(obj):
    """What each edge of the object's Shape is, for its colours in the 3D view: None for the borders of the
    areas, then the role of each curve (execute puts the curve edges after the faces' edges); None when the
    properties do not match yet (mid-recompute)."""
    edges, roles = obj.Shape.Edges, list(obj.CurveRoles)
    if len(obj.Shape.Faces) != len(obj.FaceAreas) or len(edges) < len(roles):
        return None
    return [None] * (len(edges) - len(roles)) + roles


def create(document=None, boundary_1=None, boundary_2=None, bottom_face=None, name="GuideCurveNet", **values):
    """Add a guide curve net. boundary_1/2 and bottom_face are (object, "EdgeN"/"FaceN") pairs; values set
    properties (K=0.25, Mode="Median to boundaries", …). Recomputes when both boundaries are given."""
    document = document or FreeCAD.ActiveDocument
    if document is None:
        raise ValueError("no document to add the guide curve net to: open or create a document first")
    obj = document.addObject(TYPE_NAME, name)
    GuideCurveNet(obj)
    for prop, link in (("Boundary1", boundary_1), ("Boundary2", boundary_2), ("BottomFace", bottom_face)):
        if link is not None:
            setattr(obj, prop, link)
    for prop, value in values.items():
        if prop not in obj.PropertiesList:
            raise ValueError("guide curve net has no property %r: use one of %s"
                             % (prop, ", ".join(name for _, name, _, _ in _INPUTS) + ", Mode"))
        setattr(obj, prop, value)
    if boundary_1 is not None and boundary_2 is not None:
        obj.recompute()
    return obj
