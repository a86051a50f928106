"""Parametric "Machining direction" analysis (App::FeaturePython): the raster angle of parallel-plane
finishing of a picked face, chosen by directional beams. Thin: properties wired to hsmplanner.direction.
The per-point result is kept in memory (not in the file) and rebuilt on recompute; the view provider draws
it as arrows of the local best direction. The Proxy class name is saved in documents: never rename it.
"""
import FreeCAD

from hsmplanner import _core, direction, feedsim

from .properties import add_inputs, add_results, refresh_choices
from . import finishing

from .progress import freecad_progress
from .property_limits import PropertyLimits
from .proxy_state import InMemoryResult

TYPE_NAME = "App::FeaturePython"
DEFAULT_MACHINE = feedsim.DEFAULT_MACHINE
# The core's defaults, in the units of the properties (each default is written once, in C++).
_CONDITIONS, _SAMPLING = _core.CuttingConditions(), _core.DirectionSettings()
ACCELERATION_ONLY = "(acceleration only)"
FEED_FROM = ["Programmed feed", "Feed per tooth"]
CHOICES = ["Directional beams", "Least predicted time", "Fastest simulated"]

_INPUTS = [
    # type, name, group, tooltip, default
    ("App::PropertyLinkSub", "Face", "Face", "the face to finish with parallel planes", None),
    ("App::PropertyLength", "ToolDiameter", "Tool", "ball-end diameter", 2.0 * _CONDITIONS.tool_radius),
    ("App::PropertyInteger", "Teeth", "Tool", "number of teeth Z", _CONDITIONS.teeth),
    ("App::PropertyLength", "Scallop", "Cutting", "scallop height Sz left between passes", _CONDITIONS.scallop),
    ("App::PropertyEnumeration", "FeedFrom", "Cutting", "programmed feed, or feed per tooth × Z × N", FEED_FROM),
    ("App::PropertyFloat", "Feed", "Cutting", "programmed feed, mm/min", 60.0 * _CONDITIONS.programmed_feed),
    ("App::PropertyLength", "FeedPerTooth", "Cutting", "feed per tooth fz (FeedFrom = Feed per tooth)", 0.2),
    ("App::PropertyFloat", "SpindleSpeed", "Cutting", "spindle speed N, rpm", 60.0 * _CONDITIONS.spindle_speed),
    ("App::PropertyEnumeration", "Machine", "Machine", "machine model: its slowest of X and Y sets a_max", None),
    ("App::PropertyFloat", "Acceleration", "Machine", "a_max in m/s², when Machine is '%s'" % ACCELERATION_ONLY, 3.0),
    ("App::PropertyBool", "UseJerk", "Machine", "also limit the real feed by the axes' jerk", False),
    ("App::PropertyFloat", "ScanFrom", "Feed scan", "lowest programmed feed of the scan, mm/min (0: no scan)", 0.0),
    ("App::PropertyFloat", "ScanTo", "Feed scan", "highest programmed feed of the scan, mm/min", 0.0),
    ("App::PropertyInteger", "ScanSteps", "Feed scan", "feeds in the scan", 15),
    ("App::PropertyInteger", "Grid", "Sampling", "sample points along each parameter of the face", _SAMPLING.grid_u),
    ("App::PropertyFloat", "AngleStep", "Sampling", "directions every … degrees over 0–180° (1 or finer)", _SAMPLING.angle_step),
    ("App::PropertyFloat", "Alpha", "Sampling", "α of the acceptable set reported (at most the optimum's)", _SAMPLING.report_alpha),
    ("App::PropertyEnumeration", "Choice", "Choice",
     "the angle applied: the paper's beams (worst point), the least predicted time of planes over the face, "
     "or the fastest of planes finished and simulated on the machine every ValidationStep", CHOICES),
    ("App::PropertyFloat", "ValidationStep", "Choice", "planes simulated every … degrees from 0 to 180", 10.0),
    ("App::PropertyLength", "Tolerance", "Choice", "machining tolerance of the simulated planes", 0.01),
]

_OUTPUTS = [
    ("App::PropertyAngle", "ChosenAngle", "the direction applied to operations, by Choice"),
    ("App::PropertyAngle", "OptimalAngle", "the beams' optimal direction θ* of the planes from X"),
    ("App::PropertyAngle", "LeastTimeAngle", "the direction of least predicted time of planes over the face"),
    ("App::PropertyFloat", "PredictedTime", "predicted time of planes at the chosen angle, s"),
    ("App::PropertyFloat", "BeamAlpha", "α*: every point keeps at least this share of its best G_p"),
    ("App::PropertyFloatList", "AcceptableAngles", "directions in the beams' intersection at the reported α, °"),
    ("App::PropertyString", "AcceptableRanges", "the acceptable directions as ranges"),
    ("App::PropertyInteger", "PointCount", "sample points used"),
    ("App::PropertyStringList", "Warnings", "points left out, ties"),
    ("App::PropertyFloatList", "ScanFeeds", "feeds of the scan, mm/min"),
    ("App::PropertyFloatList", "ScanOptimalAngles", "the optimal direction at each feed of the scan, °"),
    ("App::PropertyFloatList", "ValidationAngles", "angles of the simulated planes, °"),
    ("App::PropertyFloatList", "ValidationTimes", "simulated machining time of the planes at each angle, s"),
]


