"""GUI test: the Roughing study's Apply on a Job with no roughing tool is one undo step (the operation, the tool
controller and its ToolBit go with one undo), and FreeCAD draws the Volume roughing path of every strategy where
the part is, on the slanted slot and on one impeller channel: what the 3D view draws of the path (the coin nodes
of the view provider's display mode) lies on the stock, and the tool-axis ticks sit on it. A strategy the volume
cannot take says so and leaves the volume shown."""
import os
import sys

import FreeCAD
import FreeCADGui as Gui
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import GuiRun, scene_nodes, show_only  # noqa: E402

run = GuiRun()
state = {}
STRATEGIES = ("S1", "S2", "S3", "S4", "S5")
REFUSED = {"slot": {"S2": "S2 needs a cylindrical"}}  # the slot has no outlet cylinder for S2's coaxial slices
RETRACT_ROOM = 1.0  # of the stock's height, above it, for retracts and links along a tilted tool axis
TICK_ON_PATH_MM = 0.01  # a tick starts on the drawn tip path: both come from the same tips, interpolated alike


def names(document):
    return sorted(o.Name for o in document.Objects)


def new_part_with_volume_and_job(make, region):
    """A test part and its stock (hsmplanner.app.roughing.parts), its Roughing volume made by the command from
    both selected (`region`: 0 for all), and a Job on the part with FreeCAD's default tool controller only (feeds
    of 0: no roughing tool)."""
    from hsmplanner.app.roughing import parts as roughing_parts
    from hsmplanner.app.compat import create_job

    document = FreeCAD.ActiveDocument
    part, stock = getattr(roughing_parts, make)(document)
    known = set(names(document))
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part)
    Gui.Selection.addSelection(stock)
    Gui.runCommand("HSM_RoughingVolume")
    volume = next(document.getObject(n) for n in names(document) if n not in known and n.startswith("RoughingVolume"))
    volume.Region = region
    job = create_job([part])
    document.recompute()
    run.wait_until(lambda: run.valid(volume) and volume.Volume > 0 and job.Stock is not None, 60.0,
                   "%s, its Roughing volume and a Job" % part.Label)
    for obj in (stock, job):
        obj.ViewObject.Visibility = False
    return part, stock, volume, job


@run.step
def slot_with_a_job_without_a_roughing_tool(run):
    from hsmplanner.app.roughing.operation import is_roughing_controller

    Gui.activateWorkbench("HSMPlannerWorkbench")
    FreeCAD.newDocument("RoughingPaths")
    state["slot"] = new_part_with_volume_and_job("create_slanted_slot_block", 0)
    job = state["slot"][3]
    run.check("the Job has no tool roughing can use", not any(is_roughing_controller(c) for c in job.Tools.Group),
              str([c.Label for c in job.Tools.Group]))


