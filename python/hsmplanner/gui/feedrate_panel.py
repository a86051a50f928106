"""Task panel of a feed-rate analysis: machine, summary table, histograms, report export."""
from matplotlib.backends.backend_qtagg import FigureCanvasQTAgg
from matplotlib.figure import Figure
from PySide2 import QtCore, QtWidgets

from hsmplanner import feedsim, plots
from hsmplanner.app.feedrate_object import COLOR_MODES

from .task_panel import AnalysisPanel, narrow_combo


def summary_rows(summary):
    """(label, value) rows of the summary table; feeds and times as people read them."""
    classes = summary["feed_classes"]["share_of_time"]
    rows = [
        ("Machine", summary["machine"]),
        ("Simulated time", "%.1f s" % summary["total_time_s"]),
        ("  cutting / rapid", "%.1f s / %.1f s" % (summary["cutting_time_s"], summary["rapid_time_s"])),
        ("Length / feed estimate", "%.1f s" % summary["naive_time_s"]),
        ("Simulated / estimate", "× %.2f" % summary["time_over_naive"]),
        ("Blocks (cutting / rapid)", "%d (%d / %d)" % (summary["block_count"], summary["cutting_blocks"],
                                                       summary["rapid_blocks"])),
        ("Cutting length", "%.1f mm" % summary["cutting_length_mm"]),
    ]
    rows += [("Time at %s of F" % label, "%.1f %%" % (100 * share))
             for label, share in zip(plots.FEED_CLASS_LABELS, classes)]
    return rows


class FeedRatePanel(AnalysisPanel):
    def _build_form(self):
        form, layout, settings = self.new_form("Feed-rate analysis")
        self.machine = narrow_combo(self.obj.getEnumerationsOfProperty("Machine"), self.obj.Machine)
        settings.addRow("Machine", self.machine)
        self.color_by = narrow_combo(COLOR_MODES, self.obj.ColorBy)
        settings.addRow("Colours", self.color_by)
        self.simulate_button = QtWidgets.QPushButton("Simulate")
        layout.addWidget(self.simulate_button)
        self.message = QtWidgets.QLabel()  # errors and export results, where the eye lands after Simulate
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        self.table = QtWidgets.QTableWidget(0, 2)
        self.table.horizontalHeader().setVisible(False)
        self.table.verticalHeader().setVisible(False)
        # Values whole, labels wrapped: at the Combo View's width both columns cannot be one line wide.
        self.table.horizontalHeader().setSectionResizeMode(0, QtWidgets.QHeaderView.Stretch)
        self.table.horizontalHeader().setSectionResizeMode(1, QtWidgets.QHeaderView.ResizeToContents)
        self.table.setWordWrap(True)
        layout.addWidget(self.table)
        self.figure = Figure(figsize=(3.4, 5.2), dpi=80)
        self.canvas = FigureCanvasQTAgg(self.figure)
        self.canvas.setMinimumHeight(400)  # the two histograms stacked: they fit the Combo View's width
        layout.addWidget(self.canvas)
        self.export_button = QtWidgets.QPushButton("Export report…")
        self.export_button.setToolTip("JSON summary, per-block CSV, histogram and feed-map PNGs")
        layout.addWidget(self.export_button)
        self.simulate_button.clicked.connect(self.simulate)
        self.color_by.currentTextChanged.connect(self.recolor)
        self.export_button.clicked.connect(self.choose_export_folder)
        return form

    def simulate(self):
        self.obj.Machine = self.machine.currentText()
        self.obj.recompute()
        self.refresh()

    def recolor(self, mode):
        self.obj.ColorBy = mode
        self.obj.ViewObject.Proxy.redraw(self.obj)

    def refresh(self):
        result = self.obj.Proxy.ensure_result(self.obj) if self.obj.Report else None
        if result is None:
            error = getattr(self.obj.Proxy, "error", None)
            self.table.setRowCount(0)
            self.figure.clear()
            self.canvas.draw()
            self.message.setText("Not simulated: %s" % (error or ", ".join(self.obj.State) or "no Job or operation"))
            return
        self.message.setText("")
        summary = feedsim.summary_dict(result.summary, self.obj.Source.Label)
        rows = summary_rows(summary)
        self.table.setRowCount(len(rows))
        for i, (label, value) in enumerate(rows):
            self.table.setItem(i, 0, QtWidgets.QTableWidgetItem(label))
            self.table.setItem(i, 1, QtWidgets.QTableWidgetItem(value))
        self.table.resizeRowsToContents()
        self.fit_table_height()
        plots.draw_feed_histograms(self.figure, summary, stacked=True)
        self.canvas.draw()

    def fit_table_height(self):
        """Every row shown, no scroll bar: the summary is what people came for."""
        rows = sum(self.table.rowHeight(i) for i in range(self.table.rowCount()))
        self.table.setVerticalScrollBarPolicy(QtCore.Qt.ScrollBarAlwaysOff)
        self.table.setHorizontalScrollBarPolicy(QtCore.Qt.ScrollBarAlwaysOff)  # long values elide instead
        self.table.setFixedHeight(rows + 2 * self.table.frameWidth() + 2)

    def choose_export_folder(self):
        folder = QtWidgets.QFileDialog.getExistingDirectory(self.form, "Folder for the feed-rate report")
        if folder:
            self.export(folder)

    def export(self, folder):
        result = self.obj.Proxy.ensure_result(self.obj)
        stem = "%s_%s" % (self.obj.Source.Label, self.obj.Machine)
        paths = feedsim.write_report(result, folder, stem, self.obj.Source.Label)
        self.message.setText("written: " + ", ".join(paths))
        return paths
