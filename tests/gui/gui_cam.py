"""GUI test: HSM Planner inside FreeCAD's Path/CAM workbench. The workbench is in the selector; CAM's
preferences (Mod/CAM on 1.x) hold the suppressed feed-unit warning; a Job made by CAM's own command holds a
CAM operation and ours side by side; our operation takes a tool controller made from FreeCAD's ToolBit
library; CAM's own commands work on our operation: Inspect, Toggle Operation, Post Process, the Job's
Export Template (and a Job made from that template), and the 3-axis CAM Simulator."""
import json
import os
import shutil
import sys
import tempfile
import time

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtWidgets

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import OUT, GuiRun  # noqa: E402
from hsmplanner.app.compat import tool_shape_id  # noqa: E402

run = GuiRun()
state = {}
LIBRARY_BIT = "6mm Ball End"  # a ball end mill of FreeCAD's own ToolBit library


def cam(name):
    from hsmplanner.app.compat import cam_command_name

    return cam_command_name(name)


def when_modal(handle, timeout_s=20.0):
    """Runs handle(dialog) from the event loop once a command's modal dialog (its exec) blocks the step: the
    dialog is looked for every 100 ms (FreeCAD 1.1's Job dialog takes longer to show than 1.0's); after
    `timeout_s` handle(None) runs, so that the step goes on and reports what it did not see."""
    end = time.time() + timeout_s

    def poll():
        dialog = QtWidgets.QApplication.activeModalWidget()
        if dialog is not None and dialog.isVisible():
            handle(dialog)
        elif time.time() >= end:
            handle(None)
        else:
            QtCore.QTimer.singleShot(100, poll)

    QtCore.QTimer.singleShot(100, poll)


def feed_lines(text):
    """The G1 blocks of a G-code text, whatever the post put around them (line numbers, comments)."""
    return [line for line in text.splitlines() if " G1 " in " %s " % line.split("(")[0].replace("N", " N")]


@run.step
def workbench_in_the_selector(run):
    combos = [c for c in Gui.getMainWindow().findChildren(QtWidgets.QComboBox)
              if any(c.itemText(i) == "CAM" or c.itemText(i) == "Path" for i in range(c.count()))]
    run.check("FreeCAD's workbench selector found", bool(combos))
    items = [combos[0].itemText(i) for i in range(combos[0].count())] if combos else []
    run.notes["workbench selector"] = items
    run.check("HSM Planner in the workbench selector", "HSM Planner" in items, str(items))
    if "HSM Planner" in items:
        index = items.index("HSM Planner")
        run.check("its icon shown in the selector", not combos[0].itemIcon(index).isNull())


@run.step
def cam_workbench_commands_and_preferences(run):
    from hsmplanner.app.compat import cam_preferences_path, cam_workbench_name

    Gui.activateWorkbench(cam_workbench_name())
    run.wait_until(lambda: type(Gui.activeWorkbench()).__name__ == cam_workbench_name(), 20.0,
                   "FreeCAD's %s active" % cam_workbench_name())
    missing = [n for n in ("Job", "Post", "Inspect", "Simulator", "ExportTemplate", "OpActiveToggle", "Custom")
               if cam(n) not in Gui.listCommands()]
    run.check("CAM's own commands registered", not missing, str(missing))
    import Path.Preferences

    ours = FreeCAD.ParamGet(cam_preferences_path())
    run.check("CAM's preferences group is ours", Path.Preferences.preferences().GetGroupName() == ours.GetGroupName(),
              "%s / %s" % (Path.Preferences.preferences().GetGroupName(), cam_preferences_path()))
    run.check("the feed-unit warning is suppressed in CAM's preferences", Path.Preferences.suppressVelocity(),
              cam_preferences_path())
    Gui.activateWorkbench("HSMPlannerWorkbench")
    run.wait_until(lambda: type(Gui.activeWorkbench()).__name__ == "HSMPlannerWorkbench", 20.0,
                   "HSM Planner active again")


