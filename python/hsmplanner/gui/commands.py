"""FreeCAD commands of the HSM Planner workbench."""
import FreeCAD
import FreeCADGui

from hsmplanner.resources import icon

COMMAND_NAMES = ["HSM_MasterBottomFeature", "HSM_GuideCurveNet", "HSM_GuideCurveFinishing",
                 "HSM_ParallelPlaneFinishing", "HSM_MachiningDirection", "HSM_FeedRateAnalysis"]


class CommandMasterBottomFeature:
    """Add the parametric master bottom feature (the guidance-curve paper's test part) to the document."""

    def GetResources(self):
        return {
            "Pixmap": icon("MasterBottomFeature"),
            "MenuText": "Master bottom feature",
            "ToolTip": "Add the parametric test part of the guidance-curve paper: a curved bottom between two "
                       "curved, non-parallel flanks, open at both ends",
        }

    def IsActive(self):
        return True

    def Activated(self):
        from hsmplanner.app import master_feature_object
        from hsmplanner.gui.view_providers import ViewProviderMasterBottomFeature

        document = FreeCAD.ActiveDocument or FreeCAD.newDocument("HSMPlanner")
        document.openTransaction("Add master bottom feature")
        try:
            obj = master_feature_object.create(document)
            ViewProviderMasterBottomFeature(obj.ViewObject)
        finally:
            document.commitTransaction()
        FreeCADGui.SendMsgToActiveView("ViewFit")
        FreeCADGui.activeDocument().activeView().viewIsometric()
        return obj


class CommandGuideCurveNet:
    """Add a guide curve net and open its panel (the selected edges and face are taken as its inputs)."""

    def GetResources(self):
        return {
            "Pixmap": icon("GuideCurveNet"),
            "MenuText": "Guide curve net",
            "ToolTip": "Intermediate curves between two boundary edges of a bottom face, with K and P set live; "
                       "select the two edges (and the bottom face) first, or pick them in the panel",
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from hsmplanner.app import guide_curve_net_object
        from hsmplanner.gui.view_providers import ViewProviderGuideCurveNet

        document = FreeCAD.ActiveDocument
        document.openTransaction("Add guide curve net")
        obj = guide_curve_net_object.create(document)
        view_provider = ViewProviderGuideCurveNet(obj.ViewObject)
        view_provider.created = True
        FreeCADGui.ActiveDocument.setEdit(obj.Name)
        return obj


class CommandFeedRateAnalysis:
    """Simulate the selected Job or operation on a machine model: feed-rate map, histograms, times."""

    def GetResources(self):
        return {
            "Pixmap": icon("FeedRateAnalysis"),
            "MenuText": "Feed-rate analysis",
            "ToolTip": "Simulate what the machine really does on the selected Job or operation: machining time "
                       "against length/feed, feed classes, and a map of the reached feed on the path",
        }

    @staticmethod
    def selected_source():
        from hsmplanner.app.feedrate import is_simulatable

        selection = FreeCADGui.Selection.getSelection()
        return selection[0] if len(selection) == 1 and is_simulatable(selection[0]) else None

    def IsActive(self):
        return self.selected_source() is not None

    def Activated(self):
        from hsmplanner.app import feedrate_object
        from hsmplanner.gui.view_providers import ViewProviderFeedRateAnalysis

        source = self.selected_source()
        document = source.Document
        document.openTransaction("Feed-rate analysis")
        try:
            obj = feedrate_object.create(source, document=document)
            ViewProviderFeedRateAnalysis(obj.ViewObject)
            obj.ViewObject.Proxy.redraw(obj)
        finally:
            document.commitTransaction()
        FreeCADGui.ActiveDocument.setEdit(obj.Name)
        return obj


class CommandMachiningDirection:
    """The raster angle of parallel-plane finishing for the selected face, by directional beams."""

    def GetResources(self):
        return {
            "Pixmap": icon("MachiningDirection"),
            "MenuText": "Machining direction",
            "ToolTip": "Choose the angle of parallel planes over the selected face: directional beams, the least "
                       "predicted time, or planes simulated on the machine; arrows of the best local direction",
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from hsmplanner.app import direction_object
        from hsmplanner.gui.task_panel import selected_faces
        from hsmplanner.gui.view_providers import ViewProviderMachiningDirection

        document = FreeCAD.ActiveDocument
        document.openTransaction("Machining direction")
        try:
            obj = direction_object.create(document=document)
            ViewProviderMachiningDirection(obj.ViewObject)
            faces = selected_faces()
            if len(faces) == 1:
                obj.Face = (faces[0][0], [faces[0][1]])
                obj.recompute()
        finally:
            document.commitTransaction()
        FreeCADGui.ActiveDocument.setEdit(obj.Name)
        return obj


def register_commands():
    FreeCADGui.addCommand("HSM_MasterBottomFeature", CommandMasterBottomFeature())
    FreeCADGui.addCommand("HSM_GuideCurveNet", CommandGuideCurveNet())
    FreeCADGui.addCommand("HSM_FeedRateAnalysis", CommandFeedRateAnalysis())
    FreeCADGui.addCommand("HSM_MachiningDirection", CommandMachiningDirection())
    from hsmplanner.gui import finishing_ops_gui

    finishing_ops_gui.register_commands()
