"""The Roughing study panel: pick a Roughing volume, run the five strategies on it (progress, Cancel), see the
table and the stock each leaves side by side, and apply the chosen one as a Volume roughing operation in the
Job (hsmplanner.app.roughing.study does the work; this module only shows it)."""
import FreeCAD
import FreeCADGui
from PySide import QtCore, QtWidgets

import hsmplanner
from hsmplanner.app.roughing import volume as roughing_object, study as roughing_study
from hsmplanner.app.progress import freecad_progress, in_background
from hsmplanner.plots.roughing_study import short_label

from .task_panel import (PanelPlots, TaskPanel, freecad_message, narrow_combo, narrow_form_layout,
                         with_controller_selected)

STRATEGIES = ("S1", "S2", "S3", "S4", "S5")
PAPER_TORUS = "the paper's Ø8 r1 torus"  # the study's tool when the Job has none roughing can use
# The table's columns: (heading, row key, tool tip). The figures a choice rests on come first: the Combo View
# shows about three columns, the others scroll into view.
# The variants of a strategy the study runs: (check box, tip, study_strategy's keywords, what the row says).
VARIANTS = [("as the paper", "one level per slice, the paper's", dict(step_up=False), roughing_study.PAPER),
            ("step-up", "intermediate levels inside the slices where the part leans", {}, roughing_study.STEP_UP),
            ("+ rest Ø4", "step-up, then a rest roughing of what it left with a Ø4 r0.5 torus (S3 on the stock "
             "left, 4 mm step): two operations", dict(rest=roughing_study.Rest()), roughing_study.Rest().label)]
TABLE = [("strat.", "strategy", "the strategy whose figures the row holds (Apply makes it): S1 as the paper (one "
          "level per slice), S1+su with step-up levels, S1+su+r then a rest roughing with a Ø4 torus"),
         ("V_r %", "vr", "stock left, % of the volume to remove (the paper's V_r; its value in the row's tip)"),
         ("time s", "time_s", "machining time simulated on the 840D A/C trunnion (length/feed in the tip)"),
         ("feed mm", "feed_mm", "feed path length (rapids not counted)"),
         ("no allow. %", "vr_beyond_allowance", "V_r without the allowance layer left on the part on purpose"),
         ("in mat. %", "in_material", "share of the feed path that cuts a chip"),
         ("in path %", "in_material_path", "share of the whole path (rapids and links too) that cuts a chip"),
         ("stick-out", "stick_out_mm", "least stick-out, mm, for the holder to clear part and stock"),
         ("stock mean", "stock_mean_mm", "stock left on the part, area-weighted mean, mm"),
         ("stock max", "stock_max_mm", "stock left on the part, largest, mm"),
         ("held by", "held_by", "what held the speed, share of the time"),
         ("rapids fed", "rapids_fed", "approaches that would have cut stock left as rapids: they feed into it")]
KEY_COLUMNS = 3  # strategy (and variant), V_r, time: in view without scrolling
MAP_HEIGHT_PX = 190  # of one stock map stacked in the panel


def roughing_volumes(document):
    return [o for o in document.Objects if hasattr(o, "Proxy") and type(o.Proxy).__name__ == "RoughingVolume"]


def job_of(document):
    found = roughing_object.jobs(document)
    return found[0] if found else None


