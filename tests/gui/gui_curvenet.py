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


def curve_count(run):
    run.process_events(0.4)  # the preview waits 30 ms for the slider to settle, then computes
    result = panel().last_result
    return len(result.net.curves) if result else 0


@run.step
def build_part_and_select_its_boundaries(run):
    Gui.activateWorkbench("HSMPlannerWorkbench")
    Gui.runCommand("HSM_MasterBottomFeature")
    run.process_events(0.5)
    part = FreeCAD.ActiveDocument.getObject("MasterBottomFeature")
    state["part"] = part
    Gui.Selection.clearSelection()
    for sub in (part.Boundary1, part.Boundary2, part.BottomFace):
        Gui.Selection.addSelection(part, sub)
    Gui.runCommand("HSM_GuideCurveNet")
    run.process_events(0.8)
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
    run.check("gate rejects a face while picking an edge",
              not Gui.Selection.addSelection(part, part.BottomFace) or p.boundary_1.link[1] == [part.Boundary1])
    Gui.Selection.addSelection(part, part.Boundary2)  # both boundaries the same edge: a clear error
    run.process_events(0.4)
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
    run.process_events(0.8)
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
    run.process_events(0.6)
    run.check("panel reopened with its values", panel() is not None and panel().mode.currentText() == "4-step method")
    panel().reject()
    run.process_events(0.4)
    run.check("cancel kept the existing net", FreeCAD.ActiveDocument.getObject("GuideCurveNet") is not None)


run.start()