@run.step
def job_from_cams_command(run):
    """CAM's Job command, as a user runs it: its dialog (and no feed-unit warning before it) on the selected
    part."""
    from hsmplanner.app import guide_curve_net_object, master_feature_object

    document = FreeCAD.newDocument("CamIntegration")
    part = master_feature_object.create(document)
    net = guide_curve_net_object.create(document, (part, part.Boundary1), (part, part.Boundary2),
                                        (part, part.BottomFace))
    document.recompute()
    state.update(part=part, net=net)
    dialogs = []

    def accept_the_job_dialog(dialog):
        dialogs.append((type(dialog).__name__, dialog.windowTitle() if dialog else None,
                        dialog.text() if isinstance(dialog, QtWidgets.QMessageBox) else ""))
        if dialog is not None and "Job" not in dialog.windowTitle():  # the feed-unit warning: a failure, closed
            dialog.reject()
            when_modal(accept_the_job_dialog)
        elif dialog is not None:
            dialog.accept()

    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part)
    when_modal(accept_the_job_dialog)
    Gui.runCommand(cam("Job"))
    run.wait_until(lambda: any(hasattr(o, "Operations") for o in document.Objects), 20.0, "CAM's Job created")
    run.notes["dialogs of CAM's Job command"] = dialogs
    run.check("no feed-unit warning", not [d for d in dialogs if d[1] is None or "Job" not in d[1]], str(dialogs))
    jobs = [o for o in document.Objects if hasattr(o, "Operations")]
    models = [jobs[0].Proxy.baseObject(jobs[0], m) for m in jobs[0].Model.Group] if len(jobs) == 1 else []
    run.check("one Job on the selected part", models == [part], "%s %s" % ([j.Name for j in jobs], models))
    if jobs:
        state["job"] = jobs[0]
        state["job"].ViewObject.Proxy.taskPanel.accept()  # CAM's Job command leaves the Job's panel open
        run.wait_until(lambda: not run.task_dialog_open(), 10.0, "the Job's panel closed")


def library_working_dir():
    """A writable copy of FreeCAD's ToolBit library, set as CAM's tool working directory (as a user does at the
    first use of the library: FreeCAD's own folder is refused as one)."""
    import Path.Preferences

    work = tempfile.mkdtemp(prefix="hsm-tools-")
    default = Path.Preferences.pathDefaultToolsPath()
    for sub in ("Bit", "Library", "Shape"):
        shutil.copytree(os.path.join(default, sub), os.path.join(work, sub))
    Path.Preferences.setLastPathToolLibrary(os.path.join(work, "Library"))
    Path.Preferences.setLastPathToolBit(os.path.join(work, "Bit"))
    Path.Preferences.setLastFileToolLibrary(os.path.join(work, "Library", "Default.fctl"))
    return work


@run.step
def controller_from_the_toolbit_library(run):
    """CAM's tool library, as a user takes a tool from it: the library's ball end selected, "Add to Job" makes its
    tool controller (FreeCAD 1.1: the Toolbit Selector dialog; 1.0: the ToolBit dock)."""
    from hsmplanner.app.compat import has_tool_assets

    job = state["job"]
    before = list(job.Tools.Group)
    if has_tool_assets():
        _add_from_the_toolbit_selector(run)
    else:
        _add_from_the_toolbit_dock(run)
    added = [c for c in job.Tools.Group if c not in before]
    run.check("the library's tool controller added to the Job", len(added) == 1, str([c.Label for c in added]))
    if added:
        controller = added[0]
        controller.HorizFeed = FreeCAD.Units.Quantity("3000 mm/min")
        controller.VertFeed = FreeCAD.Units.Quantity("1000 mm/min")
        controller.SpindleSpeed = 16000
        state["controller"] = controller
        run.notes["library controller"] = [controller.Label, controller.Tool.Label, tool_shape_id(controller.Tool)]


