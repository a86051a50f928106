"""View providers of HSM Planner document objects (their class names are saved in documents)."""
from hsmplanner.app.proxy_state import NoSavedState
from hsmplanner.resources import icon

from .colors import CURVE_COLORS, REGION_BORDER, area_color, view_color


class _StatelessViewProvider(NoSavedState):
    """Common part: the object, the icon, nothing to save (0.20 and 1.x spellings)."""

    ICON = "HSMPlanner"

    def __init__(self, view_object):
        view_object.Proxy = self

    def attach(self, view_object):
        self.Object = view_object.Object

    def getIcon(self):
        return icon(self.ICON)


class ViewProviderMasterBottomFeature(_StatelessViewProvider):
    ICON = "MasterBottomFeature"


def display_deflection(obj):
    """How far FreeCAD's tessellation of `obj` may stray from its surface, mm (its formula: the sum of the
    bounding box's extents / 300 × Deviation)."""
    box, view = obj.Shape.BoundBox, obj.ViewObject
    return (box.XLength + box.YLength + box.ZLength) / 300.0 * float(getattr(view, "Deviation", 0.5))


def lift_over_the_part(net):
    """The net's areas are pieces of the part's bottom face: drawn at the same place, the two tessellations
    (each within its own deflection, ~0.5 mm) cross each other and the part showed through in blotches.
    The net is drawn higher by more than both deflections (a display-only translation at the head of its
    scene; its geometry, the picked edges and the saved shape are untouched). FreeCAD's polygon offset
    cannot be used: it is reset on every update, and it would not bridge two tessellations. Returns the
    lift, mm."""
    from pivy import coin

    root = net.ViewObject.RootNode
    part = net.BottomFace[0] if net.BottomFace else None
    lift = 1.5 * max(display_deflection(net), display_deflection(part) if part is not None else 0.0, 0.01)
    for i in range(root.getNumChildren()):
        if root.getChild(i).getName() == "HsmLift":
            root.getChild(i).translation.setValue(0.0, 0.0, lift)
            return lift
    node = coin.SoTranslation()
    node.setName("HsmLift")
    node.translation.setValue(0.0, 0.0, lift)
    root.insertChild(node, 0)
    return lift


class ViewProviderGuideCurveNet(_StatelessViewProvider):
    """Elementary areas in distinct colours, curves by role (boundary, median, intermediate)."""

    ICON = "GuideCurveNet"
    COLOURED_BY = ("Shape", "FaceAreas", "CurveRoles")

    def attach(self, view_object):
        super().attach(view_object)
        view_object.LineWidth = 3.0

    def updateData(self, obj, prop):
        if prop in self.COLOURED_BY:
            self.colour(obj)

    def colour(self, obj):
        from hsmplanner.app.guide_curve_net_object import display_edge_roles

        view = obj.ViewObject
        roles = display_edge_roles(obj)
        if view is None or roles is None:
            return  # mid-recompute: the properties do not match yet
        view.DiffuseColor = [view_color(area_color(index)) for index in obj.FaceAreas]
        lift_over_the_part(obj)
        view.LineColorArray = [view_color(REGION_BORDER if role is None else CURVE_COLORS.get(role, (0, 0, 0)))
                               for role in roles]

    def doubleClicked(self, view_object):
        import FreeCADGui

        FreeCADGui.ActiveDocument.setEdit(view_object.Object.Name)
        return True

    def setEdit(self, view_object, mode=0):
        import FreeCADGui

        from .guide_curve_net_panel import GuideCurveNetPanel

        FreeCADGui.Control.showDialog(GuideCurveNetPanel(view_object.Object,
                                                         created=getattr(self, "created", False)))
        self.created = False
        return True

    def unsetEdit(self, view_object, mode=0):
        import FreeCADGui

        FreeCADGui.Control.closeDialog()
        return True


