"""Task panel of a roughing volume: the part and the stock (from the selection, or from the solids of the
document; a Job's stock is offered first), the strategy, the step, the region, the display; the volumes and
the counts computed, and the legend of the colours.

Compute stores the form and recomputes (seconds on the impeller, with a progress dialog whose Cancel keeps
the previous result); Display applies at once (both displays are kept: nothing is computed). OK keeps the
result (computing first if the form changed), Cancel restores the object as it was when the panel opened
(or removes the object the command had just added).
"""
import FreeCADGui
from PySide import QtCore, QtWidgets

from hsmplanner.app.roughing import volume as roughing_object
from hsmplanner.app.roughing.volume import (DISPLAYS, LIMITS, STRATEGIES, STRATEGY_NONE, SUB_VOLUMES, has_solid,
                                            is_job, job_stock, jobs, part_and_stock, shown_display)

from .colors import FACE_CLASS_TIPS
from .roughing_view import palette
from .task_panel import TaskPanel, narrow_combo, narrow_form_layout

NONE_ITEM = "(none)"


def candidate_solids(obj):
    """Objects of the document that hold a solid, except roughing volumes."""
    return [o for o in obj.Document.Objects
            if has_solid(o) and type(getattr(o, "Proxy", None)).__name__ != "RoughingVolume"]


def _swatch(color, tip=""):
    swatch = QtWidgets.QLabel()
    swatch.setFixedSize(14, 14)
    r, g, b = (int(round(255 * c)) for c in color)
    swatch.setStyleSheet("background-color: rgb(%d, %d, %d); border: 1px solid #333333;" % (r, g, b))
    swatch.setToolTip(tip)
    return swatch


ERROR_STYLE = "color: #b00000;"


class Legend(QtWidgets.QWidget):
    """The colours of the view and what they mean: one swatch and label per class (or per slice parity)."""

    def __init__(self, sub_volumes):
        super().__init__()
        colors, labels = palette(sub_volumes)
        tips = list(FACE_CLASS_TIPS) if not sub_volumes else ["", ""]
        grid = QtWidgets.QGridLayout(self)
        grid.setContentsMargins(0, 0, 0, 0)
        self.labels = []
        for row, (color, label, tip) in enumerate(zip(colors, labels, tips)):
            text = QtWidgets.QLabel(label)
            text.setToolTip(tip)
            grid.addWidget(_swatch(color, tip), row, 0)
            grid.addWidget(text, row, 1)
            self.labels.append(label)
        grid.setColumnStretch(1, 1)


def message_text(obj):
    """What went wrong in the last computation, or ''."""
    proxy = obj.Proxy
    if getattr(proxy, "error", None):
        return "Not computed: %s" % proxy.error
    if getattr(proxy, "cancelled", False):
        return "Cancelled: the previous result is kept."
    return ""


def summary_text(obj):
    """The result as people read it."""
    if obj.VolumeShape.isNull():
        if getattr(obj.Proxy, "error", None):
            return ""
        return "No result yet: choose the part and the stock, then Compute."
    lines = ["<b>Volume to remove: %.0f mm³</b>" % obj.Volume,
             "stock %.0f − part %.0f mm³" % (obj.StockVolume, obj.PartVolume)]
    count = obj.RegionCount
    lines.append("%d region%s (1 = the largest):" % (count, "" if count == 1 else "s"))
    for index, (volume, counts) in enumerate(zip(obj.RegionVolumes, obj.FaceClassCounts)):
        if index == 8 and count > 9:
            lines.append("… %d more" % (count - 8))
            break
        short = counts.replace("facing_crossable", "facing").replace("not_crossable", "not")
        lines.append("%d: %.0f mm³ — %s" % (index + 1, volume, short))
    if obj.SubVolumeCount:
        where = "all regions" if obj.Region == 0 else "region %d" % obj.Region
        lines.append("<b>%d sub-volumes</b> (%s, step %g mm, %s):" % (
            obj.SubVolumeCount, obj.Strategy.split(" ")[0], obj.Step.Value, where))
        lines.append(", ".join("%.0f" % v for v in obj.SubVolumes[:24]) + (" …" if obj.SubVolumeCount > 24 else "")
                     + " mm³")
    if obj.Strategy.startswith("S3") and obj.SubVolumeCount:
        d = obj.SetupDirection
        lines.append("Setup axis (%.2f, %.2f, %.2f), reaches %.0f %%" % (d.x, d.y, d.z, 100.0 * obj.SetupReach))
    lines += ["⚠ " + warning for warning in obj.Warnings]
    return "<br>".join(lines)


