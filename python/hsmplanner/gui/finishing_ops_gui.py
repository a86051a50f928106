"""Task panels and commands of our Path operations (guide-curve and parallel-plane finishing, volume
roughing), on FreeCAD's own operation GUI (PathOpGui): the Job's tool controllers, heights and coolant pages
come with them."""
import os

import FreeCAD
import FreeCADGui
from PySide import QtWidgets

from hsmplanner import feedsim
from hsmplanner.app import finishing, finishing_ops
from hsmplanner.app.roughing import commands as roughing_commands, operation as roughing_op
from hsmplanner.app.compat import cam_module
from hsmplanner.resources import icon

from .task_panel import compact_buttons, narrow_combo, narrow_form_layout
from .tip_path import TipPathView

PathOpGui = cam_module("op_gui")


def _spin(value, limits, decimals=3, suffix=" mm"):
    box = QtWidgets.QDoubleSpinBox()
    box.setDecimals(decimals)
    box.setRange(*limits)
    box.setSingleStep(10 ** -decimals)
    box.setSuffix(suffix)
    box.setValue(value)
    return box


class _FinishingPage(PathOpGui.TaskPanelPage):
    """Tool controller, coolant, cusp height, tolerance, sweeping and pattern; subclasses add their own rows."""

    def getForm(self):
        form = QtWidgets.QWidget()
        layout = QtWidgets.QFormLayout(form)
        form.toolController = QtWidgets.QComboBox()
        form.coolantController = QtWidgets.QComboBox()
        layout.addRow("Tool controller", form.toolController)
        layout.addRow("Coolant", form.coolantController)
        self.addRows(form, layout)
        form.cusp = _spin(0.01, finishing_ops.LIMITS["CuspHeight"])
        form.tolerance = _spin(0.01, finishing_ops.LIMITS["Tolerance"])
        form.sweep = QtWidgets.QComboBox()
        form.sweep.addItems(finishing_ops.SWEEPS)
        form.pattern = QtWidgets.QComboBox()
        form.pattern.addItems(finishing_ops.PATTERNS)
        layout.addRow("Cusp height", form.cusp)
        layout.addRow("Tolerance", form.tolerance)
        layout.addRow("Sweeping", form.sweep)
        layout.addRow("Pattern", form.pattern)
        return form

    def addRows(self, form, layout):
        pass

    def getFields(self, obj):
        self.updateToolController(obj, self.form.toolController)
        self.updateCoolant(obj, self.form.coolantController)
        self.form.cusp.setRange(*finishing_ops.cusp_limits(obj.ToolController))
        obj.CuspHeight = self.form.cusp.value()
        obj.Tolerance = self.form.tolerance.value()
        obj.Sweep = self.form.sweep.currentText()
        obj.Pattern = self.form.pattern.currentText()

    def setFields(self, obj):
        self.setupToolController(obj, self.form.toolController)
        self.setupCoolant(obj, self.form.coolantController)
        self.form.cusp.setRange(*finishing_ops.cusp_limits(obj.ToolController))
        self.form.cusp.setValue(obj.CuspHeight.Value)
        self.form.tolerance.setValue(obj.Tolerance.Value)
        self.form.sweep.setCurrentText(obj.Sweep)
        self.form.pattern.setCurrentText(obj.Pattern)

    def getSignalsForUpdate(self, obj):
        f = self.form
        return [f.toolController.currentIndexChanged, f.coolantController.currentIndexChanged, f.cusp.valueChanged,
                f.tolerance.valueChanged, f.sweep.currentIndexChanged, f.pattern.currentIndexChanged]


class GuideCurveFinishingPage(_FinishingPage):
    def addRows(self, form, layout):
        form.net = QtWidgets.QComboBox()
        form.areas = QtWidgets.QComboBox()
        form.areas.addItems(finishing.AREA_CHOICES)
        layout.addRow("Guide curve net", form.net)
        layout.addRow("Areas", form.areas)

    def nets(self):
        return [o for o in FreeCAD.ActiveDocument.Objects
                if hasattr(o, "Proxy") and type(o.Proxy).__name__ == "GuideCurveNet"]

    def getFields(self, obj):
        super().getFields(obj)
        nets = {n.Label: n for n in self.nets()}
        obj.Net = nets.get(self.form.net.currentText())
        obj.Areas = self.form.areas.currentText()

    def setFields(self, obj):
        super().setFields(obj)
        self.form.net.blockSignals(True)
        self.form.net.clear()
        self.form.net.addItems([n.Label for n in self.nets()])
        self.form.net.blockSignals(False)
        if obj.Net is not None:
            self.form.net.setCurrentText(obj.Net.Label)
        self.form.areas.setCurrentText(obj.Areas)

    def getSignalsForUpdate(self, obj):
        return super().getSignalsForUpdate(obj) + [self.form.net.currentIndexChanged,
                                                   self.form.areas.currentIndexChanged]


