"""Parametric document object of the master bottom feature (Part::FeaturePython).

Thin: properties are wired to hsmplanner.app.master_feature.make_master_bottom_feature. The names of the
bottom face and of the boundary edges are published as read-only properties for the curve-net objects.
"""
import FreeCAD

from .master_feature import MasterFeatureParameters, make_master_bottom_feature
from .compat import set_shape
from .proxy_state import NoSavedState

TYPE_NAME = "Part::FeaturePython"

# (property type, name, group, tooltip, default) of the editable dimensions
_DIMENSIONS = [
    ("App::PropertyLength", "Length", "along X, the machining direction", 140.0),
    ("App::PropertyLength", "Width", "distance between the boundaries at x = 0", 50.0),
    ("App::PropertyLength", "Depth", "mean depth of the bottom below the top face", 25.0),
    ("App::PropertyLength", "Sag", "extra dip of the bottom at mid-length", 5.0),
    ("App::PropertyAngle", "DraftAngle", "draft of the flanks from vertical", 5.0),
]
_TOPOLOGY = [
    ("BottomFace", "name of the curved bottom face, e.g. Face4"),
    ("Boundary1", "edge between the bottom and flank 1 (the curve with the bump and the inflection)"),
    ("Boundary2", "edge between the bottom and flank 2"),
]


class MasterBottomFeature(NoSavedState):
    def __init__(self, obj):
        for prop_type, name, tooltip, default in _DIMENSIONS:
            obj.addProperty(prop_type, name, "Master bottom feature", tooltip)
            setattr(obj, name, default)
        for name, tooltip in _TOPOLOGY:
            obj.addProperty("App::PropertyString", name, "Topology", tooltip)
            obj.setEditorMode(name, 1)  # read-only: computed by execute()
        obj.Proxy = self

    def parameters(self, obj):
        return MasterFeatureParameters(
            length=obj.Length.Value, width=obj.Width.Value, depth=obj.Depth.Value,
            sag=obj.Sag.Value, draft_angle=obj.DraftAngle.Value)

    def execute(self, obj):
        feature = make_master_bottom_feature(self.parameters(obj))
        set_shape(obj, feature.shape)
        obj.BottomFace, obj.Boundary1, obj.Boundary2 = feature.bottom_face, feature.boundary_1, feature.boundary_2


def create(document=None, name="MasterBottomFeature"):
    """Add a master bottom feature to `document` (the active one by default), recomputed."""
    document = document or FreeCAD.ActiveDocument
    if document is None:
        raise ValueError("no document to add the master bottom feature to: open or create a document first")
    obj = document.addObject(TYPE_NAME, name)
    MasterBottomFeature(obj)
    obj.recompute()
    return obj
