"""FreeCAD commands of the HSM Planner workbench."""
import FreeCAD
import FreeCADGui

from hsmplanner.resources import icon

COMMAND_NAMES = ["HSM_MasterBottomFeature", "HSM_GuideCurveNet"]


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


def register_commands():
    FreeCADGui.addCommand("HSM_MasterBottomFeature", CommandMasterBottomFeature())
    FreeCADGui.addCommand("HSM_GuideCurveNet", CommandGuideCurveNet())