class RoughingPanel(TaskPanel):
    def __init__(self, obj, created=False):
        self.obj, self.created = obj, created
        self.document = obj.Document
        self.document.openTransaction("Edit %s" % obj.Label)  # Cancel aborts it: the object as it was
        self.form = self._build_form()
        self.load_form()
        self.refresh()
        self.opened()

    # --- form -----------------------------------------------------------------------------------------------
    def _build_form(self):
        form = QtWidgets.QWidget()
        form.setWindowTitle("Roughing volume")
        layout = QtWidgets.QVBoxLayout(form)
        inputs = narrow_form_layout()
        layout.addLayout(inputs)
        self.part = narrow_combo(names=True)
        self.part.setToolTip("the part: a closed solid")
        self.stock = narrow_combo(names=True)
        self.stock.setToolTip("the blank: a Job's stock, or a solid that contains the part")
        inputs.addRow("Part", self.part)
        inputs.addRow("Stock", self.stock)
        self.selection_button = QtWidgets.QPushButton("Use selection")
        self.selection_button.setToolTip("take the part and the stock (two solids, in any order) or the part (one) "
                                         "selected in the 3D view or the tree")
        inputs.addRow("", self.selection_button)
        self.strategy = narrow_combo(STRATEGIES)
        self.strategy.setToolTip("how the volume is cut into sub-volumes")
        inputs.addRow("Strategy", self.strategy)
        self.step = self._spin(*LIMITS["Step"], 2, " mm", self.obj.getDocumentationOfProperty("Step"))
        inputs.addRow("Step", self.step)
        self.region = QtWidgets.QSpinBox()
        self.region.setRange(*LIMITS["Region"])
        self.region.setSpecialValueText("all (slow)")
        self.region.setToolTip(self.obj.getDocumentationOfProperty("Region"))
        inputs.addRow("Region", self.region)
        self.setup_resolution = self._spin(*LIMITS["SetupResolution"], 1, " °",
                                           self.obj.getDocumentationOfProperty("SetupResolution"))
        self.setup_grid = self._spin(*LIMITS["SetupGrid"], 2, " mm", self.obj.getDocumentationOfProperty("SetupGrid"))
        inputs.addRow("S3 directions", self.setup_resolution)
        inputs.addRow("S3 grid", self.setup_grid)
        self.display = narrow_combo(DISPLAYS)
        self.display.setToolTip(self.obj.getDocumentationOfProperty("Display"))
        inputs.addRow("Display", self.display)
        self.compute_button = QtWidgets.QPushButton("Compute")
        self.compute_button.setToolTip("store the form and compute (a progress dialog with Cancel shows on long work)")
        layout.addWidget(self.compute_button)
        self.message = QtWidgets.QLabel()
        self.message.setWordWrap(True)
        self.message.setStyleSheet(ERROR_STYLE)
        layout.addWidget(self.message)
        self.legend_box = QtWidgets.QGroupBox("Colours in the 3D view")  # near the top: always in sight
        legend_layout = QtWidgets.QVBoxLayout(self.legend_box)
        self.legends = {flag: Legend(flag) for flag in (False, True)}  # face classes, slices
        for legend in self.legends.values():
            legend_layout.addWidget(legend)
        self.legend = self.legends[False]
        layout.addWidget(self.legend_box)
        self.summary = QtWidgets.QLabel()
        self.summary.setWordWrap(True)
        self.summary.setTextFormat(QtCore.Qt.RichText)
        layout.addWidget(self.summary)
        layout.addStretch(1)
        self.selection_button.clicked.connect(self.use_selection)
        self.compute_button.clicked.connect(self.compute)
        self.strategy.currentIndexChanged.connect(self.enable_rows)
        self.display.currentIndexChanged.connect(self.display_changed)
        return form

    @staticmethod
    def _spin(low, high, decimals, suffix, tip):
        box = QtWidgets.QDoubleSpinBox()
        box.setDecimals(decimals)
        box.setRange(low, high)
        box.setSuffix(suffix)
        box.setToolTip(tip)
        return box

    def fill_combos(self):
        """Part: the document's solids; Stock: the Jobs' stocks first, then the solids."""
        solids = candidate_solids(self.obj)
        stocks = [job_stock(job) for job in jobs(self.document) if job_stock(job) is not None]
        self.part_objects = list(solids)
        self.stock_objects = stocks + [o for o in solids if o not in stocks]
        for combo, objects, current in ((self.part, self.part_objects, self.obj.Part),
                                        (self.stock, self.stock_objects, self.obj.Stock)):
            if current is not None and is_job(current):
                current = job_stock(current)
            if current is not None and current not in objects:
                objects.insert(0, current)
            combo.blockSignals(True)
            combo.clear()
            combo.addItem(NONE_ITEM)
            combo.addItems([self.item_text(o) for o in objects])
            combo.setCurrentIndex(objects.index(current) + 1 if current is not None else 0)
            combo.blockSignals(False)

    def item_text(self, obj):
        for job in jobs(self.document):
            if job_stock(job) == obj:
                return "%s (%s)" % (obj.Label, job.Label)
        return obj.Label

    def load_form(self):
        self.fill_combos()
        self.strategy.setCurrentText(self.obj.Strategy)
        self.step.setValue(self.obj.Step.Value)
        self.region.setValue(self.obj.Region)
        self.setup_resolution.setValue(self.obj.SetupResolution.Value)
        self.setup_grid.setValue(self.obj.SetupGrid.Value)
        self.display.blockSignals(True)
        self.display.setCurrentText(self.obj.Display)
        self.display.blockSignals(False)
        self.enable_rows()

    def enable_rows(self, *args):
        strategy = self.strategy.currentText()
        for widget in (self.step, self.region):
            widget.setEnabled(strategy != STRATEGY_NONE)
        for widget in (self.setup_resolution, self.setup_grid):
            widget.setEnabled(strategy.startswith("S3"))

    def selected_part(self):
        index = self.part.currentIndex()
        return self.part_objects[index - 1] if index > 0 else None

    def selected_stock(self):
        index = self.stock.currentIndex()
        return self.stock_objects[index - 1] if index > 0 else None

    def use_selection(self):
        picked = [o for o in FreeCADGui.Selection.getSelection() if has_solid(o) or is_job(o)]
        if len(picked) == 2:
            part, stock = part_and_stock(*picked)
        elif len(picked) == 1:
            part, stock = picked[0], roughing_object.default_stock(picked[0]) or self.selected_stock()
        else:
            self.say("Select the part and its stock (two solids), or the part, in the 3D view or the tree "
                     "(%d solids selected)." % len(picked))
            return False
        for combo, objects, target in ((self.part, self.part_objects, part), (self.stock, self.stock_objects, stock)):
            if target is not None and is_job(target):
                target = job_stock(target)
            if target is not None and target not in objects:
                objects.append(target)
                combo.addItem(self.item_text(target))
            combo.setCurrentIndex(objects.index(target) + 1 if target is not None else 0)
        self.say("")
        return True

    def store_form(self):
        """The form into the object (only what differs: an unchanged object needs no recompute)."""
        values = dict(Part=self.selected_part(), Stock=self.selected_stock(), Strategy=self.strategy.currentText(),
                      Step=self.step.value(), Region=self.region.value(),
                      SetupResolution=self.setup_resolution.value(), SetupGrid=self.setup_grid.value(),
                      Display=self.display.currentText())
        for name, value in values.items():
            current = getattr(self.obj, name)
            current = current.Value if hasattr(current, "Value") else current
            if current != value:
                setattr(self.obj, name, value)

    # --- computing ------------------------------------------------------------------------------------------
    def compute(self):
        """Store the form and recompute; a bad input is shown here (and on one line in the Report view)."""
        self.store_form()
        if self.selected_part() is None or self.selected_stock() is None:
            self.refresh()
            self.say("Choose the part and the stock.")
            return False
        self.say("Computing…", error=False)
        QtWidgets.QApplication.processEvents()
        self.document.recompute()
        self.refresh()
        return not self.obj.Proxy.error and not self.obj.Proxy.cancelled

    def display_changed(self, *args):
        """Both displays are kept: switching computes nothing (unless the last computation failed: then the
        display waits for the next Compute, which would only fail again on the stored inputs)."""
        if self.obj.Display != self.display.currentText():
            self.obj.Display = self.display.currentText()
            if not self.obj.Proxy.error:
                self.document.recompute()
        self.refresh()

    def say(self, text, error=True):
        """A message under the settings: red for what is wrong, plain for what is going on."""
        self.message.setStyleSheet(ERROR_STYLE if error else "")
        self.message.setText(text)
        self.message.setVisible(bool(text))

    def refresh(self):
        self.say(message_text(self.obj))
        self.summary.setText(summary_text(self.obj))
        self.legend = self.legends[shown_display(self.obj) == SUB_VOLUMES]
        for legend in self.legends.values():
            legend.setVisible(legend is self.legend)

    # --- task dialog ----------------------------------------------------------------------------------------
    def getStandardButtons(self):
        return QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel

    def accept(self):
        self.store_form()
        self.document.recompute()
        self.document.commitTransaction()
        self.close_edit()
        return True

    def reject(self):
        name = self.obj.Name
        self.document.abortTransaction()  # before closing: ending the edit commits the open transaction
        self.close_edit()
        obj = self.document.getObject(name)  # the abort may have taken the command's new object already
        if obj is not None and self.created:
            self.document.removeObject(name)  # the command's new object goes if the user cancels
        elif obj is not None:
            obj.Proxy.error, obj.Proxy.cancelled = None, False  # of the edits undone
        return True