@run.step
def study_apply_is_undone_in_one_step(run):
    """Apply of a rest row adds the operation, the paper's torus controller and its ToolBit (with the ToolBit's
    body, copied from its shape file), and the rest roughing after it (its own Roughing volume, a Ø4 torus
    controller, RestFrom the first); one undo of FreeCAD takes all of them away."""
    from hsmplanner.gui import roughing_study_panel

    document = FreeCAD.ActiveDocument
    part, stock, volume, job = state["slot"]
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(volume)
    Gui.runCommand("HSM_RoughingStudy")
    run.wait_until(lambda: roughing_study_panel.RoughingStudyPanel.active is not None, 20.0, "the Roughing study panel")
    study = roughing_study_panel.RoughingStudyPanel.active
    for name, box in study.form.strategies.items():
        box.setChecked(name == "S1")
    for key, box in study.form.variants.items():
        box.setChecked(key == roughing_study_panel.VARIANTS[2][3])  # step-up, then the rest roughing
    study.form.resolution.setValue(2.0)  # coarse: only Apply is tested here
    study.run()
    study.form.table.selectRow(0)
    before, tools_before = names(document), [c.Name for c in job.Tools.Group]
    op = study.apply()
    run.check("Apply made an operation", op is not None, study.form.status.text())
    if op is None:
        return
    run.wait_until(lambda: run.valid(op) and op.Passes > 0, 60.0, "the applied operation computed")
    added = sorted(set(names(document)) - set(before))
    kinds = {document.getObject(n).TypeId for n in added}
    run.notes["apply added"] = added
    run.check("Apply added the operation, a tool controller and its ToolBit", op.Name in added and
              op.ToolController.Name in added and op.ToolController.Tool.Name in added, str(added))
    rest = [o for o in job.Operations.Group if getattr(o, "RestFrom", None) == op]
    run.check("and the rest roughing after it, on its own S3 volume with the Ø4 torus", len(rest) == 1 and
              rest[0].Name in added and rest[0].Volume.Name in added and rest[0].Volume.Strategy.startswith("S3")
              and abs(rest[0].ToolController.Tool.Diameter.Value - 4.0) < 1e-9, str(added))
    if rest:
        run.wait_until(lambda: run.valid(rest[0]) and "Invalid" not in rest[0].State, 60.0, "the rest roughing computed")
        run.notes["rest roughing"] = {"passes": rest[0].Passes, "cut mm": rest[0].CuttingLength.Value,
                                      "closest mm": rest[0].ClosestApproach.Value}
        run.check("the rest roughing computed, clear of the part", rest[0].ClosestApproach.Value >= 0.49 or
                  rest[0].Passes == 0, str(run.notes["rest roughing"]))
    applied = "Apply roughing strategy S1 step-up + rest S3 Ø4"
    run.notes["undo names"] = list(document.UndoNames[:4])
    run.check("Apply is the last undo step", document.UndoNames[:1] == [applied], str(document.UndoNames[:3]))
    # FreeCAD 1.1's GUI ends an open transaction when its tool library makes a tool bit's body (Apply makes two
    # bits: the Ø8 and the Ø4 torus); compat.create_tool_bit opens it again under the same name. So Apply is one
    # undo step on 1.0 and up to three of the same name on 1.1; undoing them leaves the document as before.
    steps = 0
    while document.UndoNames[:1] == [applied] and steps < 5:
        Gui.runCommand("Std_Undo")
        steps += 1
    run.notes["undo steps of Apply"] = steps
    from hsmplanner.app.compat import has_tool_assets
    run.check("Apply is %s undo step(s)" % ("1-3" if has_tool_assets() else "1"),
              1 <= steps <= (3 if has_tool_assets() else 1), str(steps))
    left = sorted(set(names(document)) - set(before))
    gone = sorted(set(before) - set(names(document)))
    run.check("undoing Apply leaves the document as before", names(document) == before,
              "left: %s, gone: %s (added: %s, %s)" % (left, gone, added, sorted(kinds)))
    run.check("the Job's tools as before", [c.Name for c in job.Tools.Group] == tools_before,
              str([c.Label for c in job.Tools.Group]))
    run.check("the Job's operations as before", not job.Operations.Group, str([o.Label for o in job.Operations.Group]))
    run.screenshot("roughing_paths_apply_undone")
    for key, box in study.form.variants.items():  # the next step draws the step-up operation alone
        box.setChecked(key == roughing_study_panel.VARIANTS[1][3])
    study.run()
    study.form.table.selectRow(0)
    state["slot_op"] = study.apply()  # again: the operation the next step draws
    run.wait_until(lambda: run.valid(state["slot_op"]) and state["slot_op"].Passes > 0, 60.0,
                   "the operation applied again")
    study.reject()
    run.wait_until(lambda: not run.task_dialog_open(), 20.0, "the study panel closed")


def mode_node(vobj):
    """The scene of the display mode the 3D view shows for a view object (FreeCAD's mode switch, under the root
    node: the child it has switched on)."""
    from pivy import coin

    root = vobj.RootNode
    for index in range(root.getNumChildren()):
        child = root.getChild(index)
        if child.isOfType(coin.SoSwitch.getClassTypeId()):
            switch = coin.cast(child, "SoSwitch")
            shown = switch.whichChild.getValue()
            return switch.getChild(shown) if 0 <= shown < switch.getNumChildren() else None
    return None


def drawn_polylines(node):
    """The points of each SoCoordinate3 under a scene node, as drawn (in the order of the moves)."""
    lines = [np.array([p.getValue() for p in coordinates.point.getValues()], dtype=float).reshape(-1, 3)
             for coordinates in scene_nodes(node, "SoCoordinate3")]
    return [line for line in lines if len(line)]


