"""GUI test: the slanted slot block and the impeller with their stocks, the Roughing volume from two selected
solids (faces coloured by class, the legend), its panel (strategy, sub-volumes in alternating colours, Cancel
restores, a bad input shown), Esc on a long partition keeps the previous result, and the colours after the
document is saved and reopened."""
import colorsys
import os
import sys
import tempfile

import FreeCAD
import FreeCADGui as Gui
import numpy as np
from PySide import QtCore

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import OUT, GuiRun, image_pixels, scene_nodes, show_only  # noqa: E402

run = GuiRun()
state = {}
SLOT_VOLUME = 15360.0
# hue bands (degrees) of the face classes' colours and of the slices' (hsmplanner.gui.colors)
# (blends with the grey part and the white background keep a colour's hue; blends of two colours do not)
CLASS_HUES = {"crossable": (200, 235), "facing crossable": (95, 165), "not crossable": (-30, 30)}
SLICE_HUES = {"even slices": (20, 50), "odd slices": (170, 205)}


def panel():
    from hsmplanner.gui import roughing_panel

    return roughing_panel.RoughingPanel.active


def roughing_node(obj):
    """The view provider's scene of the volume (None when nothing is drawn)."""
    root = getattr(obj.ViewObject.Proxy, "root", None)
    return root.getChild(0) if root is not None and root.getNumChildren() else None


def drawn_colours(obj):
    """The colour the view provider drew each face of the Shape in (None before it drew)."""
    drawn = getattr(obj.ViewObject.Proxy, "drawn", None)
    return [tuple(round(c, 3) for c in colour) for colour in drawn["faces"]] if drawn else None


def palette_of(name):
    """The colours of hsmplanner.gui.colors.<name>, rounded as drawn_colours gives them."""
    from hsmplanner.gui import colors

    return {tuple(round(c, 3) for c in colour) for colour in getattr(colors, name)}


