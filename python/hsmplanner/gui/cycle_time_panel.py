"""Task panel of a Job's cycle time: the machine, and per operation CAM's estimate, length / feed and the
simulated time with what held the speed, then the Job's total."""
from PySide import QtCore, QtWidgets

from hsmplanner.app.cycle_time import clock

from .task_panel import AnalysisPanel, narrow_combo

# The simulated time next to the operation's name: the columns in view in the default Combo View's width
# (KEY_COLUMNS) are what a user compares first; CAM's estimate and length / feed follow.
COLUMNS = [("Operation", "the Job's active operations in order, then the whole Job"),
           ("Sim.", "simulated on the machine: jerk, acceleration, look-ahead, the rotary axes"),
           ("CAM", "CAM's own estimate (the operation's CycleTime): length / feed, every move with a Z component "
                   "at the vertical feed"),
           ("L / F", "length / programmed feed, rapids at the machine's rapid traverse"),
           ("Held by", "what held the speed longest in the simulation (F: the programmed feed; X..C: that axis; "
                       "curvature; the block rate)")]
KEY_COLUMNS = 3


class CycleTimePanel(AnalysisPanel):
    def _build_form(self):
        form, layout, settings = self.new_form("Cycle time")
        self.machine = narrow_combo(self.obj.getEnumerationsOfProperty("Machine"), self.obj.Machine)
        settings.addRow("Machine", self.machine)
        self.simulate_button = QtWidgets.QPushButton("Simulate")
        self.simulate_button.setToolTip("Time the Job again on the machine chosen (it is timed again by itself "
                                        "whenever an operation is recomputed)")
        layout.addWidget(self.simulate_button)
        self.message = QtWidgets.QLabel()
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        self.table = QtWidgets.QTableWidget(0, len(COLUMNS))
        self.table.setHorizontalHeaderLabels([name for name, _ in COLUMNS])
        for column, (_, tip) in enumerate(COLUMNS):
            self.table.horizontalHeaderItem(column).setToolTip(tip)
        self.table.verticalHeader().setVisible(False)
        self.table.setEditTriggers(QtWidgets.QAbstractItemView.NoEditTriggers)
        self.table.horizontalHeader().setSectionResizeMode(QtWidgets.QHeaderView.ResizeToContents)
        layout.addWidget(self.table)
        self.why = QtWidgets.QLabel(
            "Why they differ: CAM divides each move's length by a feed; the machine also slows for every corner "
            "and short block (jerk and acceleration), and a rotary axis may hold it back.")
        self.why.setWordWrap(True)
        layout.addWidget(self.why)
        self.simulate_button.clicked.connect(self.simulate)
        return form

    def simulate(self):
        self.obj.Machine = self.machine.currentText()
        self.obj.Proxy.forget()
        self.obj.recompute()
        self.refresh()

    def refresh(self):
        rows, total, _ = self.obj.Proxy.rows(self.obj)
        self.table.setRowCount(0)
        if rows is None:
            self.message.setText("Not timed: %s" % (self.obj.Proxy.error or "link a Job"))
            return
        problems = [row for row in rows + [total] if row["error"]]
        self.message.setText("\n".join("%s: %s" % (row["label"], row["error"]) for row in problems))
        for row in rows + [total]:
            self.add_row(row, bold=row is total)
        self.table.resizeColumnsToContents()

    def add_row(self, row, bold=False):
        index = self.table.rowCount()
        self.table.insertRow(index)
        texts = [row["label"], clock(row["simulated_s"]), clock(row["cam_s"]), clock(row["naive_s"]),
                 row["held_by"] or ("—" if row["error"] else "")]
        for column, text in enumerate(texts):
            item = QtWidgets.QTableWidgetItem(text)
            if column in (1, 2, 3):
                item.setTextAlignment(QtCore.Qt.AlignRight | QtCore.Qt.AlignVCenter)
            if row["error"]:
                item.setToolTip(row["error"])
            if bold:
                font = item.font()
                font.setBold(True)
                item.setFont(font)
            self.table.setItem(index, column, item)