class ParallelPlaneFinishingPage(_FinishingPage):
    def addRows(self, form, layout):
        form.face = QtWidgets.QLineEdit()
        form.face.setReadOnly(True)
        form.useSelection = QtWidgets.QPushButton("Use the selected face")
        form.angle = _spin(0.0, (0.0, 180.0), decimals=1, suffix=" °")
        form.angle.setMinimum(0.0)
        layout.addRow("Bottom face", form.face)
        layout.addRow("", form.useSelection)
        layout.addRow("Angle from X", form.angle)
        form.useSelection.clicked.connect(self.useSelection)

    def useSelection(self):
        for selection in FreeCADGui.Selection.getSelectionEx():
            faces = [s for s in selection.SubElementNames if s.startswith("Face")]
            if faces:
                self.obj.Face = (selection.Object, faces[0])
                self.form.face.setText("%s: %s" % (selection.Object.Label, faces[0]))
                self.setDirty()
                return

    def getFields(self, obj):
        super().getFields(obj)
        obj.Angle = self.form.angle.value()

    def setFields(self, obj):
        super().setFields(obj)
        self.form.angle.setValue(obj.Angle.Value)
        if obj.Face:
            subs = obj.Face[1]
            self.form.face.setText("%s: %s" % (obj.Face[0].Label, subs[0] if not isinstance(subs, str) else subs))

    def getSignalsForUpdate(self, obj):
        return super().getSignalsForUpdate(obj) + [self.form.angle.valueChanged]


NO_REST = "(none: the whole volume)"


class VolumeRoughingPage(PathOpGui.TaskPanelPage):
    """Tool controller (a bullnose is the torus), coolant, the Roughing volume, the machine of the A/B/C, the
    radial engagement, allowance and ramp angle; the results of the last computation."""

    def getForm(self):
        form = QtWidgets.QWidget()
        layout = narrow_form_layout()
        form.setLayout(layout)
        form.toolController, form.volume, form.machine = (narrow_combo(names=True) for _ in range(3))
        form.coolantController = narrow_combo()
        form.toolController.setToolTip("the tool controller: a torus (bullnose), flat or ball end mill with a feed")
        form.volume.setToolTip("the Roughing volume whose sub-volumes the passes cut (its strategy, S1-S5)")
        form.machine.setToolTip("the machine whose rotary axes the moves' A/B/C are: post with --machine=this")
        form.engagement = _spin(70.0, roughing_op.LIMITS["RadialEngagement"], decimals=0, suffix=" %")
        form.engagement.setToolTip("radial engagement: the step between passes, % of the tool diameter")
        form.allowance = _spin(0.5, roughing_op.LIMITS["Allowance"], decimals=2)
        form.allowance.setToolTip("stock left on the part for finishing")
        form.ramp = _spin(3.0, roughing_op.LIMITS["RampAngle"], decimals=1, suffix=" °")
        form.ramp.setToolTip("entries into material ramp at most this steep")
        form.stepUp = _spin(1.0, roughing_op.LIMITS["StepUpMinimum"], decimals=2)
        form.stepUp.setToolTip("step-up: intermediate levels inside each slice where the part leans, at least this "
                               "far apart; 0: one level per slice (the paper's)")
        form.scallop = _spin(0.25, roughing_op.LIMITS["StepUpScallop"], decimals=2)
        form.scallop.setToolTip("step-up levels are added while a leaning wall keeps a staircase thicker than this")
        form.pushOut = _spin(0.0, roughing_op.LIMITS["PushOut"], decimals=2)
        form.pushOut.setToolTip("push-out: how far each level's outline may move from the safe keep-out towards the "
                                "part, to the tool's exact clearance (less stock left by the outer passes); 0: off")
        form.restFrom = narrow_combo(names=True)
        form.restFrom.setToolTip("rest roughing: cut only the stock this Volume roughing (before this one) left")
        for label, widget in (("Tool", form.toolController), ("Coolant", form.coolantController),
                              ("Volume", form.volume), ("Machine", form.machine), ("Engagement", form.engagement),
                              ("Allowance", form.allowance), ("Ramp angle", form.ramp), ("Step-up", form.stepUp),
                              ("Scallop", form.scallop), ("Push-out", form.pushOut), ("Rest from", form.restFrom)):
            layout.addRow(label, widget)
        form.result = QtWidgets.QLabel()
        form.result.setWordWrap(True)
        layout.addRow(form.result)  # the whole row: a label column would leave it half the width
        return form

    def modifyStandardButtons(self, buttonBox):
        compact_buttons(buttonBox)

    def volumes(self):
        return [o for o in FreeCAD.ActiveDocument.Objects
                if hasattr(o, "Proxy") and type(o.Proxy).__name__ == "RoughingVolume"]

    def roughings_before(self, obj):
        """The Volume roughing operations this one may follow (not itself)."""
        return [o for o in FreeCAD.ActiveDocument.Objects if roughing_op.is_volume_roughing(o) and o is not obj]

    def getFields(self, obj):
        self.updateToolController(obj, self.form.toolController)
        self.updateCoolant(obj, self.form.coolantController)
        volumes = {v.Label: v for v in self.volumes()}
        obj.Volume = volumes.get(self.form.volume.currentText())
        obj.Machine = self.form.machine.currentText()
        obj.RadialEngagement = int(self.form.engagement.value())
        obj.Allowance = self.form.allowance.value()
        obj.RampAngle = self.form.ramp.value()
        obj.StepUpMinimum = self.form.stepUp.value()
        obj.StepUpScallop = self.form.scallop.value()
        obj.PushOut = self.form.pushOut.value()
        before = {o.Label: o for o in self.roughings_before(obj)}
        obj.RestFrom = before.get(self.form.restFrom.currentText())

    def setFields(self, obj):
        self.setupToolController(obj, self.form.toolController)
        self.setupCoolant(obj, self.form.coolantController)
        for box, items, current in ((self.form.volume, [v.Label for v in self.volumes()],
                                     obj.Volume.Label if obj.Volume is not None else None),
                                    (self.form.machine, obj.getEnumerationsOfProperty("Machine"), obj.Machine),
                                    (self.form.restFrom, [NO_REST] + [o.Label for o in self.roughings_before(obj)],
                                     obj.RestFrom.Label if obj.RestFrom is not None else NO_REST)):
            box.blockSignals(True)
            box.clear()
            box.addItems(items)
            if current:
                box.setCurrentText(current)
            box.blockSignals(False)
        self.form.engagement.setValue(obj.RadialEngagement)
        self.form.allowance.setValue(obj.Allowance.Value)
        self.form.ramp.setValue(obj.RampAngle.Value)
        self.form.stepUp.setValue(obj.StepUpMinimum.Value)
        self.form.scallop.setValue(obj.StepUpScallop.Value)
        self.form.pushOut.setValue(obj.PushOut.Value)
        self.form.result.setText("%d passes, %.0f mm of cut; closest to the part %.3f mm" % (
            obj.Passes, obj.CuttingLength.Value, obj.ClosestApproach.Value) if obj.Passes else "")

    def getSignalsForUpdate(self, obj):
        f = self.form
        return [f.toolController.currentIndexChanged, f.coolantController.currentIndexChanged,
                f.volume.currentIndexChanged, f.machine.currentIndexChanged, f.engagement.valueChanged,
                f.allowance.valueChanged, f.ramp.valueChanged, f.stepUp.valueChanged, f.scallop.valueChanged,
                f.pushOut.valueChanged, f.restFrom.currentIndexChanged]


