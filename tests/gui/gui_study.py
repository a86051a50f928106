"""GUI test: the Strategy study command on the master bottom feature in a Job — the panel says what to select,
takes the selected face and boundaries, says a bad range in the panel (nothing raised), Esc in the progress
dialog keeps the finished rows, a small grid (planes 0° and 90°, a guide net K0.5 P20 with the median, F4000,
a Ø10 ball at 0.1 mm cusp) on two worker processes fills the table and the ranking with its Pareto front, the
selected rows' feed maps are drawn side by side and in the 3D view, and Apply adds operations to the Job that
compute."""
import os
import sys
import time

import FreeCAD
import FreeCADGui as Gui

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import OUT, GuiRun  # noqa: E402

run = GuiRun()
state = {}
GRID = dict(planes="0,90", k="0.5", p="20", median="with the median", feeds="4000")


def panel():
    from hsmplanner.gui import strategy_study_panel

    return strategy_study_panel.StrategyStudyPanel.active


def fill(p, planes="", k="", p_values="", median="with the median", feeds="4000", workers=2):
    f = p.form
    f.planes.setText(planes)
    f.k.setText(k)
    f.p.setText(p_values)
    f.median.setCurrentText(median)
    f.four_step.setChecked(False)
    f.feeds.setText(feeds)
    f.tool.setValue(10.0)  # coarse finishing: the study's logic, in seconds
    f.cusp.setValue(0.1)
    f.workers.setValue(workers)


def table_rows(p):
    """{variant name: (time s, error)} as the table shows them."""
    table = p.form.table
    return {table.item(r, 0).text(): (table.item(r, 1).data(0), table.item(r, 8).text())
            for r in range(table.rowCount())}


def scroll_to(widget):
    """The task view scrolls: bring `widget` into the screenshot."""
    from PySide import QtWidgets

    parent = widget.parent()
    while parent is not None and not isinstance(parent, QtWidgets.QScrollArea):
        parent = parent.parent()
    if parent is not None:
        parent.ensureWidgetVisible(widget, 0, 0)


@run.step
def part_and_job(run):
    from hsmplanner.app.compat import create_job

    Gui.activateWorkbench("HSMPlannerWorkbench")
    document = FreeCAD.newDocument("StrategyStudy")
    run.check("no part: the command is inactive", not Gui.Command.get("HSM_StrategyStudy").isActive())
    Gui.runCommand("HSM_MasterBottomFeature")  # as a user adds it: with its view provider (drawn in the 3D view)
    part = next(o for o in document.Objects if o.Name.startswith("MasterBottomFeature"))
    state["part"] = part
    state["job"] = create_job([part])
    document.recompute()
    run.wait_until(lambda: run.shape_built(part) and Gui.Command.get("HSM_StrategyStudy").isActive(), 30.0,
                   "the part built and the Strategy study command active")
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")


@run.step
def the_panel_says_what_to_select_then_takes_the_selection(run):
    part = state["part"]
    Gui.Selection.clearSelection()
    Gui.runCommand("HSM_StrategyStudy")
    run.wait_until(lambda: run.task_dialog_open() and panel() is not None, 20.0, "the Strategy study panel")
    p = panel()
    run.check("nothing selected: the panel says what to select", "Select the bottom face" in p.form.inputs.text(),
              p.form.inputs.text())
    run.check("Run without inputs says so, raises nothing", p.run() is None and "Select" in p.form.message.text())
    run.check_fits_combo_view("strategy study panel", p.form)
    for name in (part.BottomFace, part.Boundary1, part.Boundary2):
        Gui.Selection.addSelection(part, name)
    p.form.use_selection.click()
    run.check("the selected face and boundaries are the inputs", "Face4 between Edge13 and Edge14"
              in p.form.inputs.text(), p.form.inputs.text())
    run.notes["inputs"] = p.form.inputs.text()


