"""Path/CAM operations "Guide curve finishing" and "Parallel plane finishing".

Thin, as FreeCAD's own operations: properties wired to the core (hsmplanner.toolpaths) through
hsmplanner.app.finishing. Proxy classes are recorded in saved documents: never rename them.
"""
import FreeCAD

import hsmplanner

from . import finishing
from .clearance_moves import via_clearance
from .compat import cam_module
from .op_comments import mend_leading_comments
from .progress import freecad_progress
from .stock_heights import use_exact_stock_depths
from .property_limits import PropertyLimits

PathOp = cam_module("op")

SWEEPS = ["Upward", "Downward"]  # saved in documents: the core's Sweep names, capitalised
_DEFAULTS = hsmplanner._core.FinishingSettings()  # each default written once, in C++
PATTERNS = ["ZigZag", "OneWay"]


# The task page's ranges (mm).
LIMITS = {"CuspHeight": (0.001, 10.0), "Tolerance": (0.001, 1.0)}


def cusp_limits(tool_controller):
    """The cusp heights the core takes with the controller's ball: under its radius (a cusp as high as the
    radius leaves no surface between passes), within LIMITS; LIMITS alone without a tool diameter."""
    low, high = LIMITS["CuspHeight"]
    diameter = float(getattr(getattr(tool_controller, "Tool", None), "Diameter", 0.0) or 0.0)
    return (low, min(high, 0.5 * diameter - low)) if diameter > 4.0 * low else (low, high)


class _FinishingOp(PropertyLimits, PathOp.ObjectOp):
    """What both finishing operations share: cusp, tolerance, sweeping, pattern; a ball-end tool."""

    LIMITS = LIMITS

    def opFeatures(self, obj):
        return PathOp.FeatureTool | PathOp.FeatureHeights | PathOp.FeatureCoolant

    def initFinishing(self, obj):
        obj.addProperty("App::PropertyLength", "CuspHeight", "Finishing", "largest cusp left on the surface")
        obj.CuspHeight = _DEFAULTS.cusp_height
        obj.addProperty("App::PropertyLength", "Tolerance", "Finishing", "chordal tolerance of the G1 points")
        obj.Tolerance = _DEFAULTS.tolerance
        obj.addProperty("App::PropertyEnumeration", "Sweep", "Finishing", "passes climb or descend the face")
        obj.Sweep = SWEEPS
        obj.addProperty("App::PropertyEnumeration", "Pattern", "Finishing", "zigzag or one-way passes")
        obj.Pattern = PATTERNS
        obj.addProperty("App::PropertyInteger", "Passes", "Result", "passes of the last computation")
        obj.setEditorMode("Passes", 1)
        obj.addProperty("App::PropertyFloatList", "PassLengths", "Result", "length of each pass, mm")
        obj.setEditorMode("PassLengths", 1)

    def opUpdateDepths(self, obj):
        use_exact_stock_depths(obj, getattr(self, "job", None))

    def options(self, obj, part_top):
        finishing.check_tool(obj.ToolController, self.tool)
        clearance = max(1.0, obj.SafeHeight.Value - part_top) if hasattr(obj, "SafeHeight") else 5.0
        return dict(tool_diameter=2.0 * self.radius, cusp_height=obj.CuspHeight.Value,
                    tolerance=obj.Tolerance.Value, sweep=obj.Sweep.lower(), zigzag=obj.Pattern == "ZigZag",
                    clearance=clearance)

    def emit(self, obj, moves, stats):
        mend_leading_comments(self.commandlist, obj)
        for warning in stats["warnings"]:
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, warning))
        obj.Passes = stats["passes"]
        obj.PassLengths = list(stats["pass_lengths"])
        commands = finishing.moves_to_commands(moves, self.horizFeed, self.vertFeed)
        self.commandlist.extend(via_clearance(commands, obj.ClearanceHeight.Value))

    def opSetDefaultValues(self, obj, job):
        obj.Sweep = "Upward"
        obj.Pattern = "ZigZag"
        obj.ToolController = finishing.finishing_controller(job, obj.ToolController)
        obj.OpToolDiameter = obj.ToolController.Tool.Diameter


class ObjectGuideCurveFinishing(_FinishingOp):
    def initOperation(self, obj):
        obj.addProperty("App::PropertyLink", "Net", "Guide curves", "the Guide curve net whose areas are machined")
        obj.addProperty("App::PropertyEnumeration", "Areas", "Guide curves", "which areas of the net")
        obj.Areas = finishing.AREA_CHOICES
        self.initFinishing(obj)

    def opExecute(self, obj):
        if obj.Net is None:
            raise ValueError("no Guide curve net: link one (Net) to give the areas")
        shape, face = finishing.net_part(obj.Net)
        areas = finishing.net_areas(obj.Net, obj.Areas)
        direction = tuple(obj.Net.ChosenDirection)
        with freecad_progress("%s: guide-curve finishing" % obj.Label) as progress:
            moves, stats = hsmplanner.guide_finishing(shape, face, areas, direction, progress=progress,
                                                      **self.options(obj, finishing.exact_top(shape)))
        self.emit(obj, moves, stats)


class ObjectParallelPlaneFinishing(_FinishingOp):
    def initOperation(self, obj):
        obj.addProperty("App::PropertyLinkSub", "Face", "Parallel planes", "the bottom face to finish")
        obj.addProperty("App::PropertyAngle", "Angle", "Parallel planes", "direction of the planes from X")
        self.initFinishing(obj)

    def opExecute(self, obj):
        if not obj.Face:
            raise ValueError("no face to finish: set Face to the bottom face (e.g. the model's Face4)")
        part, subs = obj.Face
        face = subs[0] if not isinstance(subs, str) else subs
        with freecad_progress("%s: parallel-plane finishing" % obj.Label) as progress:
            moves, stats = hsmplanner.parallel_finishing(part.Shape, face, obj.Angle.Value, progress=progress,
                                                         **self.options(obj, finishing.exact_top(part.Shape)))
        self.emit(obj, moves, stats)


def SetupProperties():
    return ["CuspHeight", "Tolerance", "Sweep", "Pattern"]


def CreateGuideCurveFinishing(name, obj=None, parentJob=None):
    if obj is None:
        obj = FreeCAD.ActiveDocument.addObject("Path::FeaturePython", name)
    obj.Proxy = ObjectGuideCurveFinishing(obj, name, parentJob)
    return obj


def CreateParallelPlaneFinishing(name, obj=None, parentJob=None):
    if obj is None:
        obj = FreeCAD.ActiveDocument.addObject("Path::FeaturePython", name)
    obj.Proxy = ObjectParallelPlaneFinishing(obj, name, parentJob)
    return obj
