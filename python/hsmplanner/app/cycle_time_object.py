"""Parametric "Cycle time" document object (App::FeaturePython): a CAM Job timed three ways on a machine model,
operation by operation (cycle_time.job_rows). Thin: properties wired to the pure functions.

It links the Job, so FreeCAD recomputes it after any of the Job's operations: the times stay current. It also
writes each operation's and the Job's simulated time into a property of theirs, SimulatedCycleTime (s, in
the group "HSM Planner"), beside CAM's own CycleTime, so that a user, a spreadsheet or a report reads it where
CAM's estimate is. Those properties are outputs: setting them does not touch the operations.
"""
import json

import FreeCAD

from hsmplanner import feedsim

from .cycle_time import clock, job_rows
from .feedrate import is_job
from .feedrate_object import CUSTOM_MACHINE, add_machine_properties, chosen_machine, source_machine
from .properties import add_results
from .proxy_state import InMemoryResult

TYPE_NAME = "App::FeaturePython"
GROUP = "HSM Planner"
OP_PROPERTY = "SimulatedCycleTime"
OP_MACHINE_PROPERTY = "SimulatedOn"

_OUTPUTS = [
    ("App::PropertyFloat", "SimulatedTime", "the whole Job simulated on the machine, s"),
    ("App::PropertyFloat", "LengthOverFeed", "the whole Job's length / programmed feed, rapids at the rapid, s"),
    ("App::PropertyFloat", "CamEstimate", "the Job's CycleTime as CAM estimates it, s (0: CAM gave none)"),
    ("App::PropertyString", "Table", "every row (operations, then the Job) as JSON"),
    ("App::PropertyStringList", "Problems", "the operations that could not be timed, and why"),
]


class CycleTimeAnalysis(InMemoryResult):
    def __init__(self, obj):
        obj.addProperty("App::PropertyLink", "Job", "Cycle time", "the CAM Job to time")
        add_machine_properties(obj, "Cycle time", "the machine model it runs on")
        add_results(obj, _OUTPUTS)
        obj.Proxy = self
        self.result = None

    def has_input(self, obj):
        return is_job(obj.Job)

    def compute(self, obj):
        if not is_job(obj.Job):
            raise ValueError("Job is not a CAM Job: link one")
        rows, total = job_rows(obj.Job, chosen_machine(obj))
        self.result = dict(rows=rows, total=total, machine=obj.Machine)
        for row in rows:
            mark(obj.Document.getObject(row["name"]), row["simulated_s"], obj.Machine)
        mark(obj.Job, total["simulated_s"], obj.Machine)
        obj.Problems = ["%s: %s" % (row["label"], row["error"]) for row in rows + [total] if row["error"]]
        obj.LengthOverFeed = total["naive_s"] or 0.0
        obj.CamEstimate = total["cam_s"] or 0.0
        obj.Table = json.dumps(self.result)
        obj.SimulatedTime = total["simulated_s"] or 0.0  # last: the view redraws on it

    def failed(self, obj):
        obj.Table = ""
        obj.Problems = [self.error or "not computed"]
        obj.SimulatedTime = 0.0

    def rows(self, obj):
        """(rows, total, machine) of the last computation, recomputed if needed; (None, None, None) when there is
        none (see self.error)."""
        result = self.ensure_result(obj)
        if result is None:
            return None, None, None
        return result["rows"], result["total"], result["machine"]


def mark(target, seconds, machine):
    """The simulated time (s; 0 where it could not be) and the machine on `target` (an operation or the Job),
    as output properties: writing them does not touch it."""
    if target is None:
        return
    for prop_type, name, tooltip in (("App::PropertyFloat", OP_PROPERTY, "the simulated cycle time, s (HSM "
                                      "Planner's Cycle time: what the machine does, beside CAM's CycleTime)"),
                                     ("App::PropertyString", OP_MACHINE_PROPERTY, "the machine it was simulated on")):
        if not hasattr(target, name):
            target.addProperty(prop_type, name, GROUP, tooltip)
            target.setPropertyStatus(name, ["Output", "ReadOnly"])
    setattr(target, OP_PROPERTY, float(seconds or 0.0))
    setattr(target, OP_MACHINE_PROPERTY, machine)


def create(job, machine=None, document=None, name="CycleTime"):
    """Add a cycle-time analysis of the CAM Job `job` on `machine` (default: the Machine its operations were
    computed for, else the 3-axis default), recomputed."""
    if not is_job(job):
        raise ValueError("%s is not a CAM Job: pick a Job (or one of its operations)" % getattr(job, "Label", job))
    machine = machine or source_machine(job) or feedsim.DEFAULT_MACHINE
    obj = (document or job.Document).addObject(TYPE_NAME, name)
    CycleTimeAnalysis(obj)
    obj.Job = job
    if machine in obj.getEnumerationsOfProperty("Machine"):
        obj.Machine = machine
    else:
        obj.Machine = CUSTOM_MACHINE
        obj.MachineFile = machine
    obj.recompute()
    return obj


def summary_text(rows, total):
    """The table as text: a line per operation and the Job's total (what the Report view and scripts print)."""
    lines = ["%-28s %10s %12s %10s  %s" % ("operation", "CAM", "length/feed", "simulated", "held by")]
    for row in rows + [total]:
        lines.append("%-28s %10s %12s %10s  %s" % (row["label"][:28], clock(row["cam_s"]), clock(row["naive_s"]),
                                                    clock(row["simulated_s"]), row["held_by"] or row["error"]))
    return "\n".join(lines)