def _add_from_the_toolbit_selector(run):
    """FreeCAD 1.1: CAM's ToolBitDock command opens the Toolbit Selector (a modal dialog on the tool library's
    assets): the library's ball end picked in its list, "Add to Job", "Close"."""
    seen = {}

    def pick_and_add(dialog):
        lists = [w for w in dialog.findChildren(QtWidgets.QListWidget) if hasattr(w, "get_selected_toolbit_uris")]
        items = [lists[0].item(i) for i in range(lists[0].count())] if lists else []
        labels = [_bit_label(item) for item in items]
        seen["labels"] = labels
        if LIBRARY_BIT in labels:
            lists[0].setCurrentItem(items[labels.index(LIBRARY_BIT)])
            _button(dialog, "Add to Job").click()
        seen["image"] = os.path.join(OUT, "cam_toolbit_selector.png")
        dialog.grab().save(seen["image"])
        _button(dialog, "Close").click()

    when_modal(pick_and_add)
    Gui.runCommand(cam("ToolBitDock"))
    run.wait_until(lambda: "labels" in seen, 20.0, "CAM's Toolbit Selector")
    run.check("the library lists %s" % LIBRARY_BIT, LIBRARY_BIT in seen.get("labels", []), str(seen.get("labels")))
    if "image" in seen:
        run.screenshots.append(seen["image"])


def _bit_label(item):
    """The label of the tool bit an item of 1.1's tool list shows (its URI names the asset: toolbit://ID)."""
    from Path.Tool.toolbit.ui.toollist import ToolBitUriRole

    uri = str(item.data(ToolBitUriRole) or "")
    return uri.split("://", 1)[-1].replace("_", " ")


def _button(dialog, text):
    return next(b for b in dialog.findChildren(QtWidgets.QPushButton) if b.text().replace("&", "") == text)


def _add_from_the_toolbit_dock(run):
    """FreeCAD 1.0: CAM's ToolBit dock, the library's ball end selected, "Add to Job"."""
    library_working_dir()
    Gui.runCommand(cam("ToolBitDock"))
    run.wait_until(lambda: _library_dock() is not None, 10.0, "CAM's ToolBit dock open")
    dock = _library_dock()
    # FreeCAD 1.0's dock fills its list before it is given its libraries: at first opening it is empty until
    # the user picks a library in its combo box, as here
    dock.findChild(QtWidgets.QComboBox, "cboLibraries").currentIndexChanged.emit(0)
    tools = dock.findChild(QtWidgets.QAbstractItemView, "tools")
    model = tools.model()
    rows = [r for r in range(model.rowCount()) if model.index(r, 1).data() == LIBRARY_BIT]
    run.check("the library lists %s" % LIBRARY_BIT, bool(rows),
              str([model.index(r, 1).data() for r in range(model.rowCount())]))
    if rows:
        tools.selectionModel().select(model.index(rows[0], 0), QtCore.QItemSelectionModel.ClearAndSelect
                                      | QtCore.QItemSelectionModel.Rows)
        dock.findChild(QtWidgets.QPushButton, "addToolController").click()
    dock.close()


def _library_dock():
    docks = [d for d in Gui.getMainWindow().findChildren(QtWidgets.QDockWidget)
             if d.objectName() == "ToolSelector" and d.isVisible()]
    return docks[0] if docks else None


