"""GUI test: pick the boundaries of the master feature, move K, see the net change, accept, reopen."""
import os
import sys

import FreeCAD
import FreeCADGui as Gui

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import GuiRun  # noqa: E402

run = GuiRun()
state = {}


def panel():
    from hsmplanner.gui import guide_curve_net_panel

    return guide_curve_net_panel.GuideCurveNetPanel.active


def preview_done():
    """The panel's preview is computed for its current values (it waits 30 ms for the slider to settle,
    then computes)."""
    return panel() is not None and not panel()._timer.isActive()


def curve_count(run):
    run.wait_until(preview_done, 20.0, "the net's preview computed")
    result = panel().last_result
    return len(result.net.curves) if result else 0


def selected():
    """(object name, sub-element) of everything the selection holds."""
    return [(s.ObjectName, sub) for s in Gui.Selection.getSelectionEx() for sub in s.SubElementNames or [""]]


@run.step
def build_part_and_select_its_boundaries(run):
    Gui.activateWorkbench("HSMPlannerWorkbench")
    Gui.runCommand("HSM_MasterBottomFeature")
    run.wait_until(lambda: run.shape_built(FreeCAD.ActiveDocument.getObject("MasterBottomFeature")), 20.0,
                   "the master bottom feature built")
    part = FreeCAD.ActiveDocument.getObject("MasterBottomFeature")
    state["part"] = part
    Gui.Selection.clearSelection()
    for sub in (part.Boundary1, part.Boundary2, part.BottomFace):
        Gui.Selection.addSelection(part, sub)
    Gui.runCommand("HSM_GuideCurveNet")
    run.wait_until(lambda: run.task_dialog_open() and preview_done(), 20.0, "the Guide curve net panel open")
    run.check("panel open", panel() is not None)
    run.check_fits_combo_view("Guide curve net panel", panel().form)
    run.check("boundary 1 taken from the selection", panel().boundary_1.link == (part, [part.Boundary1]),
              str(panel().boundary_1.link))
    run.check("bottom face taken", panel().bottom.link == (part, [part.BottomFace]))
    Gui.activeDocument().activeView().viewTop()
    Gui.SendMsgToActiveView("ViewFit")


@run.step
def moving_k_changes_the_net(run):
    p = panel()
    p.mode.setCurrentText("Boundaries to median")
    p.k_slider.setValue(25)
    many = curve_count(run)
    run.screenshot("curvenet_k025")
    p.k_slider.setValue(75)
    few = curve_count(run)
    run.screenshot("curvenet_k075")
    run.notes["curves at K 0.25 and 0.75"] = [many, few]
    run.check("K 0.25 gives 13 intermediate curves", many == 15, str(many))
    run.check("K 0.75 gives 3", few == 5, str(few))
    run.check("K box follows the slider", abs(p.k_box.value() - 0.75) < 1e-9)


@run.step
def pick_button_uses_a_selection_gate(run):
    p, part = panel(), state["part"]
    p.boundary_1.button.click()
    Gui.Selection.addSelection(part, part.BottomFace)  # returns None whatever the gate says: look at the selection
    run.check("gate rejects a face while picking an edge",
              (part.Name, part.BottomFace) not in selected() and p.boundary_1.link == (part, [part.Boundary1]),
              "selection %s, field %s" % (selected(), p.boundary_1.link))
    Gui.Selection.addSelection(part, part.Boundary2)  # both boundaries the same edge: a clear error
    run.check("the gate lets the edge through", (part.Name, part.Boundary2) in selected(), str(selected()))
    run.wait_until(lambda: p.boundary_1.link == (part, [part.Boundary2]) and preview_done(), 20.0,
                   "the picked edge in the field and the preview computed")
    run.check("picked edge fills the field", p.boundary_1.link == (part, [part.Boundary2]), str(p.boundary_1.link))
    run.check("same edge twice is reported, not crashed", p.last_error is not None and "coincide" in p.last_error,
              str(p.last_error))
    run.notes["error shown for the same edge twice"] = p.info.text()
    p.boundary_1.button.click()
    Gui.Selection.addSelection(part, part.Boundary1)
    run.check("boundary 1 restored", curve_count(run) > 2)


