"""What the task panels of the workbench share: the open panel for tests and macros (`Class.active`),
closing that ends the edit, and the frame of an analysis panel."""
import FreeCADGui
from matplotlib.backends.backend_qtagg import FigureCanvasQTAgg
from matplotlib.figure import Figure
from PySide2 import QtWidgets


def selected_faces():
    """(object, 'FaceN') of every face selected in the 3D view."""
    return [(s.Object, name) for s in FreeCADGui.Selection.getSelectionEx() for name in s.SubElementNames
            if name.startswith("Face")]


def freecad_message(error):
    """The text of an error to say in a panel: FreeCAD's own exceptions carry a dict whose sErrMsg is it."""
    detail = error.args[0] if error.args else error
    return detail.get("sErrMsg", str(detail)) if isinstance(detail, dict) else str(error)


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
        return int(QtWidgets.QDialogButtonBox.Close)

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


# FreeCAD's Combo View is about 275 px wide by default: every panel must fit it, as FreeCAD's own do.
COMBO_VIEW_WIDTH = 275


def narrow_form_layout():
    """A form layout whose rows put the field under its label when the panel is narrow."""
    layout = QtWidgets.QFormLayout()
    layout.setRowWrapPolicy(QtWidgets.QFormLayout.WrapLongRows)
    layout.setFieldGrowthPolicy(QtWidgets.QFormLayout.AllNonFixedFieldsGrow)
    return layout


def narrow_combo(items=(), current=None):
    """A combo box that does not widen the panel to its longest item (the full text is in the list)."""
    combo = QtWidgets.QComboBox()
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