@run.step
def cams_operation_and_ours_in_the_job(run):
    """A CAM Custom operation and our guide-curve finishing, each taking the library's tool controller selected
    in the tree, as CAM's own operations do."""
    job, document = state["job"], state["job"].Document
    controller = state.get("controller")
    select_controller(controller)  # with two in the Job, CAM asks which one in a modal dialog otherwise
    Gui.runCommand(cam("Custom"))
    run.wait_until(lambda: document.getObject("Custom") is not None and run.task_dialog_open(), 20.0,
                   "CAM's Custom operation and its panel")
    custom = document.getObject("Custom")
    if custom is None:
        return
    custom.Gcode = ["G0 X0 Y0 Z30", "G0 X10 Y10 Z30"]
    custom.ViewObject.Proxy.panel.accept()
    run.wait_until(lambda: not run.task_dialog_open(), 10.0, "the Custom panel closed")
    select_controller(controller)
    Gui.runCommand("HSM_GuideCurveFinishing")
    run.wait_until(lambda: document.getObject("GuideCurveFinishing") is not None
                   and document.getObject("GuideCurveFinishing").ViewObject.Proxy.panel is not None, 30.0,
                   "the Guide curve finishing panel open")
    op = document.getObject("GuideCurveFinishing")
    panel = op.ViewObject.Proxy.panel
    page = panel.featurePages[-1]
    page.form.net.setCurrentText(state["net"].Label)
    page.form.cusp.setValue(0.05)  # a coarse finish: the simulator below replays every move
    page.form.tolerance.setValue(0.05)
    run.check("the panel shows the library's controller", controller is not None and
              page.form.toolController.currentText() == controller.Label, page.form.toolController.currentText())
    panel.accept()
    run.wait_until(lambda: not run.task_dialog_open() and run.valid(op) and len(op.Path.Commands) > 100, 60.0,
                   "the guide curve finishing computed")
    run.check("our operation took the library's tool controller", op.ToolController is controller,
              op.ToolController.Label)
    group = list(job.Operations.Group)
    run.check("CAM's operation and ours in the Job", custom in group and op in group, str([o.Name for o in group]))
    run.notes["job operations"] = [o.Name for o in group]
    run.notes["guide curve finishing commands"] = len(op.Path.Commands)
    state.update(op=op, custom=custom)
    show_path_only(op)
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("cam_job_with_our_operation")


@run.step
def cycle_time_of_the_job(run):
    """HSM Planner's Cycle time on CAM's Job: a row per operation, CAM's and ours, with CAM's estimate, length /
    feed and the simulated time, then the Job's total; the times also land on the operations."""
    from hsmplanner.gui.cycle_time_panel import CycleTimePanel

    job = state["job"]
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(job)
    Gui.runCommand("HSM_CycleTime")
    run.wait_until(lambda: CycleTimePanel.active is not None, 30.0, "the Cycle time panel open")
    panel = CycleTimePanel.active
    if panel is None:
        return
    ops = [o for o in job.Operations.Group if o.Active]
    table = panel.table
    cells = [[table.item(r, c).text() if table.item(r, c) else "" for c in range(table.columnCount())]
             for r in range(table.rowCount())]
    run.notes["cycle time table"] = cells
    run.check("a row per operation and the Job's", table.rowCount() == len(ops) + 1, str(cells))
    run.check("every row simulated", all(row[1] for row in cells), str(cells))
    run.check("the simulated time on each operation and the Job",
              all(getattr(o, "SimulatedCycleTime", 0) > 0 for o in ops + [job]),
              str([(o.Label, getattr(o, "SimulatedCycleTime", None)) for o in ops + [job]]))
    run.check_fits_combo_view("Cycle time panel", panel.form)
    from hsmplanner.gui.cycle_time_panel import KEY_COLUMNS

    run.check_table_reads("Cycle time table", table, KEY_COLUMNS)
    run.screenshot("cam_cycle_time")
    panel.reject()
    run.wait_until(lambda: not run.task_dialog_open(), 10.0, "the Cycle time panel closed")


def select_controller(controller):
    """The tool controller selected in the tree: CAM's next new operation takes it."""
    Gui.Selection.clearSelection()
    if controller is not None:
        Gui.Selection.addSelection(controller)


def show_path_only(op):
    for o in op.Document.Objects:
        if o.ViewObject is not None:
            o.ViewObject.Visibility = o in (op, state["part"])
    state["part"].ViewObject.Transparency = 60