def _no_gate():
    """Selection for these operations is free (PathSelection only knows FreeCAD's own operations)."""
    FreeCADGui.Selection.removeSelectionGate()


def _base_state_methods():
    """The save and restore methods of FreeCAD's operation view provider: dumps/loads from 1.0 on, only
    __getstate__/__setstate__ on 0.20. Asked by name, not by hasattr on an instance: from Python 3.11 every
    object has an __getstate__, which returns the live __dict__ (the view object, the panel) instead of the
    operation's four saved strings."""
    base = PathOpGui.ViewProvider
    if "dumps" in vars(base):
        return base.dumps, base.loads
    return base.__getstate__, base.__setstate__


class ViewProviderFinishing(PathOpGui.ViewProvider):
    """FreeCAD's operation view provider, saving the icon by name: a saved document holds no path into the
    saving user's files (another user, or a moved install, would see FreeCAD's generic icon)."""

    _base_dumps, _base_loads = _base_state_methods()

    def getIcon(self):
        """Our icon; FreeCAD's "inactive operation" icon once CAM's Toggle Operation has disabled it."""
        return self.OpIcon if self.Object.Active else super().getIcon()

    def dumps(self):
        state = dict(self._base_dumps())
        state["OpIcon"] = icon_name(state["OpIcon"])
        return state

    def loads(self, state):
        self._base_loads(state)
        self.OpIcon = icon(icon_name(self.OpIcon))  # also mends documents saved with a path

    __getstate__, __setstate__ = dumps, loads  # the FreeCAD 0.20 spelling

    def getSelectionFactory(self):
        return _no_gate