@run.step
def bad_ranges_are_said_in_the_panel(run):
    p = panel()
    for fields, words in ((dict(planes="0", k="1.5", p_values="20"), "K = 1.5 is outside ]0, 1["),
                          (dict(planes="0:180:0.00001"), "Plane angles: 18000000 values (more than 10000)"),
                          (dict(planes="0", feeds="fast"), "Feeds: 'fast' is not a number")):
        fill(p, **fields)
        result = p.run()
        run.check("%s: refused in the panel" % words, result is None and words in p.form.message.text()
                  and p.form.message.isVisible(), p.form.message.text())
    tool, cusp = p.form.tool.value(), p.form.cusp.value()
    fill(p, planes="0")
    p.form.tool.setValue(1.0)
    p.form.cusp.setValue(2.0)  # at or above the ball's radius: said once before any variant runs
    result = p.run()
    run.check("a cusp above the ball's radius is refused in the panel", result is None and
              "below the tool radius" in p.form.message.text(), p.form.message.text())
    p.form.tool.setValue(tool)
    p.form.cusp.setValue(cusp)
    run.check("nothing ran", p.form.table.rowCount() == 0)
    fill(p, planes="0", k="1.5", p_values="20")
    p.run()
    run.notes["bad range message"] = p.form.message.text()
    run.notes["visible objects"] = [o.Label for o in FreeCAD.ActiveDocument.Objects
                                    if o.ViewObject is not None and o.ViewObject.Visibility]
    Gui.SendMsgToActiveView("ViewFit")
    scroll_to(p.form.message)
    run.screenshot("strategy_study_bad_range")


@run.step
def escape_keeps_the_finished_rows(run):
    """Four plane angles in this process: Esc in the progress dialog after the first stops the study; the
    finished row stays in the table, the others say cancelled."""
    from PySide import QtCore

    p = panel()
    fill(p, planes="0,45,90,135", workers=1)
    seen = {}
    timer = QtCore.QTimer()
    timer.setInterval(100)  # until the dialog shows: it shows once the first variant is done
    timer.timeout.connect(lambda: seen.get("cancelled")
                          or run.press_escape_on_progress(seen, "strategy_study_progress"))
    timer.start()
    started = time.time()
    rows = p.run()
    timer.stop()
    run.notes["cancel"] = {"seconds": round(time.time() - started, 1), "dialogs": seen.get("dialogs"),
                           "errors": [r.get("error") for r in rows or []], "status": p.form.status.text()}
    errors = [r.get("error") for r in rows or []]
    run.check("Esc cancelled the study", seen.get("cancelled") is True, str(seen))
    run.check("finished rows kept, the rest cancelled", rows is not None and "" in errors and "cancelled" in errors,
              str(errors))
    shown = table_rows(p)
    run.check("the table shows the finished and the cancelled rows", len(shown) == 4
              and sum(error == "cancelled" for _, error in shown.values()) == errors.count("cancelled"), str(shown))
    run.check("the status says so", "cancelled (Run again" in p.form.status.text(), p.form.status.text())