@run.step
def cams_inspect_shows_our_path(run):
    op, seen = state["op"], {}

    def read_and_close(dialog):
        editor = getattr(dialog, "editor", None)
        seen["lines"] = len(editor.toPlainText().splitlines()) if editor is not None else None
        if dialog is not None:
            image = os.path.join(OUT, "cam_inspect.png")
            dialog.grab().save(image)
            run.screenshots.append(image)
            dialog.reject()  # Cancel: the path is left as it is

    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(op)
    when_modal(read_and_close)
    Gui.runCommand(cam("Inspect"))
    run.wait_until(lambda: "lines" in seen, 20.0, "CAM's Inspect dialog")
    run.check("Inspect lists every command of our path", seen.get("lines") == len(op.Path.Commands),
              "%s lines, %d commands" % (seen.get("lines"), len(op.Path.Commands)))


def post_process(job, output):
    """CAM's Post Process command on the selected Job, to `output`, overwriting and without the editor."""
    import Path.Preferences

    Path.Preferences.preferences().SetString(Path.Preferences.PostProcessorOutputPolicy, "Overwrite")
    job.PostProcessor = "linuxcnc"
    job.PostProcessorArgs = "--no-show-editor"
    job.PostProcessorOutputFile = output
    if os.path.exists(output):
        os.remove(output)
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(job)
    Gui.runCommand(cam("Post"))
    if not run.wait_until(lambda: os.path.exists(output), 30.0, "CAM's post-processor output %s" % output):
        run.notes["report view after Post Process"] = run.report_view_text()[-1500:]
        return ""
    with open(output) as stream:
        return stream.read()


@run.step
def cams_post_process_and_toggle_operation(run):
    job, op = state["job"], state["op"]
    output = os.path.join(tempfile.mkdtemp(prefix="hsm-post-"), "job.ngc")
    text = post_process(job, output)
    ours = sum(1 for c in op.Path.Commands if c.Name in ("G1", "G01"))
    lines = feed_lines(text)
    run.notes["post: G1 lines, our G1 commands"] = [len(lines), ours]
    run.check("the post names our operation", "GuideCurveFinishing" in text)
    run.check("the post writes every feed move of our operation", len(lines) >= ours > 100,
              "%d G1 lines for %d G1 commands" % (len(lines), ours))
    run.check("the post writes CAM's operation beside ours", "X10.000 Y10.000" in text)
    shutil.copy(output, os.path.join(OUT, "cam_post_linuxcnc.ngc"))

    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(op)
    Gui.runCommand(cam("OpActiveToggle"))
    run.wait_until(lambda: not op.Active, 10.0, "our operation made inactive")
    icon = op.ViewObject.Proxy.getIcon()
    run.check("an inactive operation shows CAM's inactive icon", "OpActive" in str(icon), str(icon))
    inactive = post_process(job, output)
    run.check("the post leaves the inactive operation out", "GuideCurveFinishing" not in inactive
              and len(feed_lines(inactive)) < ours)
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(op)
    Gui.runCommand(cam("OpActiveToggle"))
    run.wait_until(lambda: op.Active and run.valid(op), 30.0, "our operation active again")
    run.check("active again: our icon", op.ViewObject.Proxy.getIcon() == op.ViewObject.Proxy.OpIcon)


@run.step
def jobs_export_template_carries_our_controller(run):
    """The Job's Export Template (the command's own writer, without its file dialog), then a new Job made
    from that template: the library's ball end and its feeds came through, and our operation can use it."""
    from hsmplanner.app import finishing
    from hsmplanner.app.compat import cam_module

    job, controller = state["job"], state["controller"]
    path = os.path.join(tempfile.mkdtemp(prefix="hsm-template-"), "job_hsm.json")
    import Path.Main.Gui.JobCmd as JobCmd

    JobCmd.CommandJobTemplateExport.Execute(job, path)
    with open(path) as stream:
        template = json.load(stream)
    labels = [tc.get("label") or tc.get("name") for tc in template.get("ToolController", [])]
    run.check("the template holds the library's controller", controller.Label in labels, str(labels))
    copy = cam_module("job").Create("FromTemplate", [state["part"]], path)
    copy.Document.recompute()
    same = [tc for tc in copy.Tools.Group if tc.Label.startswith(controller.Label)]  # (labels are made unique)
    run.check("a Job from the template has the controller", len(same) == 1, str([t.Label for t in copy.Tools.Group]))
    if same:
        run.check("and our finishing can use it (a ball end with its feed)", finishing.is_usable(same[0]),
                  "%s %s %s" % (tool_shape_id(same[0].Tool), same[0].Tool.Diameter, same[0].HorizFeed))
    state["template job"] = copy