def display_lift(root):
    """The z of the net's display-only lift (0 when there is none)."""
    for i in range(root.getNumChildren()):
        if root.getChild(i).getName() == "HsmLift":
            return root.getChild(i).translation.getValue()[2]
    return 0.0


@run.step
def four_step_and_accept(run):
    p = panel()
    p.four_step.click()
    run.check("4-step preview", curve_count(run) == 5)
    p.accept()
    def net_computed():
        net = FreeCAD.ActiveDocument.getObject("GuideCurveNet")
        return run.shape_built(net) and len(net.Curves) > 0

    run.wait_until(lambda: not run.task_dialog_open() and net_computed(), 20.0, "the panel closed and the net computed")
    net = FreeCAD.ActiveDocument.getObject("GuideCurveNet")
    run.check("net valid", net is not None and net.isValid(), str(net.State if net else None))
    run.check("4 coloured areas", len(net.AreaSurfaces) == 4 and len(net.ViewObject.DiffuseColor) == len(net.FaceAreas),
              "%s %s" % (net.AreaSurfaces, len(net.ViewObject.DiffuseColor)))
    run.notes["accepted net"] = {"curves": net.Curves, "areas_mm2": [round(a, 1) for a in net.AreaSurfaces],
                                 "spacing": net.PlaneSpacing}
    from hsmplanner.gui.view_providers import display_deflection

    lifts = {name: display_lift(obj.ViewObject.RootNode) for name, obj in (("net", net), ("part", state["part"]))}
    deflection = max(display_deflection(net), display_deflection(state["part"]))
    run.notes["display lift and tessellation deflection (mm)"] = [lifts, round(deflection, 3)]
    run.check("the net's areas are drawn over the part's face by more than the tessellations' deflection",
              deflection < lifts["net"] < 3.0 * deflection and lifts["part"] == 0.0, "%s %s" % (lifts, deflection))
    state["part"].ViewObject.Transparency = 60
    Gui.Selection.clearSelection()
    Gui.activeDocument().activeView().viewTop()
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("curvenet_accepted")


@run.step
def reopen_and_cancel_keeps_the_object(run):
    Gui.ActiveDocument.setEdit("GuideCurveNet")
    run.wait_until(lambda: run.task_dialog_open() and panel() is not None, 20.0, "the Guide curve net panel reopened")
    run.check("panel reopened with its values", panel() is not None and panel().mode.currentText() == "4-step method")
    panel().reject()
    run.wait_until(lambda: not run.task_dialog_open() and panel() is None, 20.0, "the panel closed")
    run.check("cancel kept the existing net", FreeCAD.ActiveDocument.getObject("GuideCurveNet") is not None)



@run.step
def a_new_net_cancelled_leaves_neither_object_nor_undo_entry(run):
    document = FreeCAD.ActiveDocument
    before = (document.UndoCount, list(document.UndoNames), sorted(o.Name for o in document.Objects))
    Gui.Selection.clearSelection()
    Gui.runCommand("HSM_GuideCurveNet")
    run.wait_until(lambda: run.task_dialog_open() and panel() is not None, 20.0, "a new net's panel open")
    panel().reject()
    run.wait_until(lambda: not run.task_dialog_open() and panel() is None, 20.0, "the panel closed")
    after = (document.UndoCount, list(document.UndoNames), sorted(o.Name for o in document.Objects))
    run.notes["undo before and after a cancelled new net"] = [before[:2], after[:2]]
    run.check("no object added", after[2] == before[2], str(after[2]))
    run.check("the undo stack as before", after[:2] == before[:2], "%s -> %s" % (before[:2], after[:2]))


run.start()
