"""Task panel of the Guide curve net: pick the boundaries and the bottom face, tune K and P, see the net live.

Every change recomputes the curves in the core (tens of milliseconds) and redraws the preview; the
document object is written, and the face split into its areas, only on OK.
"""
import FreeCAD
import FreeCADGui
from PySide import QtCore, QtWidgets

from hsmplanner.app.guide_curve_net import FOUR_STEP, MODES, NetParameters, build_guide_curve_net
from hsmplanner.app.guide_curve_net_object import LIMITS, linked_shape

from .preview import NetPreview
from .task_panel import TaskPanel, narrow_combo, narrow_form_layout

K_SLIDER_SCALE = 100     # slider units per unit of K
STEP_SLIDER_SCALE = 2    # slider units per mm of P (0.5 mm resolution)


ADD_TRANSACTION = "Add guide curve net"  # the command's undo step

class _PickGate:
    """Selection gate: only edges, or only faces, while a Pick button is down."""

    def __init__(self, prefix):
        self.prefix = prefix

    def allow(self, document, obj, sub):
        return bool(sub) and sub.startswith(self.prefix)


class _LinkField:
    """A row 'name: [picked element] [Pick]' holding a (object, [subnames]) link."""

    def __init__(self, panel, label, prefix, layout):
        self.panel, self.prefix, self.link = panel, prefix, None
        self.text = QtWidgets.QLineEdit()
        self.text.setReadOnly(True)
        self.text.setPlaceholderText("pick a %s in the 3D view" % ("face" if prefix == "Face" else "edge"))
        self.button = QtWidgets.QPushButton("Pick")
        self.button.setCheckable(True)
        self.button.setMaximumWidth(self.button.fontMetrics().horizontalAdvance("Pick") + 24)  # room for the name
        self.button.setToolTip("then click the %s in the 3D view" % ("face" if prefix == "Face" else "edge(s)"))
        self.button.toggled.connect(self.toggled)
        row = QtWidgets.QHBoxLayout()
        row.addWidget(self.text)
        row.addWidget(self.button)
        layout.addRow(label, row)

    def toggled(self, down):
        self.panel.picking(self if down else None)

    def set(self, obj, subs):
        self.link = (obj, list(subs)) if obj is not None else None
        self.text.setText("%s: %s" % (obj.Label, ", ".join(subs)) if obj is not None else "")
        self.text.setToolTip(self.text.text())
        self.text.setCursorPosition(len(self.text.text()))  # the element's name shows when the field is narrow