class ViewProviderVolumeRoughing(TipPathView, ViewProviderFinishing):
    """The operation's view with ticks of the tool axis every 5 mm of feed moves over its path: a 4- or 5-axis
    path shows the tool turn (the angles of the operation's Machine turned back into axes). A path with A/B/C
    is drawn where the tool tip goes (gui/tip_path.py: FreeCAD's drawing would turn it off the part)."""

    TICK_EVERY_MM, TICK_LENGTH_MM = 5.0, 4.0

    def attach(self, vobj):
        super().attach(vobj)
        self.ticks = None
        self.show_ticks(vobj.Object)

    def updateData(self, obj, prop):
        super().updateData(obj, prop)
        if prop in ("Path", "Machine"):
            self.show_ticks(obj)

    def onChanged(self, vobj, prop):
        super().onChanged(vobj, prop)
        if prop == "Visibility":  # the ticks hang off the root node: they follow the path's visibility by hand
            self.show_ticks(vobj.Object)

    def show_ticks(self, obj):
        from hsmplanner.gui.feedmap import line_set

        root = getattr(getattr(self, "vobj", None), "RootNode", None)
        if root is None:
            return
        if getattr(self, "ticks", None) is not None:
            root.removeChild(self.ticks)
            self.ticks = None
        try:
            machine = feedsim.load_machine(obj.Machine)
            segments = roughing_commands.tool_axis_ticks(obj.Path.Commands, machine, self.TICK_EVERY_MM,
                                                         self.TICK_LENGTH_MM)
        except (ValueError, AttributeError, RuntimeError) as error:  # no path yet, a machine file gone
            FreeCAD.Console.PrintLog("%s: no tool-axis ticks: %s\n" % (obj.Label, error))
            return
        if len(segments) and getattr(self.vobj, "Visibility", True):
            self.ticks = line_set(list(segments), width=1.0)
            root.addChild(self.ticks)


def icon_name(path_or_name):
    """'GuideCurveFinishing' from a name or from any path to its .svg (documents saved before 0.1 hold paths)."""
    return os.path.splitext(os.path.basename(str(path_or_name)))[0]


class CommandFinishing:
    def __init__(self, name, factory, page, icon_name, menu, tooltip, view_provider=None):
        self.res = PathOpGui.CommandResources(name, factory, page, icon_name, menu, None, tooltip)
        self.icon = icon(icon_name)
        self.view_provider = view_provider or ViewProviderFinishing

    def GetResources(self):
        return {"Pixmap": self.icon, "MenuText": self.res.menuText, "ToolTip": self.res.toolTip}

    def IsActive(self):
        document = FreeCAD.ActiveDocument
        return document is not None and any(hasattr(o, "Operations") for o in document.Objects)

    def Activated(self):
        from .task_panel import selected_faces

        document = FreeCAD.ActiveDocument
        faces = selected_faces()  # picked before the command: creating the operation clears the selection
        document.openTransaction("Create %s" % self.res.name)
        obj = self.res.objFactory(self.res.name, obj=None, parentJob=None)
        if faces and hasattr(obj, "Face"):
            obj.Face = faces[0]
        view_provider = self.view_provider(obj.ViewObject, self.res)
        view_provider.OpIcon = self.icon
        obj.ViewObject.Proxy = view_provider
        document.commitTransaction()
        obj.ViewObject.Document.setEdit(obj.ViewObject, 0)
        return obj


def add_volume_roughing(job):
    """A new Volume roughing operation in `job` with the view provider the command gives it (tip path, ticks),
    for code that adds one without the command's panel."""
    resources = COMMANDS["HSM_VolumeRoughing"]
    op = roughing_op.CreateVolumeRoughing("VolumeRoughing", parentJob=job)
    op.ViewObject.Proxy = resources.view_provider(op.ViewObject, resources.res)
    op.ViewObject.Proxy.OpIcon = resources.icon
    return op


COMMANDS = {
    "HSM_GuideCurveFinishing": CommandFinishing(
        "GuideCurveFinishing", finishing_ops.CreateGuideCurveFinishing, GuideCurveFinishingPage, "GuideCurveFinishing",
        "Guide curve finishing", "Ball-end passes morphed between the curves of a Guide curve net, area by area"),
    "HSM_ParallelPlaneFinishing": CommandFinishing(
        "ParallelPlaneFinishing", finishing_ops.CreateParallelPlaneFinishing, ParallelPlaneFinishingPage,
        "ParallelPlaneFinishing", "Parallel plane finishing", "Ball-end passes in parallel planes at an angle"),
    "HSM_VolumeRoughing": CommandFinishing(
        "VolumeRoughing", roughing_op.CreateVolumeRoughing, VolumeRoughingPage, "VolumeRoughing", "Volume roughing",
        "Contour-parallel passes through the sub-volumes of a Roughing volume (S1-S5), the tool axis normal "
        "to their slicing surfaces, on a 3-, 4- or 5-axis machine", ViewProviderVolumeRoughing),
}


def register_commands():
    for name, command in COMMANDS.items():
        FreeCADGui.addCommand(name, command)
