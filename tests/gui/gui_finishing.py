"""GUI test: the two finishing operations created from their commands and panels in a Job, then their
feed-rate maps (the paper's Fig. 2b and Fig. 6 on our master feature)."""
import os
import sys

import FreeCAD
import FreeCADGui as Gui

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import OUT, GuiRun, show_only  # noqa: E402

run = GuiRun()
state = {}


def operation_panel(obj):
    return obj.ViewObject.Proxy.panel


def panel_open(name):
    """The operation `name` exists and its panel is shown in the task view."""
    op = FreeCAD.ActiveDocument.getObject(name)
    return op is not None and operation_panel(op) is not None and run.task_dialog_open()


def accepted(op):
    """The operation's panel is closed and the operation recomputed with a path."""
    return not run.task_dialog_open() and run.valid(op) and len(op.Path.Commands) > 0



@run.step
def part_net_and_job(run):
    from hsmplanner.app import finishing, guide_curve_net_object, master_feature_object
    from hsmplanner.app.compat import create_job

    Gui.activateWorkbench("HSMPlannerWorkbench")
    document = FreeCAD.newDocument("Finishing")
    part = master_feature_object.create(document)
    state["part"] = part
    state["net"] = guide_curve_net_object.create(document, (part, part.Boundary1), (part, part.Boundary2),
                                                 (part, part.BottomFace))
    job = create_job([part])  # as a new user has it: FreeCAD's Ø5 flat end mill with feeds of 0
    state["default tool"] = list(job.Tools.Group)
    run.check("the new Job's tool cannot finish", not any(finishing.is_usable(c) for c in job.Tools.Group))
    document.recompute()
    run.wait_until(lambda: run.valid(state["net"]) and len(state["net"].Curves) > 0
                   and Gui.Command.get("HSM_GuideCurveFinishing").isActive(), 30.0,
                   "the net computed and the Guide curve finishing command active")
    run.check("command active with a Job", Gui.Command.get("HSM_GuideCurveFinishing").isActive())


@run.step
def guide_curve_finishing_from_its_panel(run):
    Gui.runCommand("HSM_GuideCurveFinishing")
    run.wait_until(lambda: panel_open("GuideCurveFinishing"), 30.0, "the Guide curve finishing panel open")
    op = FreeCAD.ActiveDocument.getObject("GuideCurveFinishing")
    panel = operation_panel(op)
    run.check("operation panel open", panel is not None)
    page = panel.featurePages[-1]
    page.form.net.setCurrentText(state["net"].Label)
    page.form.areas.setCurrentText("Elementary areas of the net")
    panel.accept()
    run.wait_until(lambda: accepted(op), 60.0, "the panel closed and the guide curve finishing computed")
    run.check("guide curve path", op.isValid() and len(op.Path.Commands) > 5000 and op.Passes > 100,
              "%s %d %d" % (op.State, len(op.Path.Commands), op.Passes))
    controller = op.ToolController
    run.check("the operation took a Ø4 ball end at F4000 added to the Job",
              controller not in state["default tool"] and controller.Tool.Diameter.Value == 4.0
              and abs(controller.HorizFeed.getValueAs("mm/min").Value - 4000.0) < 1e-6, controller.Label)
    run.notes["guide curve finishing"] = {"passes": op.Passes, "commands": len(op.Path.Commands),
                                          "tool controller": controller.Label}
    state["guide"] = op


@run.step
def parallel_plane_finishing_from_its_panel(run):
    part = state["part"]
    Gui.Selection.clearSelection()
    Gui.runCommand("HSM_ParallelPlaneFinishing")
    run.wait_until(lambda: panel_open("ParallelPlaneFinishing"), 30.0, "the Parallel plane finishing panel open")
    op = FreeCAD.ActiveDocument.getObject("ParallelPlaneFinishing")
    panel = operation_panel(op)
    page = panel.featurePages[-1]
    Gui.Selection.addSelection(part, part.BottomFace)
    page.form.useSelection.click()
    run.check("face taken from the selection", page.form.face.text().endswith(part.BottomFace), page.form.face.text())
    panel.accept()
    run.wait_until(lambda: accepted(op), 60.0, "the panel closed and the parallel plane finishing computed")
    run.check("parallel plane path", op.isValid() and op.Passes > 100, "%s %d" % (op.State, op.Passes))
    run.notes["parallel plane finishing"] = {"passes": op.Passes, "commands": len(op.Path.Commands)}
    state["planes"] = op


