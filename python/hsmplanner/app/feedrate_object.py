"""Parametric "Feed-rate analysis" document object (App::FeaturePython): a Job or operation simulated on a
machine model. Thin: properties wired to hsmplanner.app.feedrate.simulate_object. The per-block result is
kept in memory (not in the file) and rebuilt on recompute; the view provider draws it as a feed-rate map.
"""
import FreeCAD

from hsmplanner import feedsim

from .feedrate import is_simulatable, simulate_object
from .properties import add_results, refresh_choices
from .proxy_state import InMemoryResult

TYPE_NAME = "App::FeaturePython"
DEFAULT_MACHINE = feedsim.DEFAULT_MACHINE
CUSTOM_MACHINE = "(machine file)"
COLOR_MODES = ["Share of programmed feed", "Feed (mm/min)"]

_OUTPUTS = [
    ("App::PropertyFloat", "TotalTime", "simulated machining time, s"),
    ("App::PropertyFloat", "CuttingTime", "time in G1/G2/G3, s"),
    ("App::PropertyFloat", "RapidTime", "time in G0, s"),
    ("App::PropertyFloat", "NaiveTime", "length / programmed feed, as CAM systems estimate it, s"),
    ("App::PropertyFloat", "TimeOverNaive", "simulated time / naive time"),
    ("App::PropertyInteger", "BlockCount", "motion blocks"),
    ("App::PropertyFloatList", "FeedClassesTime", "share of cutting time per feed class (<0.3 … ≥0.9 of F)"),
    ("App::PropertyFloatList", "FeedClassesBlocks", "share of cutting blocks per feed class"),
    ("App::PropertyFloatList", "FeedClassesLength", "share of cutting length per feed class"),
    ("App::PropertyIntegerList", "LengthClasses", "cutting blocks per block-length class"),
    ("App::PropertyString", "Report", "the summary as JSON"),
]


def add_machine_properties(obj, group, tooltip):
    """Machine (a preset, or CUSTOM_MACHINE) and MachineFile: how an analysis object chooses its machine."""
    obj.addProperty("App::PropertyEnumeration", "Machine", group, tooltip)
    obj.Machine = feedsim.machine_names() + [CUSTOM_MACHINE]
    obj.Machine = DEFAULT_MACHINE
    obj.addProperty("App::PropertyFile", "MachineFile", group,
                    "machine JSON file, used when Machine is '%s'" % CUSTOM_MACHINE)


def chosen_machine(obj):
    """The preset name or machine file an analysis object's Machine and MachineFile choose."""
    if obj.Machine == CUSTOM_MACHINE:
        if not obj.MachineFile:
            raise ValueError("Machine is '%s' but MachineFile is empty: choose a machine JSON file" % CUSTOM_MACHINE)
        return obj.MachineFile
    return obj.Machine


class FeedRateAnalysis(InMemoryResult):
    """The per-block result is simulated again after the document was reopened."""

    def __init__(self, obj):
        obj.addProperty("App::PropertyLink", "Source", "Feed-rate analysis", "Job or operation to simulate")
        add_machine_properties(obj, "Feed-rate analysis", "machine model")
        obj.addProperty("App::PropertyEnumeration", "ColorBy", "Display", "what the colours of the map show")
        obj.ColorBy = COLOR_MODES
        add_results(obj, _OUTPUTS)
        obj.Proxy = self
        self.result = None

    def onDocumentRestored(self, obj):
        super().onDocumentRestored(obj)
        refresh_choices(obj, "Machine", feedsim.machine_names() + [CUSTOM_MACHINE])

    def machine(self, obj):
        return chosen_machine(obj)

    def compute(self, obj):
        if not is_simulatable(obj.Source):
            raise ValueError("Source is not a Path/CAM Job or operation: link one")
        self.result = simulate_object(obj.Source, self.machine(obj), blocks=True)
        summary = self.result.summary
        obj.CuttingTime, obj.RapidTime = summary.cutting_time, summary.rapid_time
        obj.NaiveTime, obj.TimeOverNaive = summary.naive_time, summary.time_over_naive
        obj.BlockCount = summary.block_count
        obj.FeedClassesTime = list(summary.feed_classes_time)
        obj.FeedClassesBlocks = list(summary.feed_classes_blocks)
        obj.FeedClassesLength = list(summary.feed_classes_length)
        obj.LengthClasses = list(summary.length_classes)
        obj.Report = summary.to_json(obj.Source.Label)
        obj.TotalTime = summary.total_time  # last: the view provider redraws on it

    def has_input(self, obj):
        return is_simulatable(obj.Source)

    def failed(self, obj):
        obj.Report = ""
        obj.TotalTime = 0.0  # last: the view provider redraws on it (an empty map)


def source_machine(source):
    """The Machine the operation `source` (or every operation of the Job `source`) was computed for: its A/B/C
    are that machine's angles. None when none says, or they differ."""
    from .posts.writer import operations_machine

    group = getattr(getattr(source, "Operations", None), "Group", None)
    try:
        return operations_machine(group if group is not None else [source])
    except ValueError:
        return None


def create(source, machine=None, document=None, name="FeedRateAnalysis"):
    """Add a feed-rate analysis of `source` (a Job or an operation) on `machine` (default: the Machine its
    operations were computed for, else the 3-axis default), recomputed."""
    if not is_simulatable(source):
        raise ValueError("%s is not a Path/CAM Job or operation" % getattr(source, "Label", source))
    machine = machine or source_machine(source) or DEFAULT_MACHINE
    document = document or source.Document
    obj = document.addObject(TYPE_NAME, name)
    FeedRateAnalysis(obj)
    obj.Source = source
    if machine in obj.getEnumerationsOfProperty("Machine"):
        obj.Machine = machine
    else:
        obj.Machine = CUSTOM_MACHINE
        obj.MachineFile = machine
    obj.recompute()
    return obj