def machine_choices():
    return feedsim.machine_names() + [ACCELERATION_ONLY]


def face_shape(link):
    """The face of a LinkSub value (object, ['FaceN']), or a ValueError naming what to pick."""
    if not link:
        raise ValueError("no face: set Face to a face of a model (e.g. Body, Face4)")
    obj, subs = link
    names = [subs] if isinstance(subs, str) else list(subs)
    faces = [name for name in names if name.startswith("Face")]
    if len(faces) != 1:
        raise ValueError("Face must name exactly one face of %s, not %r" % (obj.Label, names))
    try:
        return obj.Shape.getElement(faces[0])
    except Exception:
        raise ValueError("%s has no %s: pick the face again" % (obj.Label, faces[0])) from None


# The task panel's ranges (mm, mm/min, rpm, m/s², degrees); also the work bounds of the core's sampling.
LIMITS = {"ToolDiameter": (0.1, 100.0), "Teeth": (1, 20), "Scallop": (0.0001, 1.0), "Feed": (1.0, 100000.0),
          "FeedPerTooth": (0.001, 5.0), "SpindleSpeed": (1.0, 100000.0), "Acceleration": (0.01, 100.0),
          "ScanFrom": (0.0, 100000.0), "ScanTo": (0.0, 100000.0), "ScanSteps": (2, 100),
          "ValidationStep": (1.0, 90.0), "Grid": (2, 500), "AngleStep": (0.01, 1.0), "Alpha": (0.01, 1.0),
          "Tolerance": (0.001, 1.0), "Arrows": (0, 20000)}


class MachiningDirection(PropertyLimits, InMemoryResult):
    LIMITS = LIMITS

    """The per-point result, the feed scan and the simulated planes are computed again after reopening."""

    def __init__(self, obj):
        add_inputs(obj, _INPUTS)
        obj.Machine = machine_choices()
        obj.Machine = DEFAULT_MACHINE
        add_results(obj, _OUTPUTS)
        obj.addProperty("App::PropertyInteger", "Arrows", "Display", "arrows drawn on the face, at most")
        obj.Arrows = 600
        obj.Proxy = self
        self.forget()

    def onDocumentRestored(self, obj):
        super().onDocumentRestored(obj)
        refresh_choices(obj, "Machine", machine_choices())

    def feed_mm_min(self, obj):
        return obj.Feed if obj.FeedFrom == FEED_FROM[0] else obj.FeedPerTooth.Value * obj.Teeth * obj.SpindleSpeed

    def options(self, obj):
        """Keyword arguments of hsmplanner.direction.optimal_direction, checked."""
        if obj.Teeth < 1:
            raise ValueError("Teeth %d: a tool has at least one tooth" % obj.Teeth)
        if not obj.SpindleSpeed > 0:
            raise ValueError("SpindleSpeed %g rpm must be positive" % obj.SpindleSpeed)
        if not self.feed_mm_min(obj) > 0:
            raise ValueError("%s must be positive" % ("Feed (mm/min)" if obj.FeedFrom == FEED_FROM[0] else "FeedPerTooth"))
        machine = dict(machine=obj.Machine) if obj.Machine != ACCELERATION_ONLY else \
            dict(machine=None, acceleration_m_s2=obj.Acceleration)
        return dict(tool_diameter=obj.ToolDiameter.Value, scallop=obj.Scallop.Value, spindle_rpm=obj.SpindleSpeed,
                    teeth=obj.Teeth, use_jerk=obj.UseJerk, grid=obj.Grid, angle_step=obj.AngleStep,
                    alpha=obj.Alpha, feed_mm_min=self.feed_mm_min(obj), **machine)

    def compute(self, obj):
        face, options = face_shape(obj.Face), self.options(obj)
        self.result = direction.optimal_direction(face, **options)
        self.scan = self.feed_scan(obj, face, options)
        self.validation = self.simulate(obj) if obj.Choice == CHOICES[2] else []
        obj.ScanFeeds = [row[0] for row in self.scan]
        obj.ScanOptimalAngles = [row[1] for row in self.scan]
        obj.ValidationAngles = [row["angle_deg"] for row in self.validation]
        obj.ValidationTimes = [row["simulated_s"] for row in self.validation]
        obj.LeastTimeAngle = self.result.fastest_angle_deg
        obj.BeamAlpha = self.result.alpha
        obj.AcceptableAngles = list(self.result.acceptable)
        obj.AcceptableRanges = direction.format_ranges(self.result.acceptable)
        obj.PointCount = len(self.result.points)
        obj.Warnings = list(self.result.warnings)
        for warning in self.result.warnings:
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, warning))
        obj.OptimalAngle = self.result.angle_deg
        chosen = [self.result.angle_deg, self.result.fastest_angle_deg,
                  direction.fastest(self.validation)["angle_deg"] if self.validation else None][CHOICES.index(obj.Choice)]
        times = self.result.predicted_time_s
        obj.PredictedTime = float(times[int(round(chosen / obj.AngleStep)) % len(times)])
        obj.ChosenAngle = chosen  # last: the view provider redraws on it

    def simulate(self, obj):
        """Planes every ValidationStep, finished and simulated on the machine (Choice = Fastest simulated)."""
        if obj.Machine == ACCELERATION_ONLY:
            raise ValueError("Choice '%s' simulates the planes on a machine model: choose a Machine" % CHOICES[2])
        if not 0 < obj.ValidationStep <= 90:
            raise ValueError("ValidationStep %g° must be in ]0°, 90°]" % obj.ValidationStep)
        count = int(round(180.0 / obj.ValidationStep))
        part, subs = obj.Face
        name = subs if isinstance(subs, str) else subs[0]
        with freecad_progress("%s: planes finished and simulated every %g°" % (obj.Label, obj.ValidationStep)) \
                as progress:
            return direction.simulated_directions(part.Shape, name, [180.0 * i / count for i in range(count + 1)],
                                                  tool_diameter=obj.ToolDiameter.Value, scallop=obj.Scallop.Value,
                                                  feed_mm_min=self.feed_mm_min(obj), machine=obj.Machine,
                                                  tolerance=obj.Tolerance.Value, progress=progress)

    @staticmethod
    def feed_scan(obj, face, options):
        if not obj.ScanFrom > 0 and not obj.ScanTo > 0:
            return []
        if not 0 < obj.ScanFrom < obj.ScanTo or obj.ScanSteps < 2:
            raise ValueError("feed scan from %g to %g mm/min in %d steps: give 0 < ScanFrom < ScanTo and at "
                             "least 2 steps (or ScanFrom = ScanTo = 0 for none)"
                             % (obj.ScanFrom, obj.ScanTo, obj.ScanSteps))
        step = (obj.ScanTo - obj.ScanFrom) / (obj.ScanSteps - 1)
        feeds = [obj.ScanFrom + i * step for i in range(obj.ScanSteps)]
        scan_options = {k: v for k, v in options.items() if k != "feed_mm_min"}
        return direction.directions_over_feeds(face, feeds, **scan_options)

    def has_input(self, obj):
        return bool(obj.Face)

    def failed(self, obj):
        obj.PointCount = 0
        obj.ChosenAngle = 0.0  # last: the view provider redraws on it (nothing drawn)

    def forget(self):
        self.result, self.scan, self.validation = None, [], []