@run.step
def a_face_picked_before_the_command_is_taken(run):
    """The user picks the bottom face, then Parallel plane finishing: the panel shows the face, OK computes."""
    part = state["part"]
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part, part.BottomFace)
    Gui.runCommand("HSM_ParallelPlaneFinishing")
    run.wait_until(lambda: panel_open("ParallelPlaneFinishing001"), 30.0, "a second Parallel plane finishing panel")
    op = FreeCAD.ActiveDocument.getObject("ParallelPlaneFinishing001")
    panel = operation_panel(op)
    page = panel.featurePages[-1]
    run.check("the preselected face in the panel", page.form.face.text().endswith(part.BottomFace),
              page.form.face.text())
    panel.accept()
    run.wait_until(lambda: accepted(op), 60.0, "the panel closed and the operation computed")
    run.check("OK computes the operation on that face", op.isValid() and op.Passes > 100, "%s %s" % (op.State,
                                                                                               op.Passes))
    FreeCAD.ActiveDocument.removeObject(op.Name)
    FreeCAD.ActiveDocument.recompute()


@run.step
def saved_documents_hold_no_absolute_icon_path(run):
    import tempfile
    import zipfile

    path = os.path.join(tempfile.mkdtemp(prefix="hsm-gui-"), "ops.FCStd")
    FreeCAD.ActiveDocument.saveCopy(path)
    with zipfile.ZipFile(path) as archive:
        gui = archive.read("GuiDocument.xml").decode("utf-8", "replace")
    run.check("no absolute path in the saved view providers", ".svg" not in gui and os.path.expanduser("~") not in gui,
              [line.strip()[:160] for line in gui.splitlines() if ".svg" in line][:3])
    icon = state["guide"].ViewObject.Proxy.getIcon()
    run.check("the icon resolves on this machine", os.path.isfile(icon), icon)


@run.step
def escape_cancels_a_long_finishing_and_keeps_the_document(run):
    """A cusp of 0.001 mm takes seconds: its progress dialog shows, Esc stops it, the operation is marked
    cancelled, the document and its objects stay, and the next recompute works again."""
    from PySide import QtCore

    op = state["planes"]
    seen = {}

    op.CuspHeight = 0.001
    QtCore.QTimer.singleShot(1500, lambda: run.press_escape_on_progress(seen, "finishing_progress_dialog"))
    FreeCAD.ActiveDocument.recompute()
    run.wait_until(lambda: "dialogs" in seen, 10.0, "the timer that presses Esc")
    run.notes["escape"] = {"status": op.getStatusString(), "dialogs": seen.get("dialogs")}
    run.check("a progress dialog shows", bool(seen.get("dialogs")), str(seen))
    run.check("Esc cancels the finishing", "cancelled" in op.getStatusString(), op.getStatusString())
    run.check("the document is kept", FreeCAD.ActiveDocument is not None and op.Document is FreeCAD.ActiveDocument)
    op.CuspHeight = 0.01
    FreeCAD.ActiveDocument.recompute()
    run.wait_until(lambda: run.valid(op) and op.Passes > 100, 60.0, "the operation recomputed at 0.01 mm")
    run.check("the next recompute works", op.isValid() and op.Passes > 100, "%s %d" % (op.State, op.Passes))


@run.step
def feed_rate_maps_of_both(run):
    for key, name in (("planes", "planes"), ("guide", "guide")):
        op = state[key]
        Gui.Selection.clearSelection()
        Gui.Selection.addSelection(op)
        Gui.runCommand("HSM_FeedRateAnalysis")
        from hsmplanner.gui import feedrate_panel

        def analysed():
            found = [o for o in FreeCAD.ActiveDocument.Objects if getattr(o, "Source", None) is op]
            return found and run.valid(found[0]) and feedrate_panel.FeedRatePanel.active is not None

        run.wait_until(analysed, 60.0, "the feed-rate analysis of %s computed and its panel open" % name)
        analysis = [o for o in FreeCAD.ActiveDocument.Objects if getattr(o, "Source", None) is op][0]
        run.check("%s analysed" % name, analysis.isValid() and analysis.TotalTime > 0, str(analysis.State))
        run.notes["%s simulated s / length-feed s" % name] = [round(analysis.TotalTime, 1), round(analysis.NaiveTime, 1)]
        feedrate_panel.FeedRatePanel.active.reject()
        run.wait_until(lambda: feedrate_panel.FeedRatePanel.active is None and not run.task_dialog_open(), 10.0,
                       "the feed-rate panel closed")
        show_only(state["part"], analysis)
        state["part"].ViewObject.Transparency = 75
        Gui.Selection.clearSelection()
        Gui.activeDocument().activeView().viewTop()
        Gui.SendMsgToActiveView("ViewFit")
        image = os.path.join(OUT, "finishing_%s_feed_map.png" % name)
        Gui.ActiveDocument.ActiveView.saveImage(image, 1400, 800, "Current")
        run.screenshots.append(image)


run.start()