@run.step
def a_small_grid_on_two_workers(run):
    from hsmplanner import study

    p = panel()
    fill(p, planes=GRID["planes"], k=GRID["k"], p_values=GRID["p"], median=GRID["median"], feeds=GRID["feeds"])
    started = time.time()
    rows = p.run()
    seconds = time.time() - started
    shown = table_rows(p)
    run.notes["study"] = {"seconds": round(seconds, 1), "rows": {k: v[0] for k, v in shown.items()},
                          "status": p.form.status.text(), "cached": [r.get("cached") for r in rows or []]}
    run.check("three rows that ran", rows is not None and len(shown) == 3
              and all(not error and t > 0 for t, error in shown.values()), str(shown))
    run.check("planes 0° read back from the cache of the cancelled run", any(r.get("cached") for r in rows or []))
    names = sorted(shown)
    run.check("the variants of the grid: planes 0° and 90°, a guide net K0.5 P20, at F4000",
              [n.split(" ")[0] for n in names] == ["guide", "planes", "planes"] and "K0.5 P20" in names[0]
              and names[1].startswith("planes 0°") and names[2].startswith("planes 90°")
              and all(n.endswith("F4000") for n in names), str(names))
    front = [r["name"] for r in study.rank(rows, "pareto")]
    figure = p.ranking.figure
    run.check("the ranking is drawn with its Pareto front", p.ranking.window_button.isEnabled()
              and len(figure.axes) == 1
              and any(line.get_label() == "Pareto front" for line in figure.axes[0].get_lines()), str(front))
    run.notes["pareto front"] = front
    run.panel_plots("strategy_study_ranking_panel", figure)
    table = p.form.table
    times = [table.item(r, 1).data(0) for r in range(table.rowCount())]
    run.check("the table opens with the fastest variant first, times sorted as numbers",
              table.horizontalHeader().sortIndicatorSection() == 1 and all(isinstance(t, float) for t in times)
              and times == sorted(times), str(times))
    table.sortItems(1)  # by time: sorting keeps each row's variant
    run.check("sorting by time keeps the rows", sorted(table_rows(p)) == names)
    tips = [table.item(r, 0).toolTip() for r in range(table.rowCount())]
    run.check("each row's tip says where the machine loses most time",
              all("loses most time (below F/2)" in tip and " at X" in tip for tip in tips), tips)
    state["names"] = names
    scroll_to(p.form.table)
    run.screenshot("strategy_study_table")


@run.step
def selected_rows_feed_maps(run):
    from PySide import QtCore

    p = panel()
    table = p.form.table
    table.clearSelection()
    by_name = {table.item(r, 0).text(): r for r in range(table.rowCount())}
    guide = next(n for n in by_name if n.startswith("guide"))
    planes = next(n for n in by_name if n.startswith("planes 90"))
    selection = table.selectionModel()
    for name in (guide, planes):
        index = table.model().index(by_name[name], 0)
        selection.select(index, QtCore.QItemSelectionModel.Select | QtCore.QItemSelectionModel.Rows)
    run.wait_until(lambda: len(p.maps.figure.axes) >= 2 and p.map_node is not None, 60.0,
                   "the feed maps of the two selected rows")
    maps = [a for a in p.maps.figure.axes if a.get_title()]
    run.check("two maps side by side, one colour bar", len(maps) == 2 and len(p.maps.figure.axes) == 3,
              str([a.get_title() for a in p.maps.figure.axes]))
    run.check("the selected rows are marked in the ranking",
              any(c.get_label() == "selected" for c in p.ranking.figure.axes[0].collections))
    node = p.map_node
    run.check("the selected row's feed map is in the 3D view", node is not None and node.getNumChildren() >= 3)
    run.panel_plots("strategy_study_maps_panel", p.maps.figure)
    run.panel_plots("strategy_study_ranking_selected", p.ranking.figure)
    for plots, name in ((p.ranking, "strategy_study_ranking_window"), (p.maps, "strategy_study_maps_window")):
        window = plots.open_window()
        run.widget_screenshot(name, window)
        run.check_plots_readable(name, plots.window_figure)
        window.close()
    for o in FreeCAD.ActiveDocument.Objects:  # the map over the part alone
        if o.ViewObject is not None:
            o.ViewObject.Visibility = o is state["part"]
    Gui.Selection.clearSelection()
    Gui.activeDocument().activeView().viewTop()
    Gui.SendMsgToActiveView("ViewFit")
    scroll_to(p.maps.canvas)
    run.screenshot("strategy_study_maps")
    state["selected"] = (guide, planes)


