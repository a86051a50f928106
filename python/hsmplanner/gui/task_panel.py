"""What the task panels of the workbench share: the open panel for tests and macros (`Class.active`),
closing that ends the edit, and the frame of an analysis panel."""
import FreeCADGui
from PySide2 import QtWidgets


def selected_faces():
    """(object, 'FaceN') of every face selected in the 3D view."""
    return [(s.Object, name) for s in FreeCADGui.Selection.getSelectionEx() for name in s.SubElementNames
            if name.startswith("Face")]


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

    def __init__(self, obj):
        self.obj = obj
        self.form = self._build_form()
        self.refresh()
        self.opened()

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