class _AnalysisViewProvider(_StatelessViewProvider):
    """An analysis drawn as one Coin scene (redrawn when its `REDRAW_ON` properties change), edited in its
    task panel."""

    REDRAW_ON = ()

    def attach(self, view_object):
        from pivy import coin

        super().attach(view_object)
        self.root = coin.SoSeparator()
        view_object.addDisplayMode(self.root, "Map")

    def getDisplayModes(self, view_object):
        return ["Map"]

    def getDefaultDisplayMode(self):
        return "Map"

    def setDisplayMode(self, mode):
        return mode

    def updateData(self, obj, prop):
        if prop in self.REDRAW_ON:
            self.redraw(obj)

    def onChanged(self, view_object, prop):
        pass

    def redraw(self, obj):
        if not hasattr(self, "root"):
            return
        self.root.removeAllChildren()
        node = self.scene(obj) if obj.Proxy else None
        if node is not None:
            self.root.addChild(node)

    def doubleClicked(self, view_object):
        import FreeCADGui

        FreeCADGui.ActiveDocument.setEdit(view_object.Object.Name)
        return True

    def setEdit(self, view_object, mode=0):
        import FreeCADGui

        FreeCADGui.Control.showDialog(self.panel(view_object.Object))
        return True

    def unsetEdit(self, view_object, mode=0):
        import FreeCADGui

        FreeCADGui.Control.closeDialog()
        return True


class ViewProviderFeedRateAnalysis(_AnalysisViewProvider):
    """The feed-rate map of the simulated path, with its legend."""

    ICON = "FeedRateAnalysis"
    REDRAW_ON = ("TotalTime", "ColorBy")

    def scene(self, obj):
        from .feedmap import map_node

        result = obj.Proxy.ensure_result(obj)
        return map_node(result.blocks, obj.ColorBy) if result is not None and len(result.blocks["line"]) else None

    def panel(self, obj):
        from .feedrate_panel import FeedRatePanel

        return FeedRatePanel(obj)


class ViewProviderCycleTime(_AnalysisViewProvider):
    """A Job's cycle time: nothing drawn in the 3D view, its table in the task panel."""

    ICON = "CycleTime"

    def scene(self, obj):
        return None

    def panel(self, obj):
        from .cycle_time_panel import CycleTimePanel

        return CycleTimePanel(obj)


class ViewProviderMachiningDirection(_AnalysisViewProvider):
    """Strokes of the best local direction on the face, coloured by G_pmax, and the chosen direction."""

    ICON = "MachiningDirection"
    REDRAW_ON = ("ChosenAngle", "Arrows")

    def scene(self, obj):
        from .direction_view import direction_node

        return direction_node(obj.Proxy.ensure_result(obj), obj.ChosenAngle.Value, obj.Arrows)

    def panel(self, obj):
        from .direction_panel import DirectionPanel

        return DirectionPanel(obj)


class ViewProviderSlantedSlotBlock(_StatelessViewProvider):
    ICON = "SlantedSlotBlock"


class ViewProviderImpeller(_StatelessViewProvider):
    ICON = "Impeller"


class ViewProviderTestPartStock(_StatelessViewProvider):
    """The blank of a roughing test part; its command shows it as a wireframe, so that the part shows."""

    ICON = "TestPartStock"


def _linked_deflection(obj):
    """The display deflection of a linked object (a Job's stock for a Job), 0 when it has no view."""
    if obj is None:
        return 0.0
    from hsmplanner.app.roughing.volume import job_stock, is_job

    if is_job(obj):
        obj = job_stock(obj)
    if obj is None or getattr(obj, "ViewObject", None) is None or obj.Shape.isNull():
        return 0.0
    return display_deflection(obj)


