"""Task panel of a machining direction analysis: the face, tool, scallop, feed (or feed range), machine; the
three choices (beams, least predicted time, fastest simulated) with their plots; and a button that sets the
angle of a Parallel plane finishing operation."""
from PySide import QtWidgets

from hsmplanner.app import direction_object
from hsmplanner.app.direction_object import CHOICES, FEED_FROM
from hsmplanner.plots.direction import PREDICTED_TIME_NOTE, draw_direction_report

from .task_panel import AnalysisPanel, PanelPlots, narrow_combo, narrow_form_layout, selected_faces

# (property, label, minimum, maximum, decimals, suffix): the numbers of the form, as the object holds them
# (property, label, decimals, suffix); the ranges are the object's (direction_object.LIMITS).
_ROWS = [
    ("ToolDiameter", "Ball diameter", 3, " mm"),
    ("Teeth", "Teeth Z", 0, ""),
    ("Scallop", "Scallop Sz", 4, " mm"),
    ("Feed", "Programmed feed", 0, " mm/min"),
    ("FeedPerTooth", "Feed per tooth fz", 3, " mm"),
    ("SpindleSpeed", "Spindle speed N", 0, " rpm"),
    ("Acceleration", "a_max (no machine)", 2, " m/s²"),
    ("ScanFrom", "Feed scan from", 0, " mm/min"),
    ("ScanTo", "Feed scan to", 0, " mm/min"),
    ("ScanSteps", "Feeds in the scan", 0, ""),
    ("ValidationStep", "Simulate planes every", 1, " °"),
]
_NUMBERS = [(name, label) + direction_object.LIMITS[name] + (decimals, suffix)
            for name, label, decimals, suffix in _ROWS]


def _value(obj, name):
    value = getattr(obj, name)
    return value.Value if hasattr(value, "Value") else value


def summary_text(obj):
    """The result as people read it."""
    error = getattr(obj.Proxy, "error", None)
    if error:
        return "Not computed: %s" % error
    if not obj.PointCount:
        return "Not computed yet."
    lines = ["<b>Chosen (%s): %.0f°</b> — predicted %.0f s of planes" % (obj.Choice.lower(), obj.ChosenAngle.Value,
                                                                        obj.PredictedTime),
             "Directional beams: %.0f°, α* %.3f; acceptable %s" % (obj.OptimalAngle.Value, obj.BeamAlpha,
                                                                 obj.AcceptableRanges or "—"),
             "Least predicted time: %.0f°" % obj.LeastTimeAngle.Value]
    if obj.ValidationTimes:
        best = min(zip(obj.ValidationTimes, obj.ValidationAngles))
        lines.append("Fastest simulated: %.0f° (%.1f s)" % (best[1], best[0]))
    lines += ["⚠ " + warning for warning in obj.Warnings]
    return "<br>".join(lines)


