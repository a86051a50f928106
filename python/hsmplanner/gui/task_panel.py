"""What the task panels of the workbench share: the open panel for tests and macros (`Class.active`),
closing that ends the edit, and the frame of an analysis panel."""
import FreeCADGui
from matplotlib.backends.backend_qtagg import FigureCanvasQTAgg
from matplotlib.figure import Figure
from PySide import QtCore, QtWidgets


def selected_faces():
    """(object, 'FaceN') of every face selected in the 3D view."""
    return [(s.Object, name) for s in FreeCADGui.Selection.getSelectionEx() for name in s.SubElementNames
            if name.startswith("Face")]


def freecad_message(error):
    """The text of an error to say in a panel: FreeCAD's own exceptions carry a dict whose sErrMsg is it."""
    detail = error.args[0] if error.args else error
    return detail.get("sErrMsg", str(detail)) if isinstance(detail, dict) else str(error)


def with_controller_selected(controller, create):
    """create()'s result, made while `controller` is the only selection: a new operation in a Job that has several
    tool controllers and no operation makes FreeCAD ask which one in a modal dialog, and it takes a selected
    controller instead (PathUtilsGui.selectedToolController)."""
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(controller)
    try:
        return create()
    finally:
        FreeCADGui.Selection.clearSelection()


class TaskPanel:
    active = None  # per panel class: the open one

    def opened(self):
        type(self).active = self

    def close_edit(self):
        type(self).active = None
        FreeCADGui.Control.closeDialog()
        if FreeCADGui.ActiveDocument is not None:
            FreeCADGui.ActiveDocument.resetEdit()

    def getStandardButtons(self):
        return QtWidgets.QDialogButtonBox.Close

    def reject(self):
        self.close_edit()
        return True


class AnalysisPanel(TaskPanel):
    """A panel over one analysis object: its form (`_build_form`) filled from the result (`refresh`)."""

    plots = None  # the panel's PanelPlots, if it has plots

    def __init__(self, obj):
        self.obj = obj
        self.form = self._build_form()
        self.refresh()
        self.opened()

    def close_edit(self):
        if self.plots is not None:
            self.plots.close()
        super().close_edit()

    @staticmethod
    def new_form(title):
        """The panel's widget, its vertical layout and the form layout of its settings (added first)."""
        form = QtWidgets.QWidget()
        form.setWindowTitle(title)
        layout = QtWidgets.QVBoxLayout(form)
        settings = narrow_form_layout()
        layout.addLayout(settings)
        return form, layout, settings


# FreeCAD's Combo View is 264 px wide in the default layout: every panel must fit it, as FreeCAD's own do. The
# task box's frame, margins and scroll bar take about 36 px of it (the GUI tests measure the panel in it).
COMBO_VIEW_WIDTH = 264


def narrow_form_layout():
    """A form layout whose rows put the field under its label when the panel is narrow."""
    layout = QtWidgets.QFormLayout()
    layout.setRowWrapPolicy(QtWidgets.QFormLayout.WrapLongRows)
    layout.setFieldGrowthPolicy(QtWidgets.QFormLayout.AllNonFixedFieldsGrow)
    return layout


def button_text_width(button):
    """The width a push button needs to show its icon and text whole: Qt's common style adds the button margin
    and the frame on both sides to them (the 80 px a style may ask beyond that only pads)."""
    style = button.style()
    icon = button.iconSize().width() + 4 if not button.icon().isNull() else 0
    frame = 2 * style.pixelMetric(QtWidgets.QStyle.PM_DefaultFrameWidth, None, button)
    margin = style.pixelMetric(QtWidgets.QStyle.PM_ButtonMargin, None, button)
    return button.fontMetrics().horizontalAdvance(button.text().replace("&", "")) + icon + margin + frame


def compact_buttons(button_box):
    """Lets the buttons of a dialog's button box narrow to their icon and text: the style gives a text button 80 px
    at least, and FreeCAD's OK, Apply and Cancel side by side then need more than the Combo View has."""
    for button in button_box.buttons():
        button.setMinimumWidth(button_text_width(button))


