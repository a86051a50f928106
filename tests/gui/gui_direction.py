"""GUI test: pick the valleys face, run the Machining direction command, see the arrows and plots, change the
feed in the panel, validate by simulation, and set the angle of a Parallel plane finishing operation."""
import os
import sys

import FreeCAD
import FreeCADGui as Gui

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import GuiRun, scene_nodes  # noqa: E402

run = GuiRun()
state = {}


def panel():
    from hsmplanner.gui import direction_panel

    return direction_panel.DirectionPanel.active


@run.step
def valleys_with_a_job(run):
    from hsmplanner.app import finishing, finishing_ops, surfaces
    from hsmplanner.app.compat import create_job

    Gui.activateWorkbench("HSMPlannerWorkbench")
    document = FreeCAD.newDocument("Direction")
    part = document.addObject("Part::Feature", "Valleys")
    part.Shape = surfaces.valleys()
    document.recompute()
    job = create_job([part])
    finishing.ball_end_controller(job, 10.0, 6000.0)
    state["planes"] = finishing_ops.CreateParallelPlaneFinishing("Planes", parentJob=job)
    state["planes"].Face = (job.Model.Group[0], ["Face1"])
    document.recompute()
    state["part"] = part
    for obj in (job, state["planes"]):
        obj.ViewObject.Visibility = False
    run.wait_until(lambda: run.shape_built(part) and run.valid(state["planes"]) and state["planes"].Passes > 0, 30.0,
                   "the part and the Planes operation computed")


@run.step
def command_on_the_selected_face(run):
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(state["part"], "Face1")
    run.wait_until(lambda: [(s.ObjectName, s.SubElementNames) for s in Gui.Selection.getSelectionEx()]
                   == [(state["part"].Name, ("Face1",))], 10.0, "Face1 of the part selected")
    Gui.runCommand("HSM_MachiningDirection")

    def analysis_shown():
        analysis = FreeCAD.ActiveDocument.getObject("MachiningDirection")
        return (run.valid(analysis) and panel() is not None and run.task_dialog_open()
                and analysis.ViewObject.Proxy.root.getNumChildren() > 0)

    run.wait_until(analysis_shown, 60.0, "the direction analysis computed, its arrows drawn and its panel open")
    analysis = FreeCAD.ActiveDocument.getObject("MachiningDirection")
    state["analysis"] = analysis
    run.check("analysis valid", analysis is not None and analysis.isValid(), str(analysis.State if analysis else ""))
    run.check("panel open", panel() is not None)
    run.check_fits_combo_view("Machining direction panel", panel().form)
    run.check("arrows drawn", analysis.ViewObject.Proxy.root.getNumChildren() > 0)
    run.check("face taken from the selection", analysis.Face[1] == ("Face1",) or analysis.Face[1] == ["Face1"],
              str(analysis.Face))
    run.check("summary shows the beams", "Directional beams" in panel().summary.text(), panel().summary.text())
    import numpy as np
    from hsmplanner.plots.common import feed_colors
    from hsmplanner.gui import direction_view

    result = analysis.Proxy.result
    values = np.asarray(result.fitness_max)
    low, high = direction_view.fitness_scale(values)
    colours = feed_colors((values - low) / (high - low))
    run.notes["G_pmax range (mm2)"] = [round(float(values.min()), 5), round(float(values.max()), 5)]
    run.check("the strokes' colours span the scale (not one green)",
              float(np.ptp(colours, axis=0).max()) > 0.3, str(np.ptp(colours, axis=0)))
    texts = [text.string.getValues()[0] for text in scene_nodes(analysis.ViewObject.Proxy.root, "SoText2")]
    ticks = [t for t in texts if t.endswith("mm²")]
    run.notes["legend ticks"] = ticks
    run.check("the legend's five ticks read five different numbers", len(ticks) == 5 and len(set(ticks)) == 5,
              str(ticks))
    arrow = direction_view.chosen_arrow(result.points, analysis.ChosenAngle.Value)
    run.check("the chosen direction is a double arrow", len(arrow) == 5, str(len(arrow)))
    run.notes["beams deg, alpha"] = [analysis.OptimalAngle.Value, round(analysis.BeamAlpha, 3)]
    state["part"].ViewObject.Transparency = 40
    Gui.Selection.clearSelection()
    Gui.activeDocument().activeView().viewTop()
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("direction_beams_top")
    run.panel_plots("direction_panel_beams", panel().figure)
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("direction_beams_iso")


@run.step
def feed_scan_in_the_panel(run):
    p = panel()
    p.numbers["ScanFrom"].setValue(2000.0)
    p.numbers["ScanTo"].setValue(12000.0)
    p.numbers["ScanSteps"].setValue(6)
    run.check("computed with a scan", p.compute(), p.message.text())
    analysis = state["analysis"]
    run.wait_until(lambda: run.valid(analysis) and len(analysis.ScanFeeds) == 6, 60.0,
                   "the analysis recomputed with its feed scan")
    run.check("scan of 6 feeds", len(analysis.ScanFeeds) == 6, str(list(analysis.ScanFeeds)))
    run.notes["scan optimum deg"] = list(analysis.ScanOptimalAngles)
    run.screenshot("direction_feed_scan")
    run.panel_plots("direction_panel_scan", panel().figure)


@run.step
def bad_input_is_shown_not_raised(run):
    p = panel()
    p.numbers["ScanFrom"].setValue(9000.0)
    p.numbers["ScanTo"].setValue(3000.0)
    run.check("refused", not p.compute())
    run.check("message names the input", "ScanFrom" in p.message.text(), p.message.text())
    p.numbers["ScanFrom"].setValue(0.0)
    p.numbers["ScanTo"].setValue(0.0)


@run.step
def fastest_simulated_applied_to_the_operation(run):
    p = panel()
    p.numbers["ValidationStep"].setValue(45.0)
    p.choice.setCurrentText("Fastest simulated")
    run.check("validated", p.compute(), p.message.text())
    analysis = state["analysis"]
    run.check("five angles simulated", list(analysis.ValidationAngles) == [0.0, 45.0, 90.0, 135.0, 180.0],
              str(list(analysis.ValidationAngles)))
    run.check("operation listed", p.operations.count() == 1 and p.apply_button.isEnabled())
    angle = p.apply()
    planes = state["planes"]
    run.wait_until(lambda: run.valid(planes) and abs(planes.Angle.Value - analysis.ChosenAngle.Value) < 1e-9,
                   60.0, "the Planes operation recomputed at the chosen angle")
    run.check("angle applied", angle is not None and abs(planes.Angle.Value - analysis.ChosenAngle.Value) < 1e-9,
              "%s %s" % (planes.Angle, analysis.ChosenAngle))
    run.check("operation recomputed", planes.isValid() and planes.Passes > 100, str(planes.State))
    window = p.plots.open_window()
    run.check("the plots open in a window", window.isVisible())
    run.widget_screenshot("direction_plots_window", window)
    run.notes["fastest simulated deg, times s"] = [analysis.ChosenAngle.Value,
                                                   [round(t, 1) for t in analysis.ValidationTimes]]
    run.screenshot("direction_validation_applied")
    run.panel_plots("direction_panel_validation", panel().figure)
    p.reject()
    run.wait_until(lambda: panel() is None and not run.task_dialog_open(), 10.0, "the direction panel closed")


run.start()
