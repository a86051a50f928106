"""GUI test: a Job on the master feature, the Feed-rate analysis command, its map, panel and report export."""
import os
import sys

import FreeCAD
import numpy as np
import FreeCADGui as Gui

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import OUT, GuiRun, scene_nodes  # noqa: E402

run = GuiRun()
state = {}


def panel():
    from hsmplanner.gui import feedrate_panel

    return feedrate_panel.FeedRatePanel.active


def scene_texts(node):
    """Every string of the SoText2 labels under a Coin node (the map's legend)."""
    return [text.string.getValues()[0] for text in scene_nodes(node, "SoText2")]


def analysis_open(source=None, name="FeedRateAnalysis"):
    """The analysis (of `source`, or the one named `name`) is computed and its panel is open."""
    document = FreeCAD.ActiveDocument
    analysis = ([o for o in document.Objects if getattr(o, "Source", None) is source] or [None])[0] \
        if source is not None else document.getObject(name)
    return run.valid(analysis) and panel() is not None and run.task_dialog_open()


@run.step
def job_with_a_toolpath(run):
    from hsmplanner.app import probe_paths

    Gui.activateWorkbench("HSMPlannerWorkbench")
    Gui.runCommand("HSM_MasterBottomFeature")
    run.wait_until(lambda: run.shape_built(FreeCAD.ActiveDocument.getObject("MasterBottomFeature")), 20.0,
                   "the master bottom feature built")
    part = FreeCAD.ActiveDocument.getObject("MasterBottomFeature")
    state["job"], state["op"] = probe_paths.make_probe_job(part, 4000.0)
    part.ViewObject.Transparency = 70
    run.wait_until(lambda: run.valid(state["op"]) and len(state["op"].Path.Commands) > 0, 30.0,
                   "the probe operation's path computed")


@run.step
def command_needs_a_job_selected(run):
    Gui.Selection.clearSelection()
    run.check("inactive without a Job", not Gui.Command.get("HSM_FeedRateAnalysis").isActive())
    Gui.Selection.addSelection(state["job"])
    run.wait_until(lambda: Gui.Command.get("HSM_FeedRateAnalysis").isActive(), 10.0,
                   "the Feed-rate analysis command active with the Job selected")
    run.check("active with a Job", Gui.Command.get("HSM_FeedRateAnalysis").isActive())


@run.step
def analysis_draws_the_map_and_fills_the_panel(run):
    Gui.runCommand("HSM_FeedRateAnalysis")
    run.wait_until(lambda: analysis_open() and panel().table.rowCount() > 0
                   and FreeCAD.ActiveDocument.getObject("FeedRateAnalysis").ViewObject.Proxy.root.getNumChildren() > 0,
                   60.0, "the feed-rate analysis computed, its map drawn and its panel filled")
    analysis = FreeCAD.ActiveDocument.getObject("FeedRateAnalysis")
    run.check("analysis valid", analysis is not None and analysis.isValid(), str(analysis.State if analysis else ""))
    run.check("panel open", panel() is not None)
    run.check("map drawn", analysis.ViewObject.Proxy.root.getNumChildren() > 0)
    from pivy import coin

    first = analysis.ViewObject.Proxy.root.getChild(0).getChild(0)
    run.check("the map is an overlay the part cannot hide",
              first.isOfType(coin.SoDepthBuffer.getClassTypeId()) and not first.test.getValue(), str(first))
    run.check("summary table filled", panel().table.rowCount() >= 8, str(panel().table.rowCount()))
    run.check_fits_combo_view("Feed-rate analysis panel", panel().form)
    table = panel().table
    shown = table.viewport().height()
    rows = sum(table.rowHeight(i) for i in range(table.rowCount()))
    run.check("every summary row is shown without scrolling", shown >= rows, "%d px shown of %d" % (shown, rows))
    from PySide import QtCore

    metrics, cut = table.fontMetrics(), []
    for r in range(table.rowCount()):
        for c in range(2):
            text, width = table.item(r, c).text(), table.columnWidth(c) - 6  # the cell's margins
            need = metrics.boundingRect(QtCore.QRect(0, 0, width, 10000), QtCore.Qt.TextWordWrap, text)
            if need.width() > width or need.height() > table.rowHeight(r):
                cut.append(text)
    run.check("no label or value of the table is cut short", not cut, str(cut))
    run.panel_plots("feedrate_panel_histograms", panel().figure)
    window = panel().plots.open_window()
    run.check("the plots open in a window", window.isVisible())
    run.widget_screenshot("feedrate_plots_window", window)
    window.close()
    run.notes["simulated s, naive s"] = [round(analysis.TotalTime, 2), round(analysis.NaiveTime, 2)]
    for name in ("Job", "ProbeRaster"):
        FreeCAD.ActiveDocument.getObject(name).ViewObject.Visibility = False  # the map in its own colours
    Gui.Selection.clearSelection()
    Gui.activeDocument().activeView().viewTop()
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("feedrate_map_panel")
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    image = os.path.join(OUT, "feedrate_map_view3d.png")
    Gui.ActiveDocument.ActiveView.saveImage(image, 1200, 800, "Current")
    run.screenshots.append(image)