@run.step
def apply_adds_operations_that_compute(run):
    from PySide import QtCore

    p = panel()
    job = state["job"]
    table = p.form.table
    by_name = {table.item(r, 0).text(): r for r in range(table.rowCount())}
    applied = []
    for name in state["selected"]:
        table.clearSelection()
        table.selectionModel().select(table.model().index(by_name[name], 0),
                                      QtCore.QItemSelectionModel.Select | QtCore.QItemSelectionModel.Rows)
        op = p.apply()
        run.check("%s applied" % name, op is not None, p.form.message.text())
        if op is None:
            continue
        run.wait_until(lambda: run.valid(op) and len(op.Path.Commands) > 0, 60.0, "%s computed" % op.Label)
        applied.append(op)
        run.notes.setdefault("applied", {})[op.Label] = {"commands": len(op.Path.Commands), "passes": op.Passes,
                                                         "tool": op.ToolController.Label}
    run.check("both operations in the Job", all(op in job.Operations.Group for op in applied) and len(applied) == 2)
    guide_op = next((op for op in applied if hasattr(op, "Net")), None)
    net = guide_op.Net if guide_op is not None else None
    run.check("the guide operation's net has the row's K, P and mode", net is not None and
              (net.K, net.Step.Value, net.Mode) == (0.5, 20.0, "Boundaries to median"),
              str((net.K, net.Step.Value, net.Mode) if net is not None else None))
    run.check("the ops use a Ø10 ball at F4000", all(abs(op.ToolController.Tool.Diameter.Value - 10.0) < 1e-9 and
              abs(op.ToolController.HorizFeed.getValueAs("mm/min").Value - 4000.0) < 1e-6 for op in applied))
    run.check("one tool controller for both", len({op.ToolController.Name for op in applied}) == 1)
    for o in FreeCAD.ActiveDocument.Objects:
        if o.ViewObject is not None:
            o.ViewObject.Visibility = o is state["part"] or o is guide_op
    table.clearSelection()  # the operation's path alone, without a feed map over it
    run.check("no selected row: no feed map in the 3D view", p.map_node is None)
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    run.notes["status after apply"] = p.form.status.text()
    scroll_to(p.form.status)
    run.screenshot("strategy_study_applied")


@run.step
def apply_is_one_undo_step_and_a_deleted_part_is_said(run):
    from PySide import QtCore

    from hsmplanner.app import strategy_study

    p = panel()
    document, job = state["part"].Document, state["job"]
    table = p.form.table
    by_name = {table.item(r, 0).text(): r for r in range(table.rowCount())}
    table.clearSelection()
    table.selectionModel().select(table.model().index(by_name[state["selected"][0]], 0),
                                  QtCore.QItemSelectionModel.Select | QtCore.QItemSelectionModel.Rows)
    before = len(job.Operations.Group)
    op = p.apply()
    run.check("applied again", op is not None, p.form.message.text())
    name = op.Name if op is not None else ""
    run.notes["undo names after apply"] = document.UndoNames[:3]
    document.undo()  # the whole apply, net and operation, is one step (the controller was there already)
    run.check("one undo removes the applied operation", document.getObject(name) is None and
              len(job.Operations.Group) == before, str(document.UndoNames[:3]))
    # the studied part deleted since the run: Apply says so in the panel
    box = document.addObject("Part::Box", "Gone")
    document.recompute()
    gone = strategy_study.StudyInputs(box, "Face1", (box, ["Edge1"]), (box, ["Edge2"]))
    kept, p.ran_on = p.ran_on, (gone,) + p.ran_on[1:]
    document.removeObject("Gone")
    run.check("Apply on a deleted part says so", p.apply() is None and "no longer in its document" in
              p.form.message.text(), p.form.message.text())
    p.ran_on = kept


@run.step
def closing_mid_run_stops_the_study_and_removes_the_map_and_the_cache(run):
    import multiprocessing

    from PySide import QtCore

    p = panel()
    cache = p.cache_dir
    fill(p, planes="10,20,30,40,50,60", workers=2)
    QtCore.QTimer.singleShot(400, p.reject)  # the user closes the panel while the variants run
    rows = p.run()
    run.check("the run closed quietly", rows is None)
    run.wait_until(lambda: not run.task_dialog_open() and panel() is None, 20.0, "the panel closed")
    run.check("the 3D map is gone", p.map_node is None)
    run.check("the panel's cache is removed", not os.path.exists(cache), cache)
    run.check("no worker process is left running", not multiprocessing.active_children(),
              str(multiprocessing.active_children()))


run.start()
