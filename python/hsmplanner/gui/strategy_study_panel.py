"""The Strategy study panel: finishing variants of a bottom face between two boundaries — planes at
angles, guide nets of K × P with the median or not, the 4-step method, at feeds on a machine — run on worker
processes (progress, Cancel), their table, time against slowdowns with the Pareto front, the feed maps of the
chosen rows side by side and in the 3D view, and the chosen one applied as a finishing operation in the Job.
hsmplanner.study runs the variants and hsmplanner.app.strategy_study reads the inputs and makes the operation;
this module only shows them."""
import os
import shutil
import tempfile

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtWidgets

from hsmplanner import feedsim, study
from hsmplanner.app import strategy_study
from hsmplanner.app.roughing import volume as roughing_object
from hsmplanner.app.feedrate_object import COLOR_MODES
from hsmplanner.app.progress import freecad_progress

from .task_panel import (PanelPlots, TaskPanel, freecad_message, narrow_combo, narrow_form_layout,
                         with_controller_selected)

# The table's columns: (heading, row key, (scale to the shown unit, decimals) or None for text, tool tip). The
# two figures the ranking plots come first after the variant: the Combo View shows three columns at a time.
TABLE = [("variant", "name", None, "strategy and feed (mm/min) of the variant; its machine in the tip"),
         ("time s", "time_s", (1.0, 1), "machining time simulated on the machine (jerk, acceleration, look-ahead)"),
         ("slow %", "slowdown_share", (100.0, 1), "share of the cutting time in blocks below half the programmed "
                                                  "feed"),
         ("L/F s", "length_over_feed_s", (1.0, 1), "path length / programmed feed: what CAM systems estimate"),
         ("path mm", "path_mm", (1.0, 0), "length of the path"),
         ("blocks", "blocks", (1.0, 0), "motion blocks of the program"),
         ("entries", "entries", (1.0, 0), "tool entries into the material"),
         ("short", "short_passes", (1.0, 0), "passes shorter than 20 mm (each one slows the machine)"),
         ("error", "error", None, "why the variant did not run (cancelled: the study was stopped before it)")]
TIME_COLUMN = 1
NAME_COLUMN_PX = 120  # the variant's name wraps to two lines: the figures stay in view beside it
MAP_HEIGHT_PX = 110  # a map of the panel: the width of the Combo View at the part's aspect, and its title
MAX_MAPS = 4  # feed maps side by side: each is a path regenerated and simulated again (seconds)
COLOR_BY = COLOR_MODES[0]  # the 3D map in % of the feed: the same scale as the panel's maps


def display_name(row):
    """The variant's name without its machine (the same on every row: the panel runs on one)."""
    return row["name"].rsplit(" ", 1)[0]


def selected_elements():
    """[(object, ['Face4', 'Edge13', …]), …] of the selection, in the order it was made."""
    return [(s.Object, list(s.SubElementNames)) for s in FreeCADGui.Selection.getSelectionEx()]


def has_part(document):
    return document is not None and any(roughing_object.has_solid(o) for o in document.Objects)


def spin(value, limits, decimals=2, suffix=" mm", tip=""):
    box = QtWidgets.QDoubleSpinBox()
    box.setRange(*limits)
    box.setDecimals(decimals)
    box.setValue(value)
    box.setSuffix(suffix)
    box.setToolTip(tip)
    return box


def line(text, tip):
    field = QtWidgets.QLineEdit(text)
    field.setToolTip(tip)
    return field


def draw_stacked_maps(figure, maps):
    """The feed maps [(row, blocks), …] one above the other at the Combo View's width: the titles on two lines,
    one colour bar across under them (a bar at the side would leave the maps half the width)."""
    from hsmplanner.plots.feedrate import draw_feed_map, feed_share_bar

    axes_list = [figure.add_subplot(len(maps), 1, k + 1) for k in range(len(maps))]
    for axes, (row, blocks) in zip(axes_list, maps):
        draw_feed_map(axes, blocks, linewidth=0.8)
        axes.set_title("%s\n%.1f s, %.1f %% below F/2" % (display_name(row), row["time_s"],
                                                          100 * row["slowdown_share"]), fontsize=6)
        axes.tick_params(labelsize=6)
        axes.locator_params(nbins=4)
        axes.xaxis.label.set_fontsize(6)
        axes.yaxis.label.set_fontsize(6)
    bar = feed_share_bar(figure, axes_list, label="mean feed, % of F", orientation="horizontal", shrink=0.9,
                         aspect=25)
    bar.ax.tick_params(labelsize=6)
    bar.ax.xaxis.label.set_fontsize(6)