class RoughingStudyPanel(TaskPanel):
    def __init__(self, volume=None):
        self.results = []
        self.form = self._build_form(volume)
        self.opened()

    def _build_form(self, volume):
        form = QtWidgets.QWidget()
        form.setWindowTitle("Roughing study")
        layout = QtWidgets.QVBoxLayout(form)
        settings = narrow_form_layout()
        layout.addLayout(settings)
        document = FreeCAD.ActiveDocument
        self.volumes = roughing_volumes(document)
        form.volume = narrow_combo([v.Label for v in self.volumes], volume.Label if volume is not None else None,
                                   names=True)
        form.volume.setToolTip("the Roughing volume whose part and stock the strategies run on")
        settings.addRow("Roughing volume", form.volume)
        boxes = QtWidgets.QGridLayout()  # three a row: the Combo View is narrow
        form.strategies = {}
        for k, name in enumerate(STRATEGIES):
            box = QtWidgets.QCheckBox(name)
            box.setChecked(True)
            box.setToolTip(hsmplanner.roughing.STRATEGY_LABELS[name])
            boxes.addWidget(box, k // 3, k % 3)
            form.strategies[name] = box
        settings.addRow("Strategies", boxes)
        variants = QtWidgets.QVBoxLayout()
        form.variants = {}
        for label, tip, _, key in VARIANTS:
            box = QtWidgets.QCheckBox(label)
            box.setChecked(key != VARIANTS[2][3])  # the rest roughing doubles the time: asked for
            box.setToolTip(tip)
            variants.addWidget(box)
            form.variants[key] = box
        settings.addRow("Variants", variants)
        form.resolution = QtWidgets.QDoubleSpinBox()
        form.resolution.setRange(0.05, 5.0)
        form.resolution.setDecimals(2)
        form.resolution.setSingleStep(0.1)
        form.resolution.setValue(0.2)
        form.resolution.setSuffix(" mm")
        form.resolution.setToolTip("spacing of the material-removal model's rays: every figure is at it")
        settings.addRow("Resolution", form.resolution)
        form.run = QtWidgets.QPushButton("Run the study")
        form.run.setToolTip("sweep, join, simulate the removal and the machine for each strategy (Esc cancels)")
        form.run.clicked.connect(self.run)
        layout.addWidget(form.run)
        form.status = QtWidgets.QLabel()
        form.status.setWordWrap(True)
        layout.addWidget(form.status)
        form.table = QtWidgets.QTableWidget(0, len(TABLE))
        form.table.setHorizontalHeaderLabels([heading for heading, _, _ in TABLE])
        for column, (_, _, tip) in enumerate(TABLE):
            form.table.horizontalHeaderItem(column).setToolTip(tip)
        form.table.setSelectionBehavior(QtWidgets.QAbstractItemView.SelectRows)
        form.table.setSelectionMode(QtWidgets.QAbstractItemView.SingleSelection)
        form.table.setEditTriggers(QtWidgets.QAbstractItemView.NoEditTriggers)
        form.table.setSortingEnabled(True)
        form.table.setMinimumHeight(150)
        layout.addWidget(form.table)
        form.apply = QtWidgets.QPushButton("Apply the selected strategy")
        form.apply.setToolTip("set the Roughing volume to the selected row's strategy and add a Volume roughing "
                              "operation for it to the Job")
        form.apply.setEnabled(False)
        form.apply.clicked.connect(self.apply)
        form.table.itemSelectionChanged.connect(self.selection_changed)
        layout.addWidget(form.apply)
        self.form = form
        self.plots = PanelPlots(layout, MAP_HEIGHT_PX, self.draw, "Stock left by each strategy",
                                "the stock each strategy leaves on the part, mm (each map on its own scale)")
        return form

    def selection_changed(self):
        name = self.selected()
        self.form.apply.setEnabled(bool(name))
        self.show_map(name)

    def show_map(self, name):
        """The selected strategy's stock map on the part in the 3D view (one at a time)."""
        from .stock_map_view import stock_map_node

        view = FreeCADGui.ActiveDocument.ActiveView if FreeCADGui.ActiveDocument else None
        graph = view.getSceneGraph() if view is not None and hasattr(view, "getSceneGraph") else None
        if graph is None:
            return
        if getattr(self, "map_node", None) is not None:
            graph.removeChild(self.map_node)
            self.map_node = None
        result = self.result_of(name)
        if result is not None and result.removal is not None:
            _, points, thickness, _ = result.stock_map
            self.map_node = stock_map_node(points, thickness, title="%s: stock left on the part" % name.replace("|", " "))
            graph.addChild(self.map_node)

    def close_edit(self):
        self.show_map(None)
        self.plots.close()
        super().close_edit()

    def volume(self):
        index = self.form.volume.currentIndex()
        return self.volumes[index] if 0 <= index < len(self.volumes) else None

    def selected(self):
        rows = self.form.table.selectionModel().selectedRows() if self.form.table.selectionModel() else []
        return self.form.table.item(rows[0].row(), 0).data(QtCore.Qt.UserRole) if rows else None

    def study_tool(self, volume):
        """(Cutter or None for the paper's torus, feed mm/min, what it is): the Job's roughing tool controller,
        so that Apply makes what the row measured."""
        from hsmplanner.app.roughing import operation as roughing_op

        job = job_of(volume.Document)
        for controller in (job.Tools.Group if job is not None else []):
            if roughing_op.is_roughing_controller(controller):
                return (roughing_op.check_controller(controller), controller.HorizFeed.getValueAs("mm/min").Value,
                        controller.Label)
        return None, roughing_study.DEFAULT_FEED_MM_MIN, PAPER_TORUS

    def run(self):
        """The checked strategies one after the other; Cancel stops the one running and keeps the others."""
        volume = self.volume()
        names = [n for n in STRATEGIES if self.form.strategies[n].isChecked()]
        variants = [(keywords, key) for _, _, keywords, key in VARIANTS if self.form.variants[key].isChecked()]
        if volume is None or not names or not variants:
            self.form.status.setText("Choose a Roughing volume, at least one strategy and one variant.")
            return
        with freecad_progress("Roughing study of %s" % volume.Label) as progress:
            try:  # a reopened document computes its volume again: with the dialog open
                removal_volume, part_brep, stock_brep, _ = volume.Proxy.computed(volume, progress)
                tool, feed, tool_name = self.study_tool(volume)
            except (ValueError, RuntimeError) as error:
                self.form.status.setText("%s: %s" % (volume.Label, error))
                return
            except hsmplanner.Cancelled:
                self.form.status.setText("Cancelled while %s computed its volume." % volume.Label)
                return
            self.results, self.studied = [], (volume.Name, tool_name)
            partition = dict(step=volume.Step.Value, setup_resolution_deg=volume.SetupResolution.Value,
                             setup_grid=volume.SetupGrid.Value)
            runs = [(name, keywords, key) for name in names for keywords, key in variants]
            for k, (name, keywords, key) in enumerate(runs):
                share = (lambda done, k=k: progress((k + done) / len(runs))) if progress else None
                if progress:
                    progress.say("Roughing study of %s: %s %s (%d of %d)" % (volume.Label, name, key, k + 1, len(runs)))
                try:
                    result = in_background(roughing_study.study_strategy, name, part_brep, stock_brep, removal_volume,
                                           tool=tool, feed_mm_min=feed, resolution=self.form.resolution.value(),
                                           progress=share, partition_settings=partition, **keywords)
                except hsmplanner.Cancelled:
                    self.form.status.setText("Cancelled during %s %s: the rows before it are kept." % (name, key))
                    break
                self.results.append(result)
            else:
                count = len(removal_volume.solids)
                self.form.status.setText("%d rows at %.2f mm, %s joined, %s at F%g."
                                         % (len(self.results), self.form.resolution.value(),
                                            "1 region" if count == 1 else "all %d regions" % count, tool_name, feed))
        self.fill_table()
        self.plots.redraw()

    @staticmethod
    def key_of(row):
        return "%s|%s" % (row["strategy"], row["variant"])

    def result_of(self, key):
        return next((r for r in self.results if self.key_of(r.row) == key), None)

    def fill_table(self):
        table = self.form.table
        table.setSortingEnabled(False)
        table.setRowCount(len(self.results))
        table.verticalHeader().hide()  # a header would keep its place when the rows sort: the label is a column
        for row, result in enumerate(self.results):
            values = result.row
            note_column = next((c for c, (_, key, _) in enumerate(TABLE) if values.get(key, "") == ""), None)
            for column, (_, key, _) in enumerate(TABLE):
                item = QtWidgets.QTableWidgetItem()
                value = values.get(key, "")
                if key == "strategy":  # with its variant, short: the key columns fit the Combo View
                    value = short_label(values)
                if isinstance(value, (int, float)):
                    item.setData(QtCore.Qt.DisplayRole, value)  # sorts as a number
                else:
                    # a row without figures (failed, cancelled) says why once, in its first empty column
                    note = (values.get("note") or "")[:60] if column == note_column else ""
                    item.setText(str(value) if value != "" else note)
                item.setToolTip("paper: V_r %s %%, path %s mm, in material %s %%, stick-out %s mm; length/feed %s s"
                                % (values["paper_vr"], values["paper_path_mm"], values["paper_in_material"],
                                   values["paper_stick_out_mm"], values.get("length_over_feed_s", "")))
                if column == 0:
                    item.setData(QtCore.Qt.UserRole, self.key_of(values))
                table.setItem(row, column, item)
        table.setSortingEnabled(True)  # before sizing: the headers then leave room for the sort arrow
        table.sortByColumn(0, QtCore.Qt.AscendingOrder)  # the study's order (Qt's default is descending)
        table.resizeColumnsToContents()

    def draw(self, figure, wide):
        from hsmplanner.plots.roughing_study import draw_stock_maps

        maps = [r.stock_map for r in self.results if r.stock_map is not None]
        if not wide:  # stacked, one a row: side by side, their titles ran into each other
            self.plots.canvas.setMinimumHeight(MAP_HEIGHT_PX * max(1, len(maps)))
        return draw_stock_maps(figure, maps, columns=3 if wide else 1, own_scales=True, coordinates=wide)

    def apply(self):
        """The selected row on the Roughing volume, all its regions as the study joined them: a Volume roughing
        operation in the Job that makes them (one level per slice for the paper's variant), and for a rest row
        a second one after it — a Roughing volume of the same part and stock with the rest strategy and step,
        the rest tool's controller, RestFrom the first. The status says what it made against the row."""
        key, volume = self.selected(), self.volume()
        if key is None or volume is None:
            return None
        row = self.result_of(key).row
        name = row["strategy"]
        document = volume.Document  # the studied volume's, whichever document is active now
        job = job_of(document)
        if job is None:
            self.form.status.setText("No Job in this document: make one (CAM → Job) to add the operation to.")
            return None
        document.openTransaction("Apply roughing strategy %s %s" % (name, row["variant"]))
        try:
            op = self.add_roughing(job, volume, name, row["variant"])
            if row["variant"] not in (roughing_study.PAPER, roughing_study.STEP_UP):
                self.add_rest(job, volume, op, roughing_study.Rest())
            document.recompute()
        except Exception as error:  # noqa: BLE001 (whatever FreeCAD raises is said in the panel)
            document.abortTransaction()
            self.form.status.setText("Not applied: %s" % freecad_message(error))
            return None
        document.commitTransaction()
        self.form.status.setText(self.applied_text(key, op, job))
        return op

    @staticmethod
    def add_roughing(job, volume, name, variant):
        from hsmplanner.app.roughing import operation as roughing_op
        from hsmplanner.gui.finishing_ops_gui import add_volume_roughing

        controller = roughing_op.roughing_controller(job)  # the Job's, or the paper's torus added
        volume.Strategy = roughing_object.strategy_label(name)
        volume.Region = 0  # every region, as the row measured them
        op = with_controller_selected(controller, lambda: add_volume_roughing(job))
        op.ToolController = controller
        op.Volume = volume
        if variant == roughing_study.PAPER:
            op.StepUpMinimum = 0.0
        return op

    @staticmethod
    def add_rest(job, volume, first, rest):
        """The rest roughing after `first`: its own Roughing volume (the rest strategy and step), a controller of
        the rest tool, RestFrom `first`."""
        from hsmplanner.app.roughing import operation as roughing_op
        from hsmplanner.gui.finishing_ops_gui import add_volume_roughing
        from hsmplanner.gui.view_providers import ViewProviderRoughingVolume

        rest_volume = roughing_object.create(volume.Part, volume.Stock, document=volume.Document,
                                             name="RestVolume", recompute=False, Strategy=rest.strategy,
                                             Step=rest.step, Region=0, SetupResolution=volume.SetupResolution,
                                             SetupGrid=volume.SetupGrid)
        rest_volume.Label = "%s rest %s" % (volume.Label, rest.strategy)
        ViewProviderRoughingVolume(rest_volume.ViewObject)
        controller = roughing_op.torus_controller(job, diameter=rest.tool.diameter,
                                                  corner_radius=rest.tool.corner_radius,
                                                  feed_mm_min=roughing_study.DEFAULT_FEED_MM_MIN, number=4,
                                                  replace=False)
        op = with_controller_selected(controller, lambda: add_volume_roughing(job))
        op.ToolController = controller
        op.Volume = rest_volume
        op.RestFrom = first
        op.Label = "%s rest" % first.Label
        return op

    def applied_text(self, key, op, job):
        row = self.result_of(key).row
        name = "%s %s" % (row["strategy"], row["variant"])
        made = ("%s applied: %s in %s, %d region%s joined, %d passes, %.0f mm of cut"
                % (name, op.Label, job.Label, op.RegionsSwept, "" if op.RegionsSwept == 1 else "s", op.Passes,
                   op.CuttingLength.Value))
        if row["variant"] not in (roughing_study.PAPER, roughing_study.STEP_UP):
            made += ", then its rest roughing (RestFrom %s)" % op.Label
        if row.get("regions") and op.RegionsSwept != row["regions"]:
            made += " (the row measured %d regions)" % row["regions"]
        tool = getattr(self, "studied", (None, None))[1]
        if tool not in (None, PAPER_TORUS) and op.ToolController.Label != tool:
            made += "; tool %s, the row's %s" % (op.ToolController.Label, tool)
        return made + "."


class CommandRoughingStudy:
    def GetResources(self):
        from hsmplanner.resources import icon

        return {"Pixmap": icon("RoughingStudy"), "MenuText": "Roughing study",
                "ToolTip": "Run the five strategies of 5-axis roughing on a Roughing volume: the volume each leaves, "
                           "its path, stick-out and simulated machining time side by side; apply the chosen one"}

    def IsActive(self):
        document = FreeCAD.ActiveDocument
        return document is not None and bool(roughing_volumes(document))

    def Activated(self):
        selected = [o for o in FreeCADGui.Selection.getSelection() if o in roughing_volumes(FreeCAD.ActiveDocument)]
        panel = RoughingStudyPanel(selected[0] if selected else None)
        FreeCADGui.Control.showDialog(panel)
        return panel
