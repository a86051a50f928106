"""GUI test: FreeCAD lists and activates the HSM Planner workbench, its command builds the test part."""
import os
import sys

import FreeCAD
import FreeCADGui as Gui
from PySide import QtWidgets

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import GuiRun  # noqa: E402

run = GuiRun()


@run.step
def workbench_is_listed(run):
    run.check("workbench listed", "HSMPlannerWorkbench" in Gui.listWorkbenches(), str(list(Gui.listWorkbenches())))


@run.step
def workbench_activates(run):
    Gui.activateWorkbench("HSMPlannerWorkbench")

    def visible_toolbars():
        return [t.windowTitle() for t in Gui.getMainWindow().findChildren(QtWidgets.QToolBar) if t.isVisible()]

    run.wait_until(lambda: type(Gui.activeWorkbench()).__name__ == "HSMPlannerWorkbench"
                   and "HSM Planner" in visible_toolbars(), 20.0, "the workbench active with its toolbar shown")
    active = Gui.activeWorkbench()
    run.check("workbench active", type(active).__name__ == "HSMPlannerWorkbench", type(active).__name__)
    toolbars = visible_toolbars()
    run.check("toolbar shown", "HSM Planner" in toolbars, str(toolbars))
    run.notes["toolbars"] = toolbars


@run.step
def command_builds_master_feature(run):
    Gui.runCommand("HSM_MasterBottomFeature")
    run.wait_until(lambda: run.shape_built(FreeCAD.ActiveDocument.getObject("MasterBottomFeature")), 20.0,
                   "the master bottom feature built")
    document = FreeCAD.ActiveDocument
    obj = document.getObject("MasterBottomFeature") if document else None
    run.check("object created", obj is not None)
    if obj is None:
        return
    run.check("object valid", obj.isValid(), str(obj.State))
    run.notes["bottom_face"], run.notes["boundaries"] = obj.BottomFace, [obj.Boundary1, obj.Boundary2]
    Gui.Selection.addSelection(obj, [obj.Boundary1, obj.Boundary2])
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("workbench_master_feature")
    view_image = os.path.join(os.environ.get("HSM_GUI_TEST_OUT", "."), "view3d_master_feature.png")
    Gui.ActiveDocument.ActiveView.saveImage(view_image, 1000, 750, "White")
    run.screenshots.append(view_image)


@run.step
def undo_removes_it(run):
    document = FreeCAD.ActiveDocument
    document.undo()
    run.wait_until(lambda: document.getObject("MasterBottomFeature") is None, 10.0, "the feature removed by undo")
    run.check("undo removed the feature", document.getObject("MasterBottomFeature") is None)


run.start()