def is_parallel_plane_finishing(obj):
    proxy = getattr(obj, "Proxy", None)
    return type(proxy).__name__ == "ObjectParallelPlaneFinishing"


def apply_to_operation(analysis, operation):
    """Set the Angle of a Parallel plane finishing operation to the analysis's chosen angle (and its Face, if
    it has none), and recompute it."""
    if not is_parallel_plane_finishing(operation):
        raise ValueError("%s is not a Parallel plane finishing operation" % getattr(operation, "Label", operation))
    if analysis.Proxy.ensure_result(analysis) is None:
        raise ValueError("%s has no result: %s" % (analysis.Label, getattr(analysis.Proxy, "error", None)
                                                    or "set its Face and recompute"))
    operation.Angle = analysis.ChosenAngle.Value
    if not operation.Face:
        operation.Face = analysis.Face
    operation.recompute()
    return operation.Angle.Value


def create(face=None, document=None, name="MachiningDirection", **properties):
    """Add a machining direction analysis of `face` ((object, 'FaceN')), with any property given by name
    (ToolDiameter=10, Feed=6000, …), recomputed when it has a face."""
    document = document or (face[0].Document if face else FreeCAD.ActiveDocument)
    if document is None:
        raise ValueError("no document: open or create one first")
    known = {entry[1] for entry in _INPUTS} | {"Arrows"}
    unknown = sorted(set(properties) - known)
    if unknown:
        raise ValueError("a Machining direction has no property %s: use %s" % (", ".join(map(repr, unknown)),
                                                                             ", ".join(sorted(known))))
    obj = document.addObject(TYPE_NAME, name)
    MachiningDirection(obj)
    job_tool = finishing.job_ball_end(document)
    if job_tool is not None:  # the Job's ball end mill and its feeds, unless given
        diameter, feed, rpm = job_tool
        defaults = dict(ToolDiameter=diameter, Feed=feed if feed > 0 else None, SpindleSpeed=rpm if rpm > 0 else None)
        for key, value in defaults.items():
            if value is not None:
                properties.setdefault(key, value)
    for key, value in properties.items():
        setattr(obj, key, value)
    if face:
        obj.Face = face
        obj.recompute()
    return obj