class ViewProviderRoughingVolume(_StatelessViewProvider):
    """The volume to remove, its faces coloured by class (or its sub-volumes by slice), a little transparent and
    inset from the part's coincident faces (gui/roughing_view.py says why), with a legend; edited in its task
    panel. FreeCAD's own display modes show the same colours (DiffuseColor)."""

    ICON = "RoughingVolume"
    MODE = "Roughing"
    TRANSPARENCY = 30

    def __init__(self, view_object):
        super().__init__(view_object)
        view_object.Transparency = self.TRANSPARENCY

    def attach(self, view_object):
        from pivy import coin

        super().attach(view_object)
        self.root = coin.SoSeparator()
        view_object.addDisplayMode(self.root, self.MODE)

    def getDisplayModes(self, view_object):
        return [self.MODE]

    def getDefaultDisplayMode(self):
        return self.MODE

    def setDisplayMode(self, mode):
        return mode

    def updateData(self, obj, prop):
        # execute sets FaceColorIndex last, after Shape; an undo or a reopened file may set them in any order
        if prop == "FaceColorIndex" or (prop == "Shape" and "Recompute" not in obj.State):
            self.redraw(obj)

    def onChanged(self, view_object, prop):
        if prop in ("Transparency", "Deviation") and getattr(self, "Object", None) is not None \
                and not getattr(self, "drawing", False):
            self.redraw(self.Object)

    def inset(self, obj):
        """How far the faces are drawn inside the volume: more than its own and the part's and the stock's
        tessellation deflections (mm)."""
        return 1.5 * max(display_deflection(obj), _linked_deflection(getattr(obj, "Part", None)),
                         _linked_deflection(getattr(obj, "Stock", None)), 0.01)

    def redraw(self, obj):
        root = getattr(self, "root", None)
        if root is None or getattr(self, "drawing", False):
            return
        self.drawing = True  # FreeCAD may echo DiffuseColor into Transparency: no redraw from within
        try:
            self.draw(obj, root)
        finally:
            self.drawing = False

    def draw(self, obj, root):
        import FreeCAD

        from hsmplanner.app.roughing.volume import SUB_VOLUMES, shown_display

        from .roughing_view import palette, volume_node

        root.removeAllChildren()
        self.drawn, self.triangle_faces = None, []
        shape, codes = obj.Shape, list(obj.FaceColorIndex)
        if shape.isNull() or len(shape.Faces) != len(codes) or obj.ViewObject is None:
            return  # nothing computed, or mid-recompute: the properties do not match yet
        local = shape.copy()
        local.Placement = FreeCAD.Placement()  # the view's own transform places it
        sub_volumes = shown_display(obj) == SUB_VOLUMES
        transparency = obj.ViewObject.Transparency / 100.0
        node, self.triangle_faces = volume_node(local, codes, sub_volumes, display_deflection(obj), self.inset(obj),
                                                transparency)
        if node is not None:
            root.addChild(node)
        self.colour_faces(obj, codes, sub_volumes, transparency)
        colors, labels = palette(sub_volumes)
        self.drawn = dict(colors=[tuple(c) for c in colors], labels=list(labels),  # what is drawn, for tests
                          faces=[tuple(colors[code % len(colors)]) for code in codes])

    def getElement(self, detail):
        """The face picked in the Roughing mode: our faces are triangles (FreeCAD would name the triangle's
        number); '' elsewhere, so that FreeCAD names what its own modes picked."""
        from pivy import coin

        faces = getattr(self, "triangle_faces", [])
        view = getattr(getattr(self, "Object", None), "ViewObject", None)
        if view is None or view.DisplayMode != self.MODE or not detail.isOfType(coin.SoFaceDetail.getClassTypeId()):
            return ""
        index = coin.cast(detail, "SoFaceDetail").getFaceIndex()
        return "Face%d" % (int(faces[index]) + 1) if 0 <= index < len(faces) else ""

    @staticmethod
    def colour_faces(obj, codes, sub_volumes, transparency):
        """The same colours in FreeCAD's own display modes (Flat Lines, Shaded)."""
        from .roughing_view import palette

        colors, _ = palette(sub_volumes)
        obj.ViewObject.DiffuseColor = [view_color(colors[code % len(colors)], transparency) for code in codes]

    def doubleClicked(self, view_object):
        import FreeCADGui

        FreeCADGui.ActiveDocument.setEdit(view_object.Object.Name)
        return True

    def setEdit(self, view_object, mode=0):
        import FreeCADGui

        from .roughing_panel import RoughingPanel

        FreeCADGui.Control.showDialog(RoughingPanel(view_object.Object, created=getattr(self, "created", False)))
        self.created = False
        return True

    def unsetEdit(self, view_object, mode=0):
        import FreeCADGui

        FreeCADGui.Control.closeDialog()
        return True