class ElidingComboBox(QtWidgets.QComboBox):
    """A combo box that draws a current text too long for it with an ellipsis (Qt would cut it at the edge);
    the full text is the first line of its tool tip, and setToolTip sets the lines after it. Names of objects
    are elided in the middle, so that names sharing a prefix ("SlantedSlotBlock", "SlantedSlotBlock stock")
    still read apart; other choices at the end, where their words stay whole."""

    def __init__(self, parent=None, elide=QtCore.Qt.ElideRight):
        super().__init__(parent)
        self.elide = elide
        self.description = ""
        self.currentTextChanged.connect(self._update_tooltip)

    def setToolTip(self, text):
        self.description = text
        self._update_tooltip()

    def _update_tooltip(self, *args):
        lines = [line for line in (self.currentText(), self.description) if line]
        super().setToolTip("\n".join(lines))

    def _field_width(self):
        option = QtWidgets.QStyleOptionComboBox()
        self.initStyleOption(option)
        field = self.style().subControlRect(QtWidgets.QStyle.CC_ComboBox, option,
                                            QtWidgets.QStyle.SC_ComboBoxEditField, self)
        return field.width() - 2  # the style draws the text 1 px in from each side of the field

    def shown_text(self):
        """The current text as drawn: whole, or elided to the width of the box's text field."""
        return self.fontMetrics().elidedText(self.currentText(), self.elide, self._field_width())

    def paintEvent(self, event):
        self._update_tooltip()  # a panel that fills the box with its signals blocked changed the text unseen
        painter = QtWidgets.QStylePainter(self)
        option = QtWidgets.QStyleOptionComboBox()
        self.initStyleOption(option)
        option.currentText = self.shown_text()
        painter.drawComplexControl(QtWidgets.QStyle.CC_ComboBox, option)
        painter.drawControl(QtWidgets.QStyle.CE_ComboBoxLabel, option)


def narrow_combo(items=(), current=None, names=False):
    """A combo box that does not widen the panel to its longest item (the full text is in the list and the
    tool tip; a text too long is drawn elided, in the middle for `names` of objects)."""
    combo = ElidingComboBox(elide=QtCore.Qt.ElideMiddle if names else QtCore.Qt.ElideRight)
    combo.addItems(list(items))
    combo.setSizeAdjustPolicy(QtWidgets.QComboBox.AdjustToMinimumContentsLengthWithIcon)
    combo.setMinimumContentsLength(8)
    if current is not None:
        combo.setCurrentText(current)
    return combo


class PanelPlots:
    """Plots drawn for the panel's width (stacked, small type), under a button that shows the same plots side by
    side in a window of their own: the Combo View is too narrow to read a plot in detail."""

    def __init__(self, layout, height, draw, title, tooltip=""):
        """draw(figure, wide) draws the plots and says whether there were any; wide is False in the panel, True
        in the window (titled `title`)."""
        self.draw_plots, self.title, self.window = draw, title, None
        self.figure = Figure(dpi=80)
        self.canvas = FigureCanvasQTAgg(self.figure)
        self.canvas.setMinimumHeight(height)
        self.canvas.setToolTip(tooltip)
        self.window_button = QtWidgets.QPushButton("Plots in a window")
        self.window_button.setToolTip("the same plots, side by side, in a window you can resize and save")
        self.window_button.clicked.connect(self.open_window)
        layout.addWidget(self.window_button)
        layout.addWidget(self.canvas)

    def redraw(self):
        """Draws the panel's plots (and the window's, when it is open); clears them when there is nothing."""
        shown = bool(self.draw_plots(self.figure, False))
        if not shown:
            self.figure.clear()
        self.canvas.draw()
        self.window_button.setEnabled(shown)
        if self.window is not None and self.window.isVisible():
            self._draw_window()

    def open_window(self):
        from matplotlib.backends.backend_qtagg import NavigationToolbar2QT

        if self.window is None:
            self.window = QtWidgets.QDialog(FreeCADGui.getMainWindow())
            self.window.setWindowTitle(self.title)
            self.window_figure = Figure(figsize=(13, 5), dpi=90)
            canvas = FigureCanvasQTAgg(self.window_figure)
            layout = QtWidgets.QVBoxLayout(self.window)
            layout.addWidget(NavigationToolbar2QT(canvas, self.window))  # zoom, pan, save as PNG/SVG/PDF
            layout.addWidget(canvas)
            self.window.resize(1170, 520)
        self._draw_window()
        self.window.show()
        return self.window

    def _draw_window(self):
        self.draw_plots(self.window_figure, True)
        self.window_figure.canvas.draw()

    def close(self):
        if self.window is not None:
            self.window.close()