@run.step
def other_machine_colours_and_export(run):
    p = panel()
    before = FreeCAD.ActiveDocument.getObject("FeedRateAnalysis").TotalTime
    p.machine.setCurrentText("grbl")
    p.simulate_button.click()
    analysis = FreeCAD.ActiveDocument.getObject("FeedRateAnalysis")
    run.wait_until(lambda: run.valid(analysis) and analysis.Machine == "grbl" and analysis.TotalTime != before,
                   60.0, "the analysis simulated again on grbl")
    after = analysis.TotalTime
    run.check("another machine, another time", abs(after - before) > 1.0, "%s %s" % (before, after))
    p.color_by.setCurrentText("Feed (mm/min)")
    run.wait_until(lambda: any("mm/min" in text for text in scene_texts(analysis.ViewObject.Proxy.root)), 20.0,
                   "the map redrawn with its mm/min legend")
    from hsmplanner.gui import feedmap

    blocks = FreeCAD.ActiveDocument.getObject("FeedRateAnalysis").Proxy.result.blocks
    colors, (low, high, unit) = feedmap.block_colors(blocks, "Feed (mm/min)")
    run.notes["mm/min scale"] = [low, high, unit]
    run.check("the mm/min scale tops at the programmed feed, not the rapid speed", abs(high - 4000.0) < 1.0, str(high))
    cutting = blocks["motion"] != 0
    at_feed = cutting & (blocks["mean_feed"] > 0.95 * blocks["programmed_feed"])
    greens = colors[at_feed]
    run.check("cuts at the programmed feed are drawn green", len(greens) > 0 and bool(np.all(greens[:, 1] > greens[:, 0])),
              str(greens[:3]))
    run.screenshot("feedrate_map_grbl_mm_min")
    folder = os.path.join(OUT, "report")
    paths = p.export(folder)
    run.check("report written", len(paths) == 4 and all(os.path.getsize(x) > 0 for x in paths), str(paths))
    p.reject()
    run.wait_until(lambda: panel() is None and not run.task_dialog_open(), 10.0, "the feed-rate panel closed")


@run.step
def a_second_run_opens_the_same_analysis(run):
    """The command on a source that has its analysis opens that one (its machine kept), not another object."""
    count = len([o for o in FreeCAD.ActiveDocument.Objects if hasattr(o, "Source")])
    source = FreeCAD.ActiveDocument.getObject("FeedRateAnalysis").Source
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(source)
    Gui.runCommand("HSM_FeedRateAnalysis")
    run.wait_until(lambda: panel() is not None, 20.0, "the analysis's panel open again")
    run.check("no second analysis object", len([o for o in FreeCAD.ActiveDocument.Objects if hasattr(o, "Source")])
              == count, str([o.Name for o in FreeCAD.ActiveDocument.Objects]))
    run.check("the panel is the first analysis's, on its machine", panel().obj.Name == "FeedRateAnalysis"
              and panel().machine.currentText() == "grbl", panel().obj.Name)
    panel().reject()
    run.wait_until(lambda: panel() is None and not run.task_dialog_open(), 10.0, "the feed-rate panel closed")


@run.step
def an_operation_at_f0_gives_one_clear_message_in_the_panel(run):
    """FreeCAD's default tool controller has feeds of 0: the analysis of such a path says so, once, in its
    panel, instead of tracebacks and an empty panel."""
    from hsmplanner.app.compat import cam_module

    custom = cam_module("custom_op").Create("AtF0", parentJob=state["job"])
    custom.Gcode = ["G0 X0 Y0 Z5", "G1 Z-1 F0", "G1 X10"]
    FreeCAD.ActiveDocument.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(custom)
    Gui.runCommand("HSM_FeedRateAnalysis")
    run.wait_until(lambda: analysis_open(custom) and panel().message.text(), 60.0,
                   "the analysis of AtF0 computed and its panel open with a message")
    analysis = [o for o in FreeCAD.ActiveDocument.Objects if getattr(o, "Source", None) is custom][0]
    message = panel().message.text() if panel() is not None else ""
    run.notes["F0 message"] = message
    run.check("the analysis stays valid with an empty result (as FreeCAD's CAM operations do)",
              analysis.isValid() and analysis.TotalTime == 0.0, str(analysis.State))
    run.check("the panel names the operation and F0", "AtF0 cuts at F0" in message, message)
    report = run.report_view_text()
    # once from this analysis (the Job's own analysis, which now holds AtF0 too, says it for the Job)
    run.check("the Report view has the message on one line, once", report.count(
        "%s: AtF0 cuts at F0" % analysis.Label) == 1, report[-600:])
    run.check("and no traceback", "Traceback" not in report, report[-600:])
    run.check("the panel's table stays empty", panel().table.rowCount() == 0)
    run.screenshot("feedrate_panel_f0")
    panel().reject()
    run.wait_until(lambda: panel() is None and not run.task_dialog_open(), 10.0, "the feed-rate panel closed")


run.start()
