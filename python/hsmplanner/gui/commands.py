"""FreeCAD commands of the HSM Planner workbench."""
import FreeCAD
import FreeCADGui

from hsmplanner.resources import icon

COMMAND_NAMES = ["HSM_MasterBottomFeature", "HSM_GuideCurveNet", "HSM_GuideCurveFinishing",
                 "HSM_ParallelPlaneFinishing", "HSM_MachiningDirection", "HSM_FeedRateAnalysis", "HSM_CycleTime",
                 "Separator",
                 "HSM_SlantedSlotBlock", "HSM_Impeller", "HSM_RoughingVolume", "HSM_VolumeRoughing",
                 "HSM_RoughingStudy", "HSM_StrategyStudy"]


class CommandMasterBottomFeature:
    """Add the parametric master bottom feature (the guidance-curve paper's test part) to the document."""

    def GetResources(self):
        return {
            "Pixmap": icon("MasterBottomFeature"),
            "MenuText": "Master bottom feature",
            "ToolTip": "Add the parametric test part of the guidance-curve paper: a curved bottom between two "
                       "curved, non-parallel flanks, open at both ends",
        }

    def IsActive(self):
        return True

    def Activated(self):
        from hsmplanner.app import master_feature_object
        from hsmplanner.gui.view_providers import ViewProviderMasterBottomFeature

        document = FreeCAD.ActiveDocument or FreeCAD.newDocument("HSMPlanner")
        document.openTransaction("Add master bottom feature")
        try:
            obj = master_feature_object.create(document)
            ViewProviderMasterBottomFeature(obj.ViewObject)
        finally:
            document.commitTransaction()
        FreeCADGui.SendMsgToActiveView("ViewFit")
        FreeCADGui.activeDocument().activeView().viewIsometric()
        return obj