def worst_text(row):
    """The row's worst slowdown regions, for its tooltip: where the machine loses the most time."""
    regions = row.get("worst_slowdowns") or []
    return "".join(["\nloses most time (below F/2):"] + [
        "\n  %.2f s at X%.0f Y%.0f over %.0f mm (held by %s)" % (w["lost_s"], w["x_mm"], w["y_mm"], w["length_mm"],
                                                            w["held_by"]) for w in regions]) if regions else ""


class StrategyStudyPanel(TaskPanel):
    def __init__(self):
        self.inputs = None         # StrategyStudy's inputs: what the next run studies
        self.rows, self.ran_on = [], None  # the last run's rows, and its (inputs, shapes, finishing settings)
        self.blocks = {}           # name -> feedsim blocks of the variants mapped so far (regenerated on demand)
        self.map_node = self.map_graph = None  # the 3D feed map and the scene graph it was added to
        self.closed = False        # closed while a study ran: the run stops and says nothing
        self.running = False       # a study runs (its workers may still write to the cache)
        # the panel's runs share a cache: Run again after a Cancel reads the finished variants back
        self.cache_dir = tempfile.mkdtemp(prefix="hsm-strategy-study-")
        self.form = self._build_form()
        self.use_selection()
        self.opened()

    # --- the form ---------------------------------------------------------------------------------------
    def _build_form(self):
        form = QtWidgets.QWidget()
        form.setWindowTitle("Strategy study")
        layout = QtWidgets.QVBoxLayout(form)
        form.inputs = QtWidgets.QLabel()
        form.inputs.setWordWrap(True)
        layout.addWidget(form.inputs)
        form.use_selection = QtWidgets.QPushButton("Use the selection")
        form.use_selection.setToolTip(strategy_study.WHAT_TO_SELECT)
        form.use_selection.clicked.connect(self.use_selection)
        layout.addWidget(form.use_selection)
        layout.addLayout(self._grid_fields(form))
        layout.addLayout(self._finishing_fields(form))
        form.run = QtWidgets.QPushButton("Run the study")
        form.run.setToolTip("generate, simulate and score every variant (Cancel or Esc stops: the finished ones "
                            "are kept, and read back when you run again)")
        form.run.clicked.connect(self.run)
        layout.addWidget(form.run)
        form.message = QtWidgets.QLabel()  # what is wrong with the input: where the eye lands after Run
        form.message.setWordWrap(True)
        form.message.setStyleSheet("color: #b22222")
        layout.addWidget(form.message)
        form.status = QtWidgets.QLabel()
        form.status.setWordWrap(True)
        layout.addWidget(form.status)
        layout.addWidget(self._table(form))
        form.apply = QtWidgets.QPushButton("Apply the selected variant")
        form.apply.setToolTip("add its finishing operation to the Job (a guide variant also gets its Guide curve "
                              "net), with a ball end of the study's diameter at the variant's feed")
        form.apply.setEnabled(False)
        form.apply.clicked.connect(self.apply)
        layout.addWidget(form.apply)
        self.form = form
        self.ranking = PanelPlots(layout, 260, self.draw_ranking, "Strategy study: time and slowdowns",
                                  "simulated time against the share of time below half the feed; the Pareto "
                                  "front in red, the selected rows ringed")
        self.maps = PanelPlots(layout, MAP_HEIGHT_PX + 70, self.draw_maps,
                               "Strategy study: feed maps of the selected variants",
                               "the selected variants' paths from above, each block in the colour of its mean "
                               "reached feed (select up to %d rows)" % MAX_MAPS)
        return form

    def _grid_fields(self, form):
        fields = narrow_form_layout()
        help_text = "; " + study.RANGE_HELP
        form.planes = line("0:180:45", "angles of the parallel planes from X, degrees" + help_text)
        form.k = line("0.25,0.5,0.75", "K of the guide nets, inside ]0, 1[ (empty: no guide nets)" + help_text)
        form.p = line("10", "P of the guide nets: the largest step of their planes, mm" + help_text)
        form.median = narrow_combo(strategy_study.MEDIAN_CHOICES)
        form.median.setToolTip("guide nets from boundary 1 to boundary 2, from the boundaries to the median, or both")
        form.four_step = QtWidgets.QCheckBox("the paper's 4-step method")
        form.feeds = line("4000", "programmed feeds, mm/min" + help_text)
        form.machine = narrow_combo(feedsim.machine_names(), feedsim.DEFAULT_MACHINE)
        form.machine.setToolTip("the machine model every variant is simulated on")
        for label, widget in (("Plane angles °", form.planes), ("K", form.k), ("P mm", form.p),
                              ("Median", form.median), ("", form.four_step), ("Feeds mm/min", form.feeds),
                              ("Machine", form.machine)):
            fields.addRow(label, widget)
        return fields

    def _finishing_fields(self, form):
        fields = narrow_form_layout()
        quick = strategy_study.QUICK_FINISHING
        form.tool = spin(quick["tool_diameter"], (1.0, 50.0), 1, tip="ball end mill diameter of every variant")
        form.cusp = spin(quick["cusp_height"], (0.001, 2.0), 3, tip="largest cusp left: it sets the step over "
                         "(a coarse cusp ranks strategies as a fine one does, in a fraction of the time)")
        form.tolerance = spin(quick["tolerance"], (0.001, 1.0), 3, tip="chordal tolerance of the path's points")
        form.workers = QtWidgets.QSpinBox()
        form.workers.setRange(0, os.cpu_count() or 1)
        form.workers.setSpecialValueText("all cores")
        form.workers.setToolTip("worker processes running variants side by side (0: one per core)")
        for label, widget in (("Ball Ø", form.tool), ("Cusp", form.cusp), ("Tolerance", form.tolerance),
                              ("Workers", form.workers)):
            fields.addRow(label, widget)
        return fields

    def _table(self, form):
        table = QtWidgets.QTableWidget(0, len(TABLE))
        table.setHorizontalHeaderLabels([heading for heading, _, _, _ in TABLE])
        for column, (_, _, _, tip) in enumerate(TABLE):
            table.horizontalHeaderItem(column).setToolTip(tip)
        table.verticalHeader().setVisible(False)
        table.setWordWrap(True)
        header = table.horizontalHeader()
        for column in range(1, len(TABLE)):  # the figures' widths follow them and their sort arrow
            header.setSectionResizeMode(column, QtWidgets.QHeaderView.ResizeToContents)
        table.setSelectionBehavior(QtWidgets.QAbstractItemView.SelectRows)
        table.setSelectionMode(QtWidgets.QAbstractItemView.ExtendedSelection)  # several: maps side by side
        table.setEditTriggers(QtWidgets.QAbstractItemView.NoEditTriggers)
        table.setSortingEnabled(True)
        table.setMinimumHeight(180)
        table.itemSelectionChanged.connect(self.selection_changed)
        form.table = table
        return table

    def say(self, message):
        self.form.message.setText(message)
        self.form.message.setVisible(bool(message))

    # --- inputs and grid --------------------------------------------------------------------------------
    def use_selection(self):
        """The face and boundaries (or Guide curve net) selected now become the study's inputs."""
        try:
            self.inputs = strategy_study.inputs_from_selection(selected_elements())
            self.inputs.document()
        except ValueError as error:
            if self.inputs is None:
                self.form.inputs.setText(str(error))
                return
            try:
                self.say("%s: kept %s" % (error, self.inputs.describe()))  # a bad pick keeps the inputs there were
            except ValueError as gone:  # and those were deleted meanwhile
                self.inputs = None
                self.form.inputs.setText("%s. %s" % (error, gone))
            return
        self.form.inputs.setText("Studied: %s" % self.inputs.describe())
        self.say("")

    def grid(self):
        f = self.form
        return strategy_study.study_grid(planes=f.planes.text(), k=f.k.text(), p=f.p.text(),
                                         median=f.median.currentText(), four_step=f.four_step.isChecked(),
                                         feeds=f.feeds.text(), machine=f.machine.currentText())

    def finishing_settings(self):
        return dict(tool_diameter=self.form.tool.value(), cusp_height=self.form.cusp.value(),
                    tolerance=self.form.tolerance.value())

    # --- the run ----------------------------------------------------------------------------------------
    def run(self):
        """Every variant of the grid on worker processes; Cancel (or Esc) in the progress dialog stops the study
        after the variants running finish: the finished rows are kept. A bad range is said in the panel."""
        try:
            if self.inputs is None:
                raise ValueError(strategy_study.WHAT_TO_SELECT)
            grid, settings, shapes = self.grid(), self.finishing_settings(), self.inputs.shapes()
        except ValueError as error:
            self.say(str(error))
            return None
        self.say("")
        workers = self.form.workers.value()
        self.form.status.setText("Running %d variants on %s…" % (len(grid), "%d workers" % workers if workers
                                                                   else "all cores"))
        QtWidgets.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        self.running = True
        try:
            with freecad_progress("Strategy study: %d variants" % len(grid)) as progress:
                on_row, idle = self.progress_of(progress, len(grid))
                rows = study.study(*shapes, grid, workers=workers, cache_dir=self.cache_dir, finishing=settings,
                                   progress=on_row, idle=idle)
        except ValueError as error:  # a setting refused before any variant ran (a cusp above the ball's radius)
            if not self.closed:
                self.say(str(error))
            return None
        except Exception as error:  # a failure of the run itself (each variant's own is in its row)
            if not self.closed:
                self.say("The study failed: %s: %s" % (type(error).__name__, error))
            return None
        finally:
            self.running = False
            QtWidgets.QApplication.restoreOverrideCursor()
            if self.closed:  # closed while the study ran: its cache goes now that no worker writes to it
                shutil.rmtree(self.cache_dir, ignore_errors=True)
        if self.closed:  # nothing left to show the rows in
            return None
        self.rows, self.ran_on, self.blocks = rows, (self.inputs, shapes, settings), {}
        self.form.status.setText(self.summary(rows))
        self.fill_table()
        self.ranking.redraw()
        self.maps.redraw()
        return rows

    def progress_of(self, progress, count):
        """study's progress(done, row) and idle() on the progress dialog: the dialog's Cancel makes them return
        False; idle keeps the GUI drawn and the dialog shown while the first variants run in the workers."""
        finished = []

        def on_row(done, row):
            if self.closed:
                return False
            finished.append(row["name"])
            self.form.status.setText("%d of %d variants done: %s" % (len(finished), count, display_name(row)))
            return progress(done) if progress else True

        def idle():
            if self.closed:
                return False
            return progress(len(finished) / count) if progress else True

        return on_row, idle

    @staticmethod
    def summary(rows):
        ran = [r for r in rows if not r.get("error")]
        cancelled = sum(r.get("error") == "cancelled" for r in rows)
        failed = len(rows) - len(ran) - cancelled
        text = "%d of %d variants ran" % (len(ran), len(rows))
        if ran:
            best = study.rank(rows, "time")[0]
            text += "; fastest: %s, %.1f s" % (display_name(best), best["time_s"])
        if cancelled:
            text += "; %d cancelled (Run again reads the finished ones back)" % cancelled
        if failed:
            text += "; %d failed (see the error column)" % failed
        return text + "."

    # --- the table --------------------------------------------------------------------------------------
    def fill_table(self):
        table = self.form.table
        table.setSortingEnabled(False)
        table.clearSelection()
        table.setRowCount(len(self.rows))
        for index, row in enumerate(self.rows):
            for column, (_, key, scale, _) in enumerate(TABLE):
                table.setItem(index, column, self.cell(row, key, scale, index if column == 0 else None))
        table.setColumnWidth(0, min(table.sizeHintForColumn(0), NAME_COLUMN_PX))
        table.resizeRowsToContents()
        table.setSortingEnabled(True)
        table.sortByColumn(TIME_COLUMN, QtCore.Qt.AscendingOrder)  # the fastest first (Qt's default: the name, descending)

    @staticmethod
    def cell(row, key, shown_as, index):
        item = QtWidgets.QTableWidgetItem()
        value = row.get(key, "")
        if shown_as is not None and not row.get("error"):
            scale, decimals = shown_as
            number = round(float(value) * scale, decimals)
            item.setData(QtCore.Qt.DisplayRole, number if decimals else int(number))  # sorts as a number
        elif key == "name":
            item.setText(display_name(row))
        elif shown_as is None:
            item.setText(str(value))
        if index is not None:
            item.setData(QtCore.Qt.UserRole, index)  # the row of self.rows, whatever the sorting
            item.setToolTip(row["name"] + (": " + row["error"] if row.get("error") else "") + worst_text(row))
        return item

    def selected_rows(self):
        """The selected rows that ran, in the table's order."""
        table = self.form.table
        indices = sorted(i.row() for i in table.selectionModel().selectedRows()) if table.selectionModel() else []
        rows = [self.rows[table.item(i, 0).data(QtCore.Qt.UserRole)] for i in indices]
        return [r for r in rows if not r.get("error")]

    def selection_changed(self):
        rows = self.selected_rows()
        self.form.apply.setEnabled(bool(rows))
        QtWidgets.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)  # a map not seen yet takes seconds
        try:
            self.ranking.redraw()
            self.maps.canvas.setMinimumHeight(MAP_HEIGHT_PX * max(1, min(len(rows), MAX_MAPS)) + 70)
            self.maps.redraw()
            self.show_map(rows[0] if rows else None)
        finally:
            QtWidgets.QApplication.restoreOverrideCursor()

    # --- plots and the 3D map ---------------------------------------------------------------------------
    def blocks_of(self, row):
        """The row's simulated blocks: its path regenerated and simulated again (the study's workers keep only
        the scores), once per row."""
        if row["name"] not in self.blocks:
            _, (part, face, b1, b2), settings = self.ran_on
            moves, _ = study.variant_moves(row, part, face, b1, b2, settings)
            self.blocks[row["name"]] = study.simulate_variant(row, moves).blocks
        return self.blocks[row["name"]]

    def draw_ranking(self, figure, wide):
        """Time against slowdowns of the rows that ran, the Pareto front (study.rank's) ringed on its step line,
        the selected rows marked; in the panel the names of the selected only (the front's crowd it)."""
        from hsmplanner.plots.strategy_study import draw_pareto

        ran = [r for r in self.rows if not r.get("error")]
        figure.clear()
        if not ran:
            return False
        figure.set_layout_engine("constrained")  # labels kept inside whatever size the canvas is given
        axes = figure.add_subplot(1, 1, 1)
        selected = self.selected_rows()
        front = draw_pareto(axes, self.rows, [r["name"] for r in selected], label_front=wide)
        axes.scatter([r["time_s"] for r in front], [100 * r["slowdown_share"] for r in front], s=70,
                     facecolors="none", edgecolors="black", linewidths=1.0, zorder=3)
        axes.set_title("%d variants, %d on the Pareto front" % (len(ran), len(front)), fontsize=8 if wide else 7)
        if not wide:
            self.compact_ranking(axes, selected)
        return True

    @staticmethod
    def compact_ranking(axes, selected):
        """The ranking at the Combo View's width: fewer ticks, a smaller legend, the selected rows named."""
        axes.locator_params(nbins=4)
        axes.set_ylabel("time below F/2, %", fontsize=7)
        axes.set_xlabel("simulated time, s", fontsize=7)
        axes.legend(fontsize=5, loc="best")
        axes.margins(0.12)  # the rings at the edges stay inside
        low, high = axes.get_xlim()
        for row in selected[:MAX_MAPS]:
            right_half = row["time_s"] > 0.5 * (low + high)  # named on the side with room, inside the axes
            axes.annotate(study.short_name(row), (row["time_s"], 100 * row["slowdown_share"]), fontsize=5,
                          xytext=(-5 if right_half else 5, 5), textcoords="offset points",
                          ha="right" if right_half else "left", annotation_clip=True)

    def draw_maps(self, figure, wide):
        """The feed maps of the selected rows (at most MAX_MAPS): side by side in the window, stacked in the panel."""
        from hsmplanner.plots.strategy_study import draw_feed_maps

        rows = self.selected_rows()[:MAX_MAPS] if self.rows else []
        try:
            maps = [(r, self.blocks_of(r)) for r in rows]
        except (ValueError, RuntimeError) as error:  # the inputs changed or vanished since the run
            self.say("No feed map: %s" % error)
            maps = []
        figure.clear()
        if not maps:
            return False
        figure.set_layout_engine("constrained")  # room for the shared colour bar at any canvas size
        if wide:
            draw_feed_maps(figure, maps, columns=len(maps))
        else:
            draw_stacked_maps(figure, maps)
        return True

    def show_map(self, row):
        """The row's feed map on the part in the studied document's 3D view (one at a time)."""
        from .feedmap import map_node

        if self.map_node is not None:
            self.map_graph.removeChild(self.map_node)
            self.map_node = self.map_graph = None
        if row is None or row["name"] not in self.blocks or self.ran_on is None:  # drawn by the maps' plot
            return
        try:
            document = self.ran_on[0].document()
        except ValueError:
            return  # the studied document was closed: no view to draw in
        view = getattr(FreeCADGui.getDocument(document.Name), "ActiveView", None)
        graph = view.getSceneGraph() if view is not None and hasattr(view, "getSceneGraph") else None
        if graph is not None:
            self.map_node, self.map_graph = map_node(self.blocks[row["name"]], COLOR_BY), graph
            graph.addChild(self.map_node)

    # --- apply ------------------------------------------------------------------------------------------
    def apply(self):
        """The first selected row as a finishing operation in the studied document's Job, recomputed."""
        rows = self.selected_rows()
        if not rows or self.ran_on is None:
            self.say("Select a row that ran to apply it.")
            return None
        row, (inputs, _, settings) = rows[0], self.ran_on
        try:
            document = inputs.document()
        except ValueError as error:
            self.say("Not applied: %s." % error)
            return None
        jobs = roughing_object.jobs(document)
        if not jobs:
            self.say("No Job in %s: make one (Path → Job) to add the operation to." % document.Label)
            return None
        job = jobs[0]
        try:
            # first, on its own: FreeCAD's ToolBit GUI commits a transaction of its own ("Create ToolBit"),
            # which would end the one below and leave the net and the operation outside any undo step
            controller = strategy_study.study_controller(job, settings["tool_diameter"], row["feed_mm_min"])
        except Exception as error:  # noqa: BLE001 (whatever FreeCAD raises is said in the panel)
            self.say("Not applied: %s" % freecad_message(error))
            return None
        document.openTransaction("Apply strategy %s" % row["name"])
        try:
            op, net = with_controller_selected(
                controller, lambda: strategy_study.create_operation(row, inputs, job, controller, settings))
            self.attach_view_providers(op, net)
            document.recompute()
        except Exception as error:  # noqa: BLE001
            document.abortTransaction()
            self.say("Not applied: %s" % freecad_message(error))
            return None
        document.commitTransaction()
        self.say("" if op.isValid() else "%s did not compute: %s" % (op.Label, op.getStatusString()))
        self.form.status.setText("%s applied: %s in %s (%d passes)." % (display_name(row), op.Label, job.Label,
                                                                        getattr(op, "Passes", 0)))
        return op

    @staticmethod
    def attach_view_providers(op, net):
        from .finishing_ops_gui import COMMANDS
        from .view_providers import ViewProviderGuideCurveNet

        resources = COMMANDS["HSM_GuideCurveFinishing" if net is not None else "HSM_ParallelPlaneFinishing"]
        op.ViewObject.Proxy = resources.view_provider(op.ViewObject, resources.res)
        op.ViewObject.Proxy.OpIcon = resources.icon
        if net is not None:
            ViewProviderGuideCurveNet(net.ViewObject)
            net.ViewObject.Proxy.colour(net)  # the net computed before its view provider was there

    def close_edit(self):
        self.closed = True  # a study running stops at its next variant or idle call
        self.show_map(None)
        self.ranking.close()
        self.maps.close()
        if not self.running:  # else the run removes it when its workers have stopped
            shutil.rmtree(self.cache_dir, ignore_errors=True)
        super().close_edit()


class CommandStrategyStudy:
    def GetResources(self):
        from hsmplanner.resources import icon

        return {"Pixmap": icon("StrategyStudy"), "MenuText": "Strategy study",
                "ToolTip": "Run finishing strategies of a bottom face between two boundaries — parallel planes at "
                           "angles, guide curves of K × P, the 4-step method — at feeds on a machine model: their "
                           "simulated time, slowdowns and Pareto front, their feed maps; apply the chosen one. "
                           "Select the face and its two boundary edges (or a Guide curve net) first"}

    def IsActive(self):
        return has_part(FreeCAD.ActiveDocument)

    def Activated(self):
        if FreeCADGui.Control.activeDialog():  # a panel is open (this one, or another's): FreeCAD shows one
            FreeCAD.Console.PrintWarning("Strategy study: close the open task panel first\n")
            return None
        panel = StrategyStudyPanel()
        FreeCADGui.Control.showDialog(panel)
        return panel