def simulated_tops(simulation, part, cell_mm=2.0):
    """The top of the simulated stock in each 2 mm cell over the middle of the bottom face (5 mm in from its
    box), sorted. Untouched, every one is the stock's top."""
    face = part.Shape.getElement(part.BottomFace).BoundBox
    tops = {}
    for mesh in (simulation.cutMaterial.Mesh, simulation.cutMaterialIn.Mesh):
        for p in mesh.Points:
            if face.XMin + 5 < p.x < face.XMax - 5 and face.YMin + 5 < p.y < face.YMax - 5:
                cell = (int(p.x // cell_mm), int(p.y // cell_mm))
                tops[cell] = max(tops.get(cell, p.z), p.z)
    return sorted(tops.values())


def simulation_of(command):
    """Runs CAM's Simulator command and returns the simulation it made (its panel's Python object is not
    reachable through FreeCAD's task view): the class's Activate records its instance for this run."""
    import Path.Main.Gui.Simulator as Simulator

    made, activate = [], Simulator.PathSimulation.Activate

    def recording(self):
        made.append(self)
        activate(self)

    Simulator.PathSimulation.Activate = recording
    try:
        Gui.runCommand(command)
    finally:
        Simulator.PathSimulation.Activate = activate
    return made[0] if made else None


@run.step
def cams_simulator_cuts_with_our_path(run):
    """CAM's (3-axis) Simulator on the Job, our operation alone, run to its end: material is removed where our
    path goes. (Volume roughing with A/C is 5-axis: this simulator moves the tool in X/Y/Z only.)"""
    job, op = state["job"], state["op"]
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(job)
    simulation = simulation_of(cam("Simulator"))
    run.check("the Simulator's panel", simulation is not None and run.task_dialog_open())
    if simulation is None:
        return
    form = simulation.taskForm.form
    for i in range(form.listOperations.count()):
        item = form.listOperations.item(i)
        item.setCheckState(QtCore.Qt.Checked if item.text() == op.Label else QtCore.Qt.Unchecked)
    simulation.SimStop()  # the checked operations are taken at the next start
    simulation.SimFF()
    run.wait_until(lambda: not simulation.timer.isActive(), 240.0, "the Simulator at the end of our path")
    tops, top = simulated_tops(simulation, state["part"]), job.Stock.Shape.BoundBox.ZMax
    bottom = state["part"].Shape.getElement(state["part"].BottomFace).BoundBox.ZMin
    median = tops[len(tops) // 2] if tops else top
    feeds = [c.Parameters["Z"] for c in op.Path.Commands if c.Name == "G1" and "Z" in c.Parameters]
    run.notes["simulator over the bottom face: median and lowest material top, stock top, face's lowest, "
              "our path's lowest Z (mm)"] = [round(v, 2) for v in (median, tops[0] if tops else top, top, bottom,
                                                                  min(feeds))]
    run.notes["simulator: cells below the face's lowest - 1 mm, cells"] = [sum(t < bottom - 1.0 for t in tops),
                                                                            len(tops)]
    run.check("the Simulator cleared the channel along our path", median < top - 0.5 * (top - bottom),
              "median top %.2f, stock top %.2f, face's lowest %.2f" % (median, top, bottom))
    show_path_only(op)
    simulation.cutMaterial.ViewObject.Visibility = True
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("cam_simulator_our_path")
    simulation.taskForm.accept()
    run.wait_until(lambda: not run.task_dialog_open(), 10.0, "the Simulator closed")


run.start()