def distances_to_polylines(points, polylines):
    """Each point's distance to the nearest segment of the polylines."""
    segments = np.concatenate([np.stack([line[:-1], line[1:]], axis=1) for line in polylines if len(line) > 1])
    a, b = segments[:, 0], segments[:, 1]
    ab = b - a
    length2 = np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-24)
    nearest = np.full(len(points), np.inf)
    for start in range(0, len(points), 256):  # 256 points at a time against every segment
        chunk = points[start:start + 256, None, :]
        share = np.clip(np.einsum("pij,ij->pi", chunk - a, ab) / length2, 0.0, 1.0)
        closest = a + share[:, :, None] * ab
        nearest[start:start + 256] = np.linalg.norm(chunk - closest, axis=2).min(axis=1)
    return nearest


def tick_tips(op):
    """The tip end of each tool-axis tick the view provider draws (segments from the tip along the axis)."""
    ticks = getattr(op.ViewObject.Proxy, "ticks", None)
    if ticks is None:
        return np.zeros((0, 3))
    lines = ticks.getChild(ticks.getNumChildren() - 1)
    vertices = lines.vertexProperty.getValue().vertex.getValues()
    return np.array([v.getValue() for v in vertices], dtype=float).reshape(-1, 2, 3)[:, 0]


def check_drawn_on_the_part(key, strategy, op, stock):
    """What the 3D view draws of the operation's path lies on the stock (its box, grown by the tool's radius
    around and by RETRACT_ROOM above), reaches into it, and carries the tool-axis ticks."""
    what = "%s %s" % (key, strategy)
    drawn = drawn_polylines(mode_node(op.ViewObject)) if mode_node(op.ViewObject) is not None else []
    if not drawn:
        run.check("%s: a path is drawn" % what, False, op.ViewObject.DisplayMode)
        return
    points = np.vstack(drawn)
    low, high = points.min(axis=0), points.max(axis=0)
    box = stock.Shape.BoundBox
    margin = 0.5 * op.ToolController.Tool.Diameter.Value + 1.0
    top = box.ZMax + RETRACT_ROOM * box.ZLength  # the retracts and links run above the stock
    inside = bool(np.all(low >= [box.XMin - margin, box.YMin - margin, box.ZMin - margin])
                  and np.all(high <= [box.XMax + margin, box.YMax + margin, top]))
    into = bool(np.all(low < [box.XMax, box.YMax, box.ZMax]) and np.all(high > [box.XMin, box.YMin, box.ZMin]))
    tips = tick_tips(op)
    off = float(distances_to_polylines(tips, drawn).max()) if len(tips) else np.inf
    run.notes.setdefault("drawn paths", {})[what] = {
        "mode": op.ViewObject.DisplayMode, "drawn box": [low.round(1).tolist(), high.round(1).tolist()],
        "stock box": [[box.XMin, box.YMin, box.ZMin], [box.XMax, box.YMax, box.ZMax]], "ticks": len(tips),
        "tick farthest off the path mm": round(off, 6), "passes": op.Passes}
    run.check("%s: the drawn path lies on the stock and cuts into it" % what, inside and into,
              str(run.notes["drawn paths"][what]))
    run.check("%s: the tool-axis ticks sit on the drawn path" % what, len(tips) > 0 and off <= TICK_ON_PATH_MM,
              "%d ticks, the farthest %.4f mm off" % (len(tips), off))


def check_refused(key, strategy, volume):
    """A strategy the volume cannot take: the volume says why and stays in the view as the volume to remove."""
    from hsmplanner.gui.roughing_panel import message_text

    def drawn():
        node = getattr(volume.ViewObject.Proxy, "root", None)
        return node.getNumChildren() if node is not None else 0

    message = message_text(volume)
    run.notes.setdefault("refused", {})["%s %s" % (key, strategy)] = message
    run.check("%s %s refused with its message" % (key, strategy), REFUSED[key][strategy] in message, message)
    run.wait_until(lambda: volume.ViewObject.Visibility and drawn() > 0 and len(volume.Shape.Solids) >= 1, 10.0,
                   "%s %s: the volume to remove still shown" % (key, strategy))