class DirectionPanel(AnalysisPanel):
    def _build_form(self):
        form, layout, settings = self.new_form("Machining direction")
        face_row = QtWidgets.QHBoxLayout()
        self.face_label = QtWidgets.QLabel()
        self.face_label.setWordWrap(True)
        self.face_button = QtWidgets.QPushButton("Use selection")
        self.face_button.setToolTip("take the face selected in the 3D view")
        face_row.addWidget(self.face_label, 1)
        face_row.addWidget(self.face_button)
        settings.addRow("Face", face_row)
        self.feed_from = narrow_combo(FEED_FROM)
        settings.addRow("Feed from", self.feed_from)
        self.numbers = {}
        for name, label, low, high, decimals, suffix in _NUMBERS:
            box = QtWidgets.QSpinBox() if decimals == 0 and high <= 100 else QtWidgets.QDoubleSpinBox()
            if isinstance(box, QtWidgets.QDoubleSpinBox):
                box.setDecimals(decimals)
            box.setRange(low, high)
            box.setSuffix(suffix)
            self.numbers[name] = box
            settings.addRow(label, box)
        self.machine = narrow_combo(self.obj.getEnumerationsOfProperty("Machine"))
        settings.addRow("Machine", self.machine)
        self.use_jerk = QtWidgets.QCheckBox("jerk limit too")
        self.use_jerk.setToolTip("limit the real feed by the axes' jerk too, not only by their acceleration")
        settings.addRow("", self.use_jerk)
        self.choice = narrow_combo(CHOICES)
        settings.addRow("Apply", self.choice)
        self.compute_button = QtWidgets.QPushButton("Compute")
        layout.addWidget(self.compute_button)
        self.summary = QtWidgets.QLabel()
        self.summary.setWordWrap(True)
        layout.addWidget(self.summary)
        # Two plots stacked, each with its legend below it.
        self.plots = PanelPlots(layout, 760, self.draw_plots, "Machining direction: %s" % self.obj.Label,
                                tooltip=PREDICTED_TIME_NOTE)
        self.figure = self.plots.figure
        apply_row = narrow_form_layout()  # the operation under the button when the panel is narrow
        self.operations = narrow_combo(names=True)
        self.apply_button = QtWidgets.QPushButton("Set the angle of")
        apply_row.addRow(self.apply_button, self.operations)
        layout.addLayout(apply_row)
        self.message = QtWidgets.QLabel()
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        self.face_button.clicked.connect(self.use_selected_face)
        self.compute_button.clicked.connect(self.compute)
        self.apply_button.clicked.connect(self.apply)
        self.load_form()
        return form

    def load_form(self):
        self.face_label.setText(self.face_text())
        self.feed_from.setCurrentText(self.obj.FeedFrom)
        for name, box in self.numbers.items():
            box.setValue(_value(self.obj, name))
        self.machine.setCurrentText(self.obj.Machine)
        self.use_jerk.setChecked(self.obj.UseJerk)
        self.choice.setCurrentText(self.obj.Choice)
        self.list_operations()

    def face_text(self):
        if not self.obj.Face:
            return "none: select a face in the 3D view"
        part, subs = self.obj.Face
        return "%s, %s" % (part.Label, ", ".join([subs] if isinstance(subs, str) else subs))

    def list_operations(self):
        self.operations.clear()
        self.operation_objects = [o for o in self.obj.Document.Objects if direction_object.is_parallel_plane_finishing(o)]
        self.operations.addItems([o.Label for o in self.operation_objects])
        self.apply_button.setEnabled(bool(self.operation_objects))

    def use_selected_face(self):
        picked = selected_faces()
        if len(picked) != 1:
            self.message.setText("Select exactly one face in the 3D view (%d selected)." % len(picked))
            return False
        self.obj.Face = (picked[0][0], [picked[0][1]])
        self.face_label.setText(self.face_text())
        return True

    def store_form(self):
        self.obj.FeedFrom = self.feed_from.currentText()
        for name, box in self.numbers.items():
            setattr(self.obj, name, box.value())
        self.obj.Machine = self.machine.currentText()
        self.obj.UseJerk = self.use_jerk.isChecked()
        self.obj.Choice = self.choice.currentText()

    def compute(self):
        """Store the form and compute; a bad input is shown, not raised (the document stays as it was)."""
        self.store_form()
        if self.obj.Choice == CHOICES[2]:
            self.message.setText("Finishing and simulating planes every %g°…" % self.obj.ValidationStep)
            QtWidgets.QApplication.processEvents()
        try:
            self.obj.Proxy.run(self.obj)
        except (ValueError, RuntimeError) as error:
            self.message.setText("Not computed: %s" % error)
            return False
        self.obj.purgeTouched()
        self.message.setText("")
        self.refresh()
        return True

    def refresh(self):
        self.summary.setText(summary_text(self.obj))
        self.plots.redraw()

    def draw_plots(self, figure, wide):
        proxy = self.obj.Proxy
        if getattr(proxy, "result", None) is None:
            return False
        title = "%s: %s" % (self.obj.Label, self.face_text()) if wide else ""
        draw_direction_report(figure, proxy.result, title, scan=proxy.scan, validation=proxy.validation,
                              stacked=not wide)
        return True

    def apply(self):
        operation = self.operation_objects[self.operations.currentIndex()]
        try:
            angle = direction_object.apply_to_operation(self.obj, operation)
        except ValueError as error:
            self.message.setText(str(error))
            return None
        self.message.setText("%s: planes at %.0f°, %d passes." % (operation.Label, angle, operation.Passes))
        return angle
