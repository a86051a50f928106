"""Task panel of a feed-rate analysis: machine, summary table, histograms, report export."""
from PySide import QtCore, QtWidgets

from hsmplanner import feedsim
from hsmplanner.plots.feedrate import FEED_CLASS_LABELS, draw_feed_histograms
from hsmplanner.app.feedrate_object import COLOR_MODES

from .task_panel import AnalysisPanel, PanelPlots, narrow_combo


def summary_rows(summary):
    """(label, value, tool tip) rows of the summary table; feeds and times as people read them. Labels are
    short (the Combo View is about 275 px wide); the tool tip says what each one is. The machine is in the
    combo box above the table."""
    s = summary
    rows = [
        ("Simulated", "%.1f s" % s.total_time, "simulated machining time (jerk, acceleration, look-ahead)"),
        ("cut / rapid", "%.1f / %.1f s" % (s.cutting_time, s.rapid_time), "simulated time in G1/G2/G3 and in G0"),
        ("Length / F", "%.1f s" % s.naive_time,
         "length / programmed feed: what CAM systems and FreeCAD's cycle time estimate"),
        ("Ratio", "× %.2f" % s.time_over_naive, "simulated time / length-over-feed estimate"),
        ("Blocks", "%d (%d G0)" % (s.block_count, s.rapid_blocks),
         "motion blocks of the program (%d cutting, %d rapid)" % (s.cutting_blocks, s.rapid_blocks)),
        ("Cut length", "%.1f mm" % s.cutting_length, "length of the cutting moves"),
    ]
    rows += [("%s F" % label, "%.1f %%" % (100 * share),
              "share of the cutting time spent at %s of the programmed feed F" % label)
             for label, share in zip(FEED_CLASS_LABELS, s.feed_classes_time)]
    shares = feedsim.speed_limit_shares(s)
    if shares:  # what held the speed: on 5 axes, which axis (C limited 18 % of the time)
        everything = ", ".join("%s %.1f %%" % item for item in ((name, 100 * share) for name, share in shares.items()))
        rows.append(("Held by", ", ".join("%s %.0f %%" % (name, 100 * share) for name, share in
                                          list(shares.items())[:2]),
                     "share of the time each limit held the speed (F: the programmed feed; X..C: that axis's "
                     "velocity or acceleration; curvature; block rate): " + everything))
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
        # Short labels whole, values in the rest (they are shorter than the Combo View's width less the labels).
        self.table.horizontalHeader().setSectionResizeMode(0, QtWidgets.QHeaderView.ResizeToContents)
        self.table.horizontalHeader().setSectionResizeMode(1, QtWidgets.QHeaderView.Stretch)
        layout.addWidget(self.table)
        self.plots = PanelPlots(layout, 440, self.draw_plots, "Feed-rate analysis: %s" % self.obj.Label)
        self.figure = self.plots.figure
        self.export_button = QtWidgets.QPushButton("Export report…")
        self.export_button.setToolTip("JSON summary, per-block CSV, histogram and feed-map PNGs (and the rotary "
                                      "axes over time on a 4- or 5-axis machine)")
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

    def result(self):
        return self.obj.Proxy.ensure_result(self.obj) if self.obj.Report else None

    def refresh(self):
        result = self.result()
        if result is None:
            error = getattr(self.obj.Proxy, "error", None)
            self.table.setRowCount(0)
            self.table.hide()  # an empty frame says nothing
            self.message.setText("Not simulated: %s" % (error or ", ".join(self.obj.State) or "no Job or operation"))
        else:
            self.message.setText("")
            self.fill_table(summary_rows(result.summary))
        self.plots.redraw()

    def fill_table(self, rows):
        self.table.show()
        self.table.setRowCount(len(rows))
        for i, (label, value, tip) in enumerate(rows):
            for column, text in enumerate((label, value)):
                item = QtWidgets.QTableWidgetItem(text)
                item.setToolTip(tip)
                self.table.setItem(i, column, item)
        self.table.resizeRowsToContents()
        self.fit_table_height()

    def draw_plots(self, figure, wide):
        result = self.result()
        if result is None:
            return False
        draw_feed_histograms(figure, result.summary,
                             stacked=not wide)
        return True

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
        paths = feedsim.write_report(result, folder, stem, self.obj.Source.Label,
                                     machine=self.obj.Proxy.machine(self.obj))
        self.message.setText("written: " + ", ".join(paths))
        return paths
