"""FreeCAD commands of the HSM Planner workbench."""
import FreeCAD
import FreeCADGui

from hsmplanner.resources import icon

COMMAND_NAMES = ["HSM_MasterBottomFeature"]


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


def register_commands():
    FreeCADGui.addCommand("HSM_MasterBottomFeature", CommandMasterBottomFeature())