def every_strategy(key, op, volume, stock, timeout, strategies=STRATEGIES):
    from hsmplanner.app.roughing import volume as roughing_object

    document = FreeCAD.ActiveDocument
    for strategy in strategies:
        volume.Strategy = roughing_object.strategy_label(strategy)
        probe = run.event_loop_probe(document.recompute)
        run.notes.setdefault("event loop while %s recomputes" % key, {})[strategy] = probe
        if key == "impeller" and strategy not in REFUSED.get(key, {}):  # its sweeps take seconds: beside the loop
            run.check("%s %s: the GUI served events while the core computed" % (key, strategy),
                      probe["ticks_in_worker"] > 0, str(probe))
        if strategy in REFUSED.get(key, {}):
            run.wait_until(lambda: volume.Proxy.error is not None, timeout, "%s %s refused" % (key, strategy))
            check_refused(key, strategy, volume)
            continue
        run.wait_until(lambda: run.valid(volume) and volume.SubVolumeCount > 0 and run.valid(op) and op.Passes > 0,
                       timeout, "%s %s partitioned and swept" % (key, strategy))
        check_drawn_on_the_part(key, strategy, op, stock)
        if strategy in ("S1", "S5"):
            show_only(op, volume.Part, volume)
            Gui.activeDocument().activeView().viewIsometric()
            Gui.SendMsgToActiveView("ViewFit")
            run.screenshot("roughing_paths_%s_%s" % (key, strategy))



@run.step
def every_strategy_drawn_on_the_slot(run):
    part, stock, volume, job = state["slot"]
    every_strategy("slot", state["slot_op"], volume, stock, 60.0)


@run.step
def the_operation_panel_shows_and_sets_the_push_out(run):
    """The Volume roughing panel as a user opens it (double click: setEdit) has the push-out at its default, fits
    the Combo View, and its value reaches the operation, which recomputes with it."""
    from hsmplanner.app.roughing import volume as roughing_object

    op, volume = state["slot_op"], state["slot"][2]
    volume.Strategy = roughing_object.strategy_label("S1")  # levels across the slot's leaning walls
    FreeCAD.ActiveDocument.recompute()
    run.wait_until(lambda: run.valid(volume) and run.valid(op) and op.Passes > 0, 60.0, "the slot's S1 swept")
    cut_before = op.CuttingLength.Value
    Gui.ActiveDocument.setEdit(op.Name)
    run.wait_until(lambda: op.ViewObject.Proxy.panel is not None and run.task_dialog_open(), 30.0,
                   "the Volume roughing panel open")
    panel = op.ViewObject.Proxy.panel
    page = panel.featurePages[-1]
    run.check("the panel shows the operation's push-out", abs(page.form.pushOut.value() - op.PushOut.Value) < 1e-9
              and op.PushOut.Value > 0.0, "%g %g" % (page.form.pushOut.value(), op.PushOut.Value))
    run.check_fits_combo_view("Volume roughing panel", page.form)
    run.screenshot("volume_roughing_panel")
    page.form.pushOut.setValue(0.0)
    panel.accept()
    run.wait_until(lambda: not run.task_dialog_open() and run.valid(op) and op.PushOut.Value == 0.0, 90.0,
                   "the panel closed and the roughing recomputed without the push-out")
    run.check("without the push-out the outer passes cut less", 0.0 < op.CuttingLength.Value < cut_before,
              "%.1f mm, %.1f with" % (op.CuttingLength.Value, cut_before))
    run.notes["slot push-out"] = {"cutting mm with": cut_before, "without": op.CuttingLength.Value}


@run.step
def every_strategy_drawn_on_an_impeller_channel(run):
    """One channel of the seven (region 1, the largest) at the volume's default step: seconds a strategy. Z-level
    planes and the continuous 5-axis offsets of the hub (S2 to S4 are drawn on the slot and swept on the impeller
    by the FreeCAD layer's tests)."""
    from hsmplanner.app.roughing import operation as roughing_op
    from hsmplanner.gui.finishing_ops_gui import add_volume_roughing

    part, stock, volume, job = new_part_with_volume_and_job("create_impeller", 1)
    op = add_volume_roughing(job)
    op.ToolController = roughing_op.roughing_controller(job)
    op.Volume = volume
    every_strategy("impeller", op, volume, stock, 90.0, ("S1", "S5"))


run.start()