def hue_counts(name, bands):
    """Pixels of the 3D view (saved as an image, white background) in each hue band, of saturated colours."""
    path = os.path.join(OUT, name + ".png")
    Gui.ActiveDocument.ActiveView.saveImage(path, 900, 700, "White")
    run.screenshots.append(path)
    pixels = image_pixels(path)
    model = pixels[:, : int(0.7 * pixels.shape[1])]  # the legend (at the right) has a square of each colour
    rgb = model[:, :, [2, 1, 0]].reshape(-1, 3).astype(float) / 255.0
    saturated = rgb[(rgb.max(axis=1) - rgb.min(axis=1)) > 0.15]
    hues = np.array([colorsys.rgb_to_hsv(*p)[0] * 360.0 for p in saturated[:: max(1, len(saturated) // 40000)]])
    hues = np.where(hues > 330.0, hues - 360.0, hues)
    counts = {label: int(np.sum((hues >= low) & (hues <= high))) for label, (low, high) in bands.items()}
    run.notes.setdefault("hue pixel counts (sampled)", {})[name] = counts
    return counts



@run.step
def slot_block_and_its_stock(run):
    Gui.activateWorkbench("HSMPlannerWorkbench")
    Gui.runCommand("HSM_SlantedSlotBlock")
    document = FreeCAD.ActiveDocument
    run.wait_until(lambda: run.shape_built(document.getObject("SlantedSlotBlock"))
                   and run.shape_built(document.getObject("SlantedSlotBlockStock")), 30.0,
                   "the slot block and its stock")
    state["part"], state["stock"] = document.getObject("SlantedSlotBlock"), document.getObject("SlantedSlotBlockStock")
    run.check("stock hidden, drawn as a wireframe when shown", state["stock"].ViewObject.DisplayMode == "Wireframe"
              and not state["stock"].ViewObject.Visibility, state["stock"].ViewObject.DisplayMode)
    run.check("the icons resolve", all(os.path.isfile(o.ViewObject.Proxy.getIcon())
                                       for o in (state["part"], state["stock"])))
    run.screenshot("roughing_slot_block")


@run.step
def roughing_volume_of_two_selected_solids(run):
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(state["stock"])  # the stock first: the command tells them apart
    Gui.Selection.addSelection(state["part"])
    Gui.runCommand("HSM_RoughingVolume")
    document = FreeCAD.ActiveDocument

    def computed():
        obj = document.getObject("RoughingVolume")
        return run.valid(obj) and obj.Volume > 0 and roughing_node(obj) is not None

    run.wait_until(computed, 60.0, "the roughing volume computed and drawn")
    obj = document.getObject("RoughingVolume")
    state["slot"] = obj
    run.check("no panel for two selected solids", not run.task_dialog_open() and panel() is None)
    run.check("part and stock told apart", (obj.Part, obj.Stock) == (state["part"], state["stock"]))
    run.check("volume 15360 mm³", abs(obj.Volume - SLOT_VOLUME) <= 1e-6 * SLOT_VOLUME, str(obj.Volume))
    run.check("stock hidden", not state["stock"].ViewObject.Visibility)
    run.check("drawn in the roughing mode", obj.ViewObject.DisplayMode == "Roughing", obj.ViewObject.DisplayMode)
    colours, expected = set(drawn_colours(obj)), palette_of("FACE_CLASS_COLORS")
    run.check("the three classes' colours are drawn", colours == expected, "%s vs %s" % (colours, expected))
    run.check("a little transparent", 0 < obj.ViewObject.Transparency <= 50, str(obj.ViewObject.Transparency))
    run.check("FreeCAD's own modes get the colours too", len(obj.ViewObject.DiffuseColor) == len(obj.Shape.Faces))
    Gui.Selection.clearSelection()
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("roughing_slot_classes")
    counts = hue_counts("view3d_slot_classes", CLASS_HUES)
    run.check("the view shows the three classes' colours", all(n > 50 for n in counts.values()), str(counts))
    view = Gui.ActiveDocument.ActiveView
    width, height = view.getSize()
    picked = {info.get("Component") for x in range(0, width, 20) for y in range(0, height, 20)
              for info in [view.getObjectInfo((x, y))] if info and info.get("Object") == obj.Name}
    faces = {"Face%d" % (i + 1) for i in range(len(obj.Shape.Faces))}
    run.notes["faces picked in the slot's volume"] = sorted(picked)
    run.check("a click picks a face of the volume (not a triangle's number)", picked and picked <= faces,
              "%s of %s" % (sorted(picked), sorted(faces)))


@run.step
def panel_strategy_sub_volumes_and_cancel(run):
    obj = state["slot"]
    Gui.ActiveDocument.setEdit(obj.Name)
    run.wait_until(lambda: run.task_dialog_open() and panel() is not None, 20.0, "the Roughing volume panel open")
    p = panel()
    run.check_fits_combo_view("Roughing volume panel", p.form)
    run.check_read_apart("Roughing volume panel's part and stock", [p.part, p.stock])
    run.check("panel shows the volume", "15360 mm³" in p.summary.text(), p.summary.text())
    run.check("legend of the classes", p.legend.labels == ["crossable", "facing crossable", "not crossable"],
              str(p.legend.labels))
    run.screenshot("roughing_panel_classes")
    p.strategy.setCurrentIndex(1)  # S1
    run.check("computed S1", p.compute(), p.message.text())
    run.check("4 sub-volumes", obj.SubVolumeCount == 4, str(obj.SubVolumeCount))
    p.display.setCurrentText("Sub-volumes")
    run.wait_until(lambda: len(obj.Shape.Solids) == 4 and roughing_node(obj) is not None, 20.0,
                   "the sub-volumes shown")
    colours = set(drawn_colours(obj))
    run.check("slices in two alternating colours", colours == palette_of("SLICE_COLORS"), str(colours))
    run.check("legend of the slices", p.legend.labels[0].startswith("even"), str(p.legend.labels))
    run.notes["slot S1 panel summary"] = p.summary.text()
    run.screenshot("roughing_slot_sub_volumes")
    counts = hue_counts("view3d_slot_sub_volumes", SLICE_HUES)
    run.check("the view shows both slice colours", all(n > 50 for n in counts.values()), str(counts))
    p.reject()
    run.wait_until(lambda: not run.task_dialog_open() and panel() is None and roughing_node(obj) is not None, 20.0,
                   "the panel closed")
    run.check("Cancel restored the object", obj.Strategy.startswith("None") and obj.SubVolumeCount == 0
              and obj.Display == "Face classes" and len(obj.Shape.Solids) == 1,
              "%s %d %s" % (obj.Strategy, obj.SubVolumeCount, obj.Display))
    run.check("and its colours", set(drawn_colours(obj)) == palette_of("FACE_CLASS_COLORS"))


@run.step
def bad_input_in_the_panel_and_ok(run):
    obj = state["slot"]
    Gui.ActiveDocument.setEdit(obj.Name)
    run.wait_until(lambda: run.task_dialog_open() and panel() is not None, 20.0, "the panel reopened")
    p = panel()
    p.strategy.setCurrentIndex(2)  # S2: the slot has no cylindrical crossable face
    run.check("S2 refused", not p.compute())
    run.check("the message names the strategy and the fix", "S2 needs a cylindrical" in p.message.text()
              and "use S1, S3, S4 or S5" in p.message.text(), p.message.text())
    run.check("the object stays valid", obj.isValid(), str(obj.State))
    run.check("the volume stays in the view, its faces by class", len(obj.Shape.Solids) == 1 and obj.RegionCount == 1
              and set(drawn_colours(obj)) == palette_of("FACE_CLASS_COLORS"), "%d solids" % len(obj.Shape.Solids))
    run.check("one line in the Report view", run.wait_until(
        lambda: "RoughingVolume: S2 needs a cylindrical" in run.report_view_text(), 5.0, "the Report view's line"))
    run.check("no traceback in the Report view", "Traceback" not in run.report_view_text())
    run.notes["bad input message"] = p.message.text()
    run.screenshot("roughing_panel_bad_input")
    p.strategy.setCurrentIndex(5)  # S5
    p.display.setCurrentText("Sub-volumes")
    p.accept()
    run.wait_until(lambda: not run.task_dialog_open() and obj.SubVolumeCount == 4, 30.0, "OK computed S5")
    run.check("OK kept S5", obj.Strategy.startswith("S5") and obj.Proxy.error is None, obj.Strategy)


@run.step
def impeller_cancel_keeps_the_previous_result(run):
    from PySide import QtCore

    document = FreeCAD.ActiveDocument
    Gui.runCommand("HSM_Impeller")
    run.wait_until(lambda: run.shape_built(document.getObject("Impeller"))
                   and run.shape_built(document.getObject("ImpellerStock")), 60.0, "the impeller built")
    wheel, blank = document.getObject("Impeller"), document.getObject("ImpellerStock")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(wheel)
    Gui.Selection.addSelection(blank)
    Gui.runCommand("HSM_RoughingVolume")

    def computed():
        obj = document.getObject("RoughingVolume001")
        return run.valid(obj) and obj.RegionCount == 7 and roughing_node(obj) is not None

    run.wait_until(computed, 90.0, "the impeller's roughing volume computed")
    obj = document.getObject("RoughingVolume001")
    state["impeller"] = obj
    run.check("7 channels of 3/1/2 surfaces", list(obj.FaceClassCounts) ==
              ["crossable 3, facing_crossable 1, not_crossable 2"] * 7, str(list(obj.FaceClassCounts)))
    show_only(wheel, obj)
    Gui.Selection.clearSelection()
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("roughing_impeller_classes")
    counts = hue_counts("view3d_impeller_classes", CLASS_HUES)
    run.check("the impeller's view shows the three classes", all(n > 50 for n in counts.values()), str(counts))

    seen = {}
    volume = obj.Volume
    obj.Region = 0  # all seven channels, S3: seconds each
    obj.Strategy = [s for s in obj.getEnumerationsOfProperty("Strategy") if s.startswith("S3")][0]
    QtCore.QTimer.singleShot(1500, lambda: run.press_escape_on_progress(seen, "roughing_progress_dialog"))
    document.recompute()
    run.wait_until(lambda: "dialogs" in seen, 10.0, "the timer that presses Esc")
    run.wait_until(lambda: "touched" in [s.lower() for s in obj.State], 5.0, "the cancelled object left to recompute")
    run.notes["escape"] = {"dialogs": seen.get("dialogs"), "state": obj.State}
    run.check("a progress dialog shows", bool(seen.get("dialogs")), str(seen))
    run.check("Esc cancels, the previous result stays", obj.Proxy.cancelled and obj.isValid() and obj.Volume == volume
              and obj.SubVolumeCount == 0 and roughing_node(obj) is not None, "%s %s" % (obj.State, obj.SubVolumeCount))
    run.check("one line says so", run.wait_until(
        lambda: "cancelled: the previous result is kept" in run.report_view_text(), 5.0, "the Report view's line"))
    obj.Region = 1
    obj.Strategy = [s for s in obj.getEnumerationsOfProperty("Strategy") if s.startswith("S5")][0]
    obj.Display = "Sub-volumes"
    document.recompute()
    run.wait_until(lambda: run.valid(obj) and obj.SubVolumeCount >= 2 and not obj.Proxy.cancelled, 60.0,
                   "S5 of the largest channel computed")
    run.check("S5 sub-volumes add up to the channel", abs(sum(obj.SubVolumes) - obj.RegionVolumes[0])
              <= 1e-6 * obj.RegionVolumes[0], "%s %s" % (sum(obj.SubVolumes), obj.RegionVolumes[0]))
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("roughing_impeller_s5")


@run.step
def one_selected_part_opens_the_panel_and_cancel_removes_it(run):
    document = FreeCAD.ActiveDocument
    wheel, blank = document.getObject("Impeller"), document.getObject("ImpellerStock")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(wheel)
    Gui.runCommand("HSM_RoughingVolume")
    run.wait_until(lambda: run.task_dialog_open() and panel() is not None, 20.0, "the panel of a new roughing volume")
    p = panel()
    name = p.obj.Name
    run.check("the selected part and its stock in the panel", (p.selected_part(), p.selected_stock()) == (wheel, blank),
              "%s %s" % (p.part.currentText(), p.stock.currentText()))
    run.check("nothing computed before Compute", p.obj.VolumeShape.isNull() and "No result yet" in p.summary.text(),
              p.summary.text())
    run.screenshot("roughing_panel_new")
    p.reject()
    run.wait_until(lambda: not run.task_dialog_open() and panel() is None, 20.0, "the panel closed")
    run.check("Cancel removed the new object", document.getObject(name) is None)


@run.step
def colours_after_saving_and_reopening(run):
    document = FreeCAD.ActiveDocument
    path = os.path.join(tempfile.mkdtemp(prefix="hsm-gui-"), "roughing.FCStd")
    document.saveAs(path)
    names = {key: state[key].Name for key in ("slot", "impeller")}
    expected = {key: (drawn_colours(state[key]), list(state[key].ViewObject.DiffuseColor)) for key in names}
    FreeCAD.closeDocument(document.Name)
    document = FreeCAD.openDocument(path)
    run.wait_until(lambda: all(roughing_node(document.getObject(name)) is not None for name in names.values()), 30.0,
                   "the reopened roughing volumes drawn")
    for key, name in names.items():
        obj = document.getObject(name)
        drawn, diffuse = drawn_colours(obj), list(obj.ViewObject.DiffuseColor)
        run.check("%s: drawn in the colours of before saving, face by face" % key, drawn == expected[key][0],
                  "%s vs %s" % (drawn and drawn[:4], expected[key][0][:4]))
        run.check("%s: FreeCAD's face colours as before (within the file's 8 bits)" % key,
                  len(diffuse) == len(expected[key][1]) and np.allclose(diffuse, expected[key][1], atol=1.0 / 255),
                  "%s vs %s" % (diffuse[:2], expected[key][1][:2]))
        run.check("%s: not recomputed (nothing touched)" % key, "Touched" not in obj.State, str(obj.State))
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("roughing_reopened")


@run.step
def a_jobs_stock_is_offered_first(run):
    from hsmplanner.app.compat import create_job

    document = FreeCAD.ActiveDocument  # the reopened one (a Job reopened prints FreeCAD 0.20's "setAttr failed")
    part, stock, slot = (document.getObject(name) for name in ("SlantedSlotBlock", "SlantedSlotBlockStock",
                                                               "RoughingVolume"))
    job = create_job([part])
    document.recompute()
    run.wait_until(lambda: job.Stock is not None and run.shape_built(job.Stock), 30.0, "the Job and its stock")
    job.ViewObject.Visibility = False
    Gui.ActiveDocument.setEdit(slot.Name)
    run.wait_until(lambda: run.task_dialog_open() and panel() is not None, 20.0, "the panel reopened")
    p = panel()
    run.check("the Job's stock first in the Stock list", p.stock_objects[:1] == [job.Stock]
              and job.Label in p.stock.itemText(1), "%s" % [p.stock.itemText(i) for i in range(p.stock.count())])
    run.check("the stock chosen is kept", p.selected_stock() == stock, p.stock.currentText())
    p.reject()
    run.wait_until(lambda: not run.task_dialog_open() and panel() is None, 20.0, "the panel closed")


@run.step
def volume_roughing_operation_in_the_job(run):
    """The Volume roughing command in the Job of the last step: its panel takes the Roughing volume (S3 on the
    slot) and the trunnion machine; OK computes a tilted path clear of the part."""
    from PySide import QtWidgets

    from hsmplanner.app.roughing import operation as roughing_op

    document = FreeCAD.ActiveDocument
    job = next(o for o in document.Objects if hasattr(o, "Operations"))
    slot = document.getObject("RoughingVolume")
    slot.Strategy = [s for s in slot.getEnumerationsOfProperty("Strategy") if s.startswith("S3")][0]
    document.recompute()
    roughing_op.torus_controller(job)
    document.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(job)
    Gui.runCommand("HSM_VolumeRoughing")
    run.wait_until(run.task_dialog_open, 20.0, "the Volume roughing panel")
    op = next(o for o in document.Objects if hasattr(o, "Proxy") and type(o.Proxy).__name__ == "ObjectVolumeRoughing")
    forms = [w for w in QtWidgets.QApplication.allWidgets() if hasattr(w, "volume") and hasattr(w, "machine")]
    run.check("the panel lists the Roughing volume", bool(forms) and forms[0].volume.findText(slot.Label) >= 0,
              str([forms[0].volume.itemText(i) for i in range(forms[0].volume.count())] if forms else "no form"))
    if forms:
        forms[0].volume.setCurrentText(slot.Label)
        forms[0].machine.setCurrentText(roughing_op.DEFAULT_MACHINE)
        run.check_fits_combo_view("Volume roughing panel", forms[0])
        run.check_read_apart("Volume roughing panel's tool, volume and machine",
                             [forms[0].toolController, forms[0].volume, forms[0].machine])
    run.screenshot("volume_roughing_panel")
    Gui.Control.closeDialog()  # as Cancel: the operation stays, its Volume set from here
    run.wait_until(lambda: not run.task_dialog_open(), 20.0, "the panel closed")
    op.Volume = slot
    document.recompute()
    run.wait_until(lambda: run.valid(op) and op.Passes > 0, 60.0, "the operation computed")
    run.notes["volume roughing"] = {"passes": op.Passes, "cutting mm": op.CuttingLength.Value,
                                    "closest mm": op.ClosestApproach.Value}
    run.check("a path with passes, clear of the part", op.Passes > 0 and op.ClosestApproach.Value >= 0.48,
              str(run.notes["volume roughing"]))
    run.check("its moves tilt A", any(abs(c.Parameters.get("A", 0.0)) > 1.0 for c in op.Path.Commands))
    ticks = getattr(op.ViewObject.Proxy, "ticks", None)
    lines = ticks.getChild(ticks.getNumChildren() - 1) if ticks is not None else None
    count = lines.numVertices.getNum() if lines is not None else 0
    run.notes["volume roughing"]["tool-axis ticks"] = count
    run.check("the 3D view draws a tick of the tool axis every 5 mm of feed", count > op.CuttingLength.Value / 5.0,
              "%d ticks for %.0f mm of cutting" % (count, op.CuttingLength.Value))
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("volume_roughing_path")



def check_study_maps(study):
    """The panel's stock maps: readable at the panel's width, each on its own scale (a strategy that leaves
    little is not one dark colour beside one that leaves much), with a colour bar with numbers each."""
    run.process_events(0.5)  # the canvas takes the height of the stacked maps over a few events
    figure = study.plots.figure
    run.panel_plots("roughing_study_maps", figure)
    maps = [a for a in figure.axes if a.name == "3d"]
    bars = [a for a in figure.axes if a.name != "3d"]
    numbers = [[t.get_text() for t in bar.get_yticklabels() if t.get_text()] for bar in bars]
    spread = [float(np.ptp(a.collections[0].get_facecolors()[:, :3], axis=0).max()) for a in maps]
    run.notes["roughing study"]["maps"] = {"colour spread": [round(x, 2) for x in spread], "bar numbers": numbers}
    run.check("a map per strategy, each with its colour bar", len(maps) == len(study.results) == len(bars),
              "%d maps, %d bars" % (len(maps), len(bars)))
    run.check("each colour bar has numbers", all(len(n) >= 2 for n in numbers), str(numbers))
    run.check("each map's colours span its scale", all(x > 0.5 for x in spread), str(spread))


def legend_texts(node):
    """The strings of the SoText2 nodes under a scene node."""
    texts = [text.string.getValues() for text in scene_nodes(node, "SoText2")]
    return [t if isinstance(t, str) else t.getString() for values in texts for t in values]


def check_stock_map_legend(legend, thickness):
    """The 3D view's legend of the stock map: numbers in mm up to the map's scale, and, in the view as saved,
    a colour bar in the map's colours with white numbers beside it (not an empty dark box)."""
    from hsmplanner.gui.feedmap import LEGEND_X
    from hsmplanner.gui.stock_map_view import LEGEND_SPAN, thickness_colors

    labels = legend_texts(legend)
    numbers = [float(t.split()[0]) for t in labels if t.endswith(" mm")]
    top = float(np.percentile(thickness, 99))
    run.notes["roughing study"]["3D legend"] = labels
    run.check("the 3D legend numbers the scale up to the map's top", len(numbers) >= 3 and numbers == sorted(numbers)
              and abs(numbers[-1] - top) <= 0.05 + 0.01 * top, "%s, top %.2f mm" % (labels, top))
    path = os.path.join(OUT, "view3d_stock_map.png")
    Gui.ActiveDocument.ActiveView.saveImage(path, 900, 700, "White")
    run.screenshots.append(path)
    pixels = image_pixels(path)[:, :, [2, 1, 0]].astype(float) / 255.0
    # the legend's place in the view's [-1, 1] square: the bar over LEGEND_X, the numbers left-aligned right of it
    (x0, x1), (y0, y1) = LEGEND_X, LEGEND_SPAN
    column_of, row_of = (lambda x: int(round((x + 1.0) / 2.0 * 900))), (lambda y: int(round((1.0 - y) / 2.0 * 700)))
    column = pixels[row_of(y1) + 3:row_of(y0) - 3, column_of(0.5 * (x0 + x1))]
    ends = thickness_colors([0.025, 0.975])
    numbers_area = pixels[row_of(y1 + 0.03):row_of(y0 - 0.03), column_of(x1 + 0.01):column_of(x1 + 0.09)]
    white = int(np.sum(numbers_area.min(axis=2) > 0.85))
    run.notes["roughing study"]["3D legend pixels"] = {"bar ends": [column[-1].round(2).tolist(),
                                                                    column[0].round(2).tolist()], "white": white}
    run.check("the 3D legend draws its colour bar, dark at the bottom, light at the top",
              np.abs(column[-1] - ends[0]).max() < 0.15 and np.abs(column[0] - ends[1]).max() < 0.15,
              str(run.notes["roughing study"]["3D legend pixels"]))
    run.check("the 3D legend draws its numbers", white > 30, "%d white pixels" % white)


@run.step
def roughing_study_panel_runs_and_applies(run):
    """The Roughing study command on the slot's Roughing volume: S1 and S3 at 1 mm (quick), the table's rows
    with their figures, the stock maps drawn, Apply S3 adds a Volume roughing operation that computes."""
    from hsmplanner.gui import roughing_study_panel

    document = FreeCAD.ActiveDocument
    slot = document.getObject("RoughingVolume")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(slot)
    Gui.runCommand("HSM_RoughingStudy")
    run.wait_until(run.task_dialog_open, 20.0, "the Roughing study panel")
    study = roughing_study_panel.RoughingStudyPanel.active
    run.check("the panel opens on the selected Roughing volume", study is not None and study.volume() == slot)
    if study is None:
        return
    for name, box in study.form.strategies.items():
        box.setChecked(name in ("S1", "S3"))
    for key, box in study.form.variants.items():
        box.setChecked(key == "step-up")
    study.form.resolution.setValue(1.0)
    study.run()
    table = study.form.table

    def shown_rows():
        """{label shown: (table row, V_r shown, feed shown)} as the user reads them."""
        return {table.item(r, 0).text(): (r, float(table.item(r, 1).data(0)), float(table.item(r, 3).data(0)))
                for r in range(table.rowCount())}

    rows = shown_rows()
    run.check("the table opens in the study's order (the first column ascending)",
              [table.item(r, 0).text() for r in range(table.rowCount())] == ["S1+su", "S3+su"],
              str(list(rows)))
    vr = {name: shown[1] for name, shown in rows.items()}
    run.notes["roughing study"] = {"rows": list(rows), "V_r %": vr, "status": study.form.status.text()}
    run.check("the table has S1 and S3 with step-up and their V_r", sorted(rows) == ["S1+su", "S3+su"] and
              all(0 < v < 100 for v in vr.values()),
              str(run.notes["roughing study"]))
    run.check("S3 along the slot leaves less than Z-level S1", vr.get("S3+su", 100) < vr.get("S1+su", 0), str(vr))
    measured = {r.row["strategy"] + "+su": (r.row["vr"], r.row["feed_mm"]) for r in study.results}
    for column, order in ((1, QtCore.Qt.AscendingOrder), (1, QtCore.Qt.DescendingOrder), (3, QtCore.Qt.AscendingOrder)):
        table.sortItems(column, order)
        shown = shown_rows()
        run.check("sorted by column %d: each label keeps its own figures" % column,
                  all(abs(shown[n][1] - measured[n][0]) < 1e-9 and abs(shown[n][2] - measured[n][1]) < 1e-9
                      for n in measured), "%s against %s" % (shown, measured))
    run.check("the stock maps are drawn", study.plots.window_button.isEnabled())
    run.check_fits_combo_view("Roughing study panel", study.form)
    run.check_table_reads("Roughing study table", table, roughing_study_panel.KEY_COLUMNS)
    check_study_maps(study)
    run.screenshot("roughing_study_panel")
    table.selectRow(shown_rows()["S3+su"][0])
    run.check("the row labelled S3 is the one selected", study.selected() == "S3|step-up", str(study.selected()))
    node = getattr(study, "map_node", None)
    cloud = node.getChild(3) if node is not None else None
    count = cloud.vertexProperty.getValue().vertex.getNum() if cloud is not None else 0
    run.notes["roughing study"]["map points"] = count
    run.check("the selected strategy's stock map is drawn on the part", count > 100, "%d points" % count)
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("roughing_study_stock_map")
    if node is not None:
        check_stock_map_legend(node.getChild(node.getNumChildren() - 1), study.result_of("S3|step-up").stock_map[2])
    op = study.apply()
    status = study.form.status.text()
    run.notes["roughing study"]["applied"] = status
    run.check("Apply says S3 and sets S3 on every region", op is not None and status.startswith("S3 step-up applied")
              and slot.Strategy.startswith("S3") and slot.Region == 0, status)
    if op is not None:
        run.wait_until(lambda: run.valid(op) and op.Passes > 0, 60.0, "the applied operation computed")
        run.check("the applied operation has passes on the regions the row measured",
                  op.Passes > 0 and op.RegionsSwept == study.result_of("S3|step-up").row["regions"], status)
    study.reject()
    run.wait_until(lambda: not run.task_dialog_open(), 20.0, "the panel closed")


run.start()