class CommandGuideCurveNet:
    """Add a guide curve net and open its panel (the selected edges and face are taken as its inputs)."""

    def GetResources(self):
        return {
            "Pixmap": icon("GuideCurveNet"),
            "MenuText": "Guide curve net",
            "ToolTip": "Intermediate curves between two boundary edges of a bottom face, with K and P set live; "
                       "select the two edges (and the bottom face) first, or pick them in the panel",
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from hsmplanner.app import guide_curve_net_object
        from hsmplanner.gui.guide_curve_net_panel import ADD_TRANSACTION
        from hsmplanner.gui.view_providers import ViewProviderGuideCurveNet

        document = FreeCAD.ActiveDocument
        document.openTransaction(ADD_TRANSACTION)
        obj = guide_curve_net_object.create(document)
        view_provider = ViewProviderGuideCurveNet(obj.ViewObject)
        view_provider.created = True
        FreeCADGui.ActiveDocument.setEdit(obj.Name)
        return obj


def open_analysis(proxy_class, link, target, transaction, make):
    """Opens the panel of `target`'s analysis: the one the document has (a `proxy_class` object whose `link`
    is `target`), else a new one from make(target) in one undo step named `transaction`. A command run again
    opens what it made before rather than adding another object."""
    document = target.Document
    obj = next((o for o in document.Objects if type(getattr(o, "Proxy", None)).__name__ == proxy_class
                and getattr(o, link, None) == target), None)
    if obj is None:
        document.openTransaction(transaction)
        try:
            obj = make(target)
        finally:
            document.commitTransaction()
    FreeCADGui.ActiveDocument.setEdit(obj.Name)
    return obj


class CommandFeedRateAnalysis:
    """Simulate the selected Job or operation on a machine model: feed-rate map, histograms, times."""

    def GetResources(self):
        return {
            "Pixmap": icon("FeedRateAnalysis"),
            "MenuText": "Feed-rate analysis",
            "ToolTip": "Simulate what the machine really does on the selected Job or operation: machining time "
                       "against length/feed, feed classes, and a map of the reached feed on the path",
        }

    @staticmethod
    def selected_source():
        from hsmplanner.app.feedrate import is_simulatable

        selection = FreeCADGui.Selection.getSelection()
        return selection[0] if len(selection) == 1 and is_simulatable(selection[0]) else None

    def IsActive(self):
        return self.selected_source() is not None

    def Activated(self):
        from hsmplanner.app import feedrate_object
        from hsmplanner.gui.view_providers import ViewProviderFeedRateAnalysis

        def make(source):
            obj = feedrate_object.create(source, document=source.Document)
            ViewProviderFeedRateAnalysis(obj.ViewObject)
            obj.ViewObject.Proxy.redraw(obj)
            return obj

        return open_analysis("FeedRateAnalysis", "Source", self.selected_source(), "Feed-rate analysis", make)


class CommandCycleTime:
    """The cycle time of the selected CAM Job (or of the Job of the selected operation): per operation CAM's
    estimate, length / feed and the simulated time."""

    def GetResources(self):
        return {
            "Pixmap": icon("CycleTime"),
            "MenuText": "Cycle time",
            "ToolTip": "Time the selected CAM Job on a machine: per operation CAM's estimate, length / feed and the "
                       "simulated time (what the machine does), with what held the speed; kept current on recompute",
        }

    @staticmethod
    def selected_job():
        """The selected Job, or the Job of the selected operation; None otherwise."""
        from hsmplanner.app.feedrate import is_job
        from hsmplanner.app.posts.writer import job_of

        selection = FreeCADGui.Selection.getSelection()
        job = job_of(selection) if len(selection) == 1 else None
        return job if is_job(job) else None

    def IsActive(self):
        return self.selected_job() is not None

    def Activated(self):
        from hsmplanner.app import cycle_time_object
        from hsmplanner.gui.view_providers import ViewProviderCycleTime

        def make(job):
            obj = cycle_time_object.create(job, document=job.Document)
            ViewProviderCycleTime(obj.ViewObject)
            return obj

        return open_analysis("CycleTimeAnalysis", "Job", self.selected_job(), "Cycle time", make)


class CommandMachiningDirection:
    """The raster angle of parallel-plane finishing for the selected face, by directional beams."""

    def GetResources(self):
        return {
            "Pixmap": icon("MachiningDirection"),
            "MenuText": "Machining direction",
            "ToolTip": "Choose the angle of parallel planes over the selected face: directional beams, the least "
                       "predicted time, or planes simulated on the machine; arrows of the best local direction",
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from hsmplanner.app import direction_object
        from hsmplanner.gui.task_panel import selected_faces
        from hsmplanner.gui.view_providers import ViewProviderMachiningDirection

        document = FreeCAD.ActiveDocument
        document.openTransaction("Machining direction")
        try:
            obj = direction_object.create(document=document)
            ViewProviderMachiningDirection(obj.ViewObject)
            faces = selected_faces()
            if len(faces) == 1:
                obj.Face = (faces[0][0], [faces[0][1]])
                obj.recompute()
        finally:
            document.commitTransaction()
        FreeCADGui.ActiveDocument.setEdit(obj.Name)
        return obj


class _CommandRoughingTestPart:
    """Add a test part of 5-axis roughing and its stock to the document. The stock is hidden (its faces lie on
    the part's): Space shows it, as a wireframe."""

    NAME, MENU, TIP = "", "", ""
    BUILDER, VIEW_PROVIDER = "", ""  # names in app.roughing.parts and gui.view_providers

    def GetResources(self):
        return {"Pixmap": icon(self.NAME), "MenuText": self.MENU, "ToolTip": self.TIP}

    def IsActive(self):
        return True

    def create(self, document):
        from hsmplanner.app.roughing import parts as roughing_parts
        from hsmplanner.gui import view_providers

        part, stock = getattr(roughing_parts, self.BUILDER)(document)
        getattr(view_providers, self.VIEW_PROVIDER)(part.ViewObject)
        return part, stock

    def Activated(self):
        from PySide import QtCore, QtWidgets

        from hsmplanner.gui.view_providers import ViewProviderTestPartStock

        document = FreeCAD.ActiveDocument or FreeCAD.newDocument("HSMPlanner")
        document.openTransaction("Add %s" % self.MENU.lower())
        QtWidgets.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)  # the impeller takes seconds
        try:
            part, stock = self.create(document)
            ViewProviderTestPartStock(stock.ViewObject)
            stock.ViewObject.DisplayMode = "Wireframe"
            stock.ViewObject.LineColor = (0.35, 0.35, 0.35)
            stock.ViewObject.Visibility = False
        finally:
            QtWidgets.QApplication.restoreOverrideCursor()
            document.commitTransaction()
        FreeCADGui.SendMsgToActiveView("ViewFit")
        FreeCADGui.activeDocument().activeView().viewIsometric()
        return part, stock


class CommandSlantedSlotBlock(_CommandRoughingTestPart):
    NAME, MENU = "SlantedSlotBlock", "Slanted slot block"
    TIP = ("Add the roughing test part: a block with a slot tilted from Z (a tool along Z cannot reach under its "
           "overhang), and its stock")

    BUILDER, VIEW_PROVIDER = "create_slanted_slot_block", "ViewProviderSlantedSlotBlock"


class CommandImpeller(_CommandRoughingTestPart):
    NAME, MENU = "Impeller", "Impeller"
    TIP = ("Add the roughing paper's test part: a radial compressor impeller (7 undercut channels) and its blank; "
           "takes a few seconds")

    BUILDER, VIEW_PROVIDER = "create_impeller", "ViewProviderImpeller"


class CommandRoughingVolume:
    """The volume to remove between the selected stock and part, its faces classed, and its partition."""

    def GetResources(self):
        return {
            "Pixmap": icon("RoughingVolume"),
            "MenuText": "Roughing volume",
            "ToolTip": "The volume to remove (stock − part), its faces coloured crossable / facing crossable / not "
                       "crossable, cut into sub-volumes by one of the five slicings of 5-axis roughing; select the "
                       "part and its stock first (two solids), or choose them in the panel",
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from hsmplanner.app.roughing import volume as roughing_object
        from hsmplanner.gui.view_providers import ViewProviderRoughingVolume

        document = FreeCAD.ActiveDocument
        picked = [o for o in FreeCADGui.Selection.getSelection()
                  if roughing_object.has_solid(o) or roughing_object.is_job(o)]
        part = stock = None
        if len(picked) == 2:
            part, stock = roughing_object.part_and_stock(*picked)
        elif len(picked) == 1:
            part = picked[0]
        document.openTransaction("Roughing volume")
        obj = roughing_object.create(part, stock, document=document, recompute=False)
        view_provider = ViewProviderRoughingVolume(obj.ViewObject)
        if len(picked) == 2:
            try:
                document.recompute()
            finally:
                document.commitTransaction()
            if not obj.VolumeShape.isNull():
                show_result(obj)
            return obj
        view_provider.created = True
        FreeCADGui.ActiveDocument.setEdit(obj.Name)
        return obj


def show_result(obj):
    """The volume over the part: its stock hidden (it would hide everything)."""
    from hsmplanner.app.roughing.volume import is_job, job_stock

    stock = job_stock(obj.Stock) if is_job(obj.Stock) else obj.Stock
    if stock is not None and stock.ViewObject is not None:
        stock.ViewObject.Visibility = False


def register_commands():
    FreeCADGui.addCommand("HSM_MasterBottomFeature", CommandMasterBottomFeature())
    FreeCADGui.addCommand("HSM_GuideCurveNet", CommandGuideCurveNet())
    FreeCADGui.addCommand("HSM_FeedRateAnalysis", CommandFeedRateAnalysis())
    FreeCADGui.addCommand("HSM_CycleTime", CommandCycleTime())
    FreeCADGui.addCommand("HSM_MachiningDirection", CommandMachiningDirection())
    FreeCADGui.addCommand("HSM_SlantedSlotBlock", CommandSlantedSlotBlock())
    FreeCADGui.addCommand("HSM_Impeller", CommandImpeller())
    FreeCADGui.addCommand("HSM_RoughingVolume", CommandRoughingVolume())
    from hsmplanner.gui.roughing_study_panel import CommandRoughingStudy

    FreeCADGui.addCommand("HSM_RoughingStudy", CommandRoughingStudy())
    from hsmplanner.gui.strategy_study_panel import CommandStrategyStudy

    FreeCADGui.addCommand("HSM_StrategyStudy", CommandStrategyStudy())
    from hsmplanner.gui import finishing_ops_gui

    finishing_ops_gui.register_commands()