class GuideCurveNetPanel(TaskPanel):
    def __init__(self, obj, created=False):
        self.obj, self.created = obj, created
        self.preview = NetPreview()
        self.last_result = None
        self.last_error = None
        self.picker = None
        self._timer = QtCore.QTimer()
        self._timer.setSingleShot(True)
        self._timer.setInterval(30)  # coalesces the slider's bursts of signals
        self._timer.timeout.connect(self.update_preview)
        self.form = self._build_form()
        self._load(obj)
        FreeCADGui.Selection.addObserver(self)
        self.opened()
        self.schedule()

    # --- form ---------------------------------------------------------------------------------------------
    def _build_form(self):
        form = QtWidgets.QWidget()
        form.setWindowTitle("Guide curve net")
        outer = QtWidgets.QVBoxLayout(form)

        picks = QtWidgets.QGroupBox("Boundaries and bottom")
        picks_layout = narrow_form_layout()
        picks.setLayout(picks_layout)
        self.boundary_1 = _LinkField(self, "Boundary 1", "Edge", picks_layout)
        self.boundary_2 = _LinkField(self, "Boundary 2", "Edge", picks_layout)
        self.bottom = _LinkField(self, "Bottom face", "Face", picks_layout)
        outer.addWidget(picks)

        net = QtWidgets.QGroupBox("Net")
        grid = QtWidgets.QGridLayout(net)
        self.mode = narrow_combo(MODES)
        grid.addWidget(QtWidgets.QLabel("Mode"), 0, 0)
        grid.addWidget(self.mode, 0, 1, 1, 2)
        self.k_slider, self.k_box = self._slider_row(grid, 1, "K", 1, 99, K_SLIDER_SCALE, *LIMITS["K"], 2, "")
        self.step_slider, self.step_box = self._slider_row(grid, 2, "Step P", 1, 80, STEP_SLIDER_SCALE,
                                                           *LIMITS["Step"], 1, " mm")
        self.gap_box = QtWidgets.QDoubleSpinBox()
        self.gap_box.setRange(*LIMITS["MinGap"])
        self.gap_box.setDecimals(2)
        self.gap_box.setSuffix(" mm")
        gap_label = QtWidgets.QLabel("Min. gap")
        gap_label.setToolTip("a net stops before a curve comes closer than this to its target")
        grid.addWidget(gap_label, 3, 0)
        grid.addWidget(self.gap_box, 3, 1, 1, 2)
        self.four_step = QtWidgets.QPushButton("4-step method")
        self.four_step.setToolTip("the paper's method: the median, then one curve at K 0.75 in each half, with planes "
                                  "adapted to the guides' curvature")
        grid.addWidget(self.four_step, 4, 0, 1, 3)
        outer.addWidget(net)

        self.info = QtWidgets.QLabel()
        self.info.setWordWrap(True)
        outer.addWidget(self.info)

        self.mode.currentIndexChanged.connect(self.schedule)
        self.gap_box.valueChanged.connect(self.schedule)
        self.four_step.clicked.connect(self.use_four_step)
        return form

    def _slider_row(self, grid, row, label, lo, hi, scale, box_lo, box_hi, decimals, suffix):
        slider = QtWidgets.QSlider(QtCore.Qt.Horizontal)
        slider.setRange(lo, hi)
        box = QtWidgets.QDoubleSpinBox()
        box.setRange(box_lo, box_hi)
        box.setDecimals(decimals)
        box.setSingleStep(1.0 / scale)
        box.setSuffix(suffix)
        slider.valueChanged.connect(lambda v: box.setValue(v / scale))
        box.valueChanged.connect(lambda v: (slider.blockSignals(True), slider.setValue(round(v * scale)),
                                            slider.blockSignals(False), self.schedule()))
        grid.addWidget(QtWidgets.QLabel(label), row, 0)
        grid.addWidget(slider, row, 1)
        grid.addWidget(box, row, 2)
        return slider, box

    def _load(self, obj):
        for field, link in ((self.boundary_1, obj.Boundary1), (self.boundary_2, obj.Boundary2),
                            (self.bottom, obj.BottomFace)):
            if link:
                field.set(link[0], link[1] if not isinstance(link[1], str) else [link[1]])
        if not (self.boundary_1.link and self.boundary_2.link):
            self._take_selection()
        self.mode.setCurrentText(obj.Mode)
        self.k_box.setValue(obj.K)
        self.step_box.setValue(obj.Step.Value)
        self.gap_box.setValue(obj.MinGap.Value)

    def _take_selection(self):
        """Edges selected before the command: first is boundary 1, second boundary 2; a face is the bottom."""
        edges, faces = [], []
        for selection in FreeCADGui.Selection.getSelectionEx():
            for sub in selection.SubElementNames:
                (edges if sub.startswith("Edge") else faces if sub.startswith("Face") else []).append(
                    (selection.Object, sub))
        for field, pick in zip((self.boundary_1, self.boundary_2), edges):
            field.set(pick[0], [pick[1]])
        if faces:
            self.bottom.set(faces[0][0], [faces[0][1]])

    # --- picking --------------------------------------------------------------------------------------------
    def picking(self, field):
        for other in (self.boundary_1, self.boundary_2, self.bottom):
            if other is not field and other.button.isChecked():
                other.button.blockSignals(True)
                other.button.setChecked(False)
                other.button.blockSignals(False)
        FreeCADGui.Selection.removeSelectionGate()
        self.picker = field
        if field is not None:
            FreeCADGui.Selection.clearSelection()
            FreeCADGui.Selection.addSelectionGate(_PickGate(field.prefix))

    def addSelection(self, document, object_name, sub, position=None):
        """Selection observer: the next edge or face picked fills the field whose Pick button is down."""
        if self.picker is None or not sub.startswith(self.picker.prefix):
            return
        obj = FreeCAD.getDocument(document).getObject(object_name)
        self.picker.set(obj, [sub])
        field, self.picker = self.picker, None
        field.button.setChecked(False)
        FreeCADGui.Selection.removeSelectionGate()
        self.schedule()

    # --- computing ------------------------------------------------------------------------------------------
    def use_four_step(self):
        self.mode.setCurrentText(FOUR_STEP)
        self.k_box.setValue(NetParameters.k)
        self.step_box.setValue(NetParameters.step)

    def parameters(self):
        direction = self.obj.Direction
        return NetParameters(mode=self.mode.currentText(), k=self.k_box.value(), step=self.step_box.value(),
                             direction=None if direction.Length < 1e-12 else tuple(direction),
                             min_gap=self.gap_box.value(), fit_tolerance=self.obj.FitTolerance.Value,
                             k_median=self.obj.KMedian)

    def schedule(self, *args):
        self._timer.start()

    def update_preview(self):
        if not (self.boundary_1.link and self.boundary_2.link):
            self.preview.clear()
            self._say("Pick the two boundary edges (and the bottom face to put the curves on it).")
            return
        try:
            face = linked_shape(self.bottom.link, "Bottom face", faces=True) if self.bottom.link else None
            result = build_guide_curve_net(linked_shape(self.boundary_1.link, "Boundary 1"),
                                           linked_shape(self.boundary_2.link, "Boundary 2"), face,
                                           self.parameters(), with_regions=False)
        except (ValueError, RuntimeError, TypeError) as error:  # bad input: say it, keep the panel open
            self.last_result, self.last_error = None, str(error)
            self.preview.clear()
            self._say(str(error), error=True)
            return
        self.last_result, self.last_error = result, None
        self.preview.show(result.net)
        stations = result.net.stations
        text = "%d curves, %d elementary areas, %d planes" % (
            len(result.net.curves), len(result.net.elementary_areas()), len(stations))
        if result.report is not None:
            text += " (adapted spacing %.2f–%.2f mm)" % (result.report.smallest_step, result.report.largest_step)
        if result.net.warnings:
            text += "\n" + "\n".join(result.net.warnings)
        self._say(text)

    def _say(self, text, error=False):
        self.info.setStyleSheet("color: #b00000;" if error else "")
        self.info.setText(text)

    # --- task dialog --------------------------------------------------------------------------------------
    def getStandardButtons(self):
        return QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel

    def accept(self):
        obj = self.obj
        obj.Boundary1 = self.boundary_1.link
        obj.Boundary2 = self.boundary_2.link
        obj.BottomFace = self.bottom.link
        obj.Mode = self.mode.currentText()
        obj.K = self.k_box.value()
        obj.Step = self.step_box.value()
        obj.MinGap = self.gap_box.value()
        obj.Document.recompute()
        self._close()
        obj.Document.commitTransaction()
        return True

    def reject(self):
        document = self.obj.Document
        self._close()
        document.abortTransaction()
        if self.created and document.getObject(self.obj.Name) is not None:
            # The command's new object goes if the user cancels, and leaves no undo entry: FreeCAD has
            # committed the command's transaction by now (editing does), so it is undone, not deleted (a
            # deletion would add a "Delete" step after the "Add").
            if list(document.UndoNames[:1]) == [ADD_TRANSACTION]:
                document.undo()
            else:
                document.removeObject(self.obj.Name)
        return True

    def _close(self):
        self._timer.stop()
        FreeCADGui.Selection.removeObserver(self)
        FreeCADGui.Selection.removeSelectionGate()
        self.preview.detach()
        self.close_edit()
