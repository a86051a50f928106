"""Documents saved by HSM Planner with earlier FreeCADs (../shared/data/freecad-0.20 and freecad-1.0), opened in
the running FreeCAD: what must have come through, and how each recomputed path may differ from the one saved.
Shared by test_saved_documents.py (freecadcmd) and tests/gui/gui_saved_documents.py (the GUI): each check
returns the list of its problems, empty when the document is fine.

EXPECTED_DIFFERENCES is the one table of the paths that do not come out as saved, each with its reason and
a rule that accepts that difference and nothing else; docs/freecad-versions.md gives the same table.
"""
import json
import math
import os
import shutil

import FreeCAD

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SHARED_DATA = os.environ.get("HSM_SHARED_DATA", os.path.normpath(os.path.join(REPO, "..", "shared", "data")))
# The FreeCAD each set was saved with -> its documents
SAVED_WITH = {
    "0.20": ["master_study.FCStd", "slot_job.FCStd", "impeller_job.FCStd"],
    "1.0": ["guide_finishing.FCStd", "slot_roughing.FCStd", "slot_roughing_study.FCStd", "strategy_study.FCStd"],
}
LENGTH_TOLERANCE_MM = 1e-3  # documents.json keeps lengths to 3 decimals


def data_folder(saved_with):
    return os.path.join(SHARED_DATA, "freecad-" + saved_with)


def saved_record(saved_with):
    """documents.json of the documents saved with FreeCAD `saved_with`: per document, its objects and each
    path's command count and length as saved."""
    path = os.path.join(data_folder(saved_with), "documents.json")
    if not os.path.isfile(path):
        raise FileNotFoundError("%s is missing: the documents saved with FreeCAD %s live in ../shared/data/freecad-%s"
                                " beside the repository (or set HSM_SHARED_DATA to the data folder)"
                                % (path, saved_with, saved_with))
    with open(path) as stream:
        return json.load(stream)


def open_copy(saved_with, name, folder):
    """Opens a copy of the saved document `name` made in `folder` (the shared original is never written)."""
    copy = os.path.join(folder, name)
    shutil.copyfile(os.path.join(data_folder(saved_with), name), copy)
    return FreeCAD.openDocument(copy)


# --- objects and proxies ----------------------------------------------------------------------------------

def is_ours(obj):
    return type(getattr(obj, "Proxy", None)).__module__.startswith("hsmplanner.")


def proxy_problems(document, names):
    """Every object of documents.json is there, and every Python feature among them has its proxy again."""
    problems = []
    for name in names:
        obj = document.getObject(name)
        if obj is None:
            problems.append("%s: missing after opening" % name)
        elif obj.TypeId.endswith("Python") and getattr(obj, "Proxy", None) is None:
            problems.append("%s (%s): proxy not restored (its module is not importable)" % (name, obj.TypeId))
    return problems


def job_problems(document):
    """Each Job is FreeCAD's own again (its class from the running FreeCAD) and holds its operations, tool
    controllers, tool bits, stock and setup sheet as FreeCAD's own objects."""
    from hsmplanner.app.compat import cam_module

    expected = {"Job": (cam_module("job"), "ObjectJob"),
                "ToolController": (cam_module("tool_controller"), "ToolController"),
                "ToolBit": (cam_module("tool_bit"), "ToolBit")}
    problems = []

    def check(obj, role, what):
        module, name = expected[role]
        if obj is None or not isinstance(getattr(obj, "Proxy", None), getattr(module, name)):
            problems.append("%s: not a %s.%s (%r)" % (what, module.__name__, name, getattr(obj, "Proxy", None)))

    jobs = [o for o in document.Objects if type(getattr(o, "Proxy", None)).__name__ == "ObjectJob"]
    if not jobs:
        problems.append("no Job restored")
    for job in jobs:
        check(job, "Job", job.Name)
        for controller in job.Tools.Group:
            check(controller, "ToolController", controller.Name)
            check(getattr(controller, "Tool", None), "ToolBit", "the tool of " + controller.Name)
        for op in job.Operations.Group:
            if op.ToolController not in job.Tools.Group:
                problems.append("%s: its tool controller is not one of %s's" % (op.Name, job.Name))
        for role in ("Stock", "SetupSheet"):
            resource = getattr(job, role, None)
            if resource is None or getattr(resource, "Proxy", None) is None:
                problems.append("%s: its %s did not come through" % (job.Name, role))
    return problems


# --- properties of our objects ----------------------------------------------------------------------------

def fresh_objects(document):
    """One object of each of our proxy classes, made by today's code in `document`: what a restored object
    must have (by class name)."""
    from hsmplanner.app import feedrate_object, finishing_ops, guide_curve_net_object, master_feature_object
    from hsmplanner.app.roughing import operation as roughing_op, parts as roughing_parts, volume as roughing_object
    from hsmplanner.app.compat import create_job

    block, block_stock = roughing_parts.create_slanted_slot_block(document)
    job = create_job([block])
    made = [block, block_stock, roughing_parts.create_impeller(document)[0],
            finishing_ops.CreateGuideCurveFinishing("FreshGuide", parentJob=job),
            finishing_ops.CreateParallelPlaneFinishing("FreshPlanes", parentJob=job),
            roughing_op.CreateVolumeRoughing("FreshRoughing", parentJob=job)]
    # Last, and never recomputed: without inputs these would only report their errors.
    analysis = document.addObject(feedrate_object.TYPE_NAME, "FreshAnalysis")
    feedrate_object.FeedRateAnalysis(analysis)
    made += [analysis, guide_curve_net_object.create(document), roughing_object.create(block, recompute=False),
             master_feature_object.create(document)]
    return {type(obj.Proxy).__name__: obj for obj in made}


def _value_problem(obj, name):
    """What is wrong with one property's value, or None."""
    kind, value = obj.getTypeIdOfProperty(name), getattr(obj, name)
    if kind == "App::PropertyEnumeration":
        choices = obj.getEnumerationsOfProperty(name)
        if value not in choices:
            return "%s = %r is not one of its choices %s" % (name, value, choices)
    number = getattr(value, "Value", value)
    if isinstance(number, float) and not math.isfinite(number):
        return "%s = %r" % (name, value)
    if kind == "App::PropertyLength" and number < 0:
        return "%s = %r is negative" % (name, value)
    if kind.startswith("App::PropertyLink"):
        targets = value if isinstance(value, list) else [value]
        for target in targets:
            target = target[0] if isinstance(target, tuple) else target
            if target is not None and target.Document != obj.Document:
                return "%s links %s of another document" % (name, target.Name)
    return None


def property_problems(document, fresh):
    """Every property today's code gives an object of its class exists on the restored object, with the same
    type, the same choices (enumerations) and a sane value; and the links every such object needs are set."""
    problems = []
    for obj in (o for o in document.Objects if is_ours(o)):
        model = fresh.get(type(obj.Proxy).__name__)
        if model is None:
            problems.append("%s: no fresh %s to compare with (add it to fresh_objects)" % (obj.Name, type(obj.Proxy)))
            continue
        for name in model.PropertiesList:
            if name not in obj.PropertiesList:
                problems.append("%s: property %s missing (add it in onDocumentRestored)" % (obj.Name, name))
                continue
            if obj.getTypeIdOfProperty(name) != model.getTypeIdOfProperty(name):
                problems.append("%s.%s is a %s, today's code makes a %s" % (obj.Name, name,
                                obj.getTypeIdOfProperty(name), model.getTypeIdOfProperty(name)))
            elif (model.getTypeIdOfProperty(name) == "App::PropertyEnumeration"
                  and obj.getEnumerationsOfProperty(name) != model.getEnumerationsOfProperty(name)):
                problems.append("%s.%s offers %s, today's code %s" % (obj.Name, name,
                                obj.getEnumerationsOfProperty(name), model.getEnumerationsOfProperty(name)))
            problem = _value_problem(obj, name)
            if problem:
                problems.append("%s: %s" % (obj.Name, problem))
        for name in REQUIRED_LINKS.get(type(obj.Proxy).__name__, ()):
            if getattr(obj, name, None) in (None, [], ()):
                problems.append("%s: %s is not set" % (obj.Name, name))
    return problems


# The links without which an object of the class cannot recompute (as the saved documents have them).
REQUIRED_LINKS = {
    "GuideCurveNet": ("Boundary1", "Boundary2", "BottomFace"),
    "ObjectGuideCurveFinishing": ("Net", "ToolController"),
    "ObjectVolumeRoughing": ("Volume", "ToolController"),
    "RoughingVolume": ("Part", "Stock"),
    "TestPartStock": ("Part",),
    "FeedRateAnalysis": ("Source",),
}


# --- paths ------------------------------------------------------------------------------------------------

def paths_of(document):
    """{object name: its Path's commands} of every object with a Path."""
    return {obj.Name: list(obj.Path.Commands) for obj in document.Objects if hasattr(obj, "Path")}


def recompute_all(document):
    """Recomputes every object of ours and the Jobs' stocks (opening leaves some untouched, and an untouched
    operation would keep its saved path); returns the objects left invalid."""
    for obj in document.Objects:
        if is_ours(obj) or type(getattr(obj, "Proxy", None)).__name__.startswith("Stock"):
            obj.touch()
    document.recompute()
    return ["%s: %s" % (o.Name, o.getStatusString()) for o in document.Objects if not o.isValid()]


def path_length(commands):
    import Path

    return Path.Path(commands).Length


def _moves(commands):
    return [c for c in commands if not c.Name.startswith("(")]


def only_retract_heights(saved_z, new_z):
    """A rule: the same commands, but for the head comment (see same_head_comment) and the G0 moves at Z
    `saved_z`, which are at `new_z` now with X and Y unchanged."""

    def rule(obj, saved, now):
        problems = same_head_comment(obj, saved, now)
        saved_moves, new_moves = _moves(saved), _moves(now)
        if len(saved_moves) != len(new_moves):
            return problems + ["%d moves, %d saved" % (len(new_moves), len(saved_moves))]
        moved = 0
        for index, (old, new) in enumerate(zip(saved_moves, new_moves)):
            if old.toGCode() == new.toGCode():
                continue
            expected = dict(old.Parameters, Z=new_z)
            if (old.Name != "G0" or new.Name != "G0" or abs(old.Parameters.get("Z", math.nan) - saved_z) > 1e-6
                    or set(expected) != set(new.Parameters)
                    or any(abs(expected[k] - new.Parameters[k]) > 1e-6 for k in expected)):
                problems.append("move %d: %s, saved %s: not a retract moved from Z%g to Z%g"
                                % (index, new.toGCode(), old.toGCode(), saved_z, new_z))
            else:
                moved += 1
        if not moved:
            problems.append("no retract moved from Z%g to Z%g: the difference is gone, drop it from the table"
                            % (saved_z, new_z))
        return problems

    return rule


def same_head_comment(obj, saved, now):
    """The head comment is the label as op_comments writes it (brackets for parentheses); the saved one was
    FreeCAD 0.20's, whose inner '(' Path.Command dropped."""
    from hsmplanner.app.op_comments import comment_text

    head = [c.Name for c in now if c.Name.startswith("(")][:1]
    wanted = "(%s)" % comment_text(obj.Label)
    return [] if head == [wanted] else ["head comment %s, expected %s" % (head, wanted)]


def rebuilt_sweep(passes, saved_cutting_mm):
    """A rule for a roughing whose sweep is built otherwise today: the head comment as saved, the same number
    of passes, every move clear of the part by the operation's allowance, and at least the saved cutting
    length (a better sweep cuts no less)."""

    def rule(obj, saved, now):
        problems = [] if [c.Name for c in saved[:1]] == [c.Name for c in now[:1]] else ["head comment changed"]
        if obj.Passes != passes:
            problems.append("%d passes, %d saved" % (obj.Passes, passes))
        allowance, closest = obj.Allowance.Value, obj.ClosestApproach.Value
        if not closest >= allowance - 0.01:
            problems.append("closest approach %.4f mm under the allowance %.3f mm" % (closest, allowance))
        if not obj.CuttingLength.Value >= saved_cutting_mm - 0.01:
            problems.append("cutting length %.3f mm, %.3f mm saved" % (obj.CuttingLength.Value, saved_cutting_mm))
        return problems

    return rule


class Difference:
    """How a recomputed path differs from the one saved, and why."""

    def __init__(self, reason, rule, commands=None, length_mm=None):
        self.reason, self.rule = reason, rule
        self.commands, self.length_mm = commands, length_mm  # as recomputed on FreeCAD 1.0, for the docs' table


# (FreeCAD it was saved with, document, object) -> Difference. Every other path must come out as saved.
EXPECTED_DIFFERENCES = {
    ("0.20", "master_study.FCStd", "GuideCurveFinishing"): Difference(
        "our code: retracts at the Safe height, 4.000 (the stock's exact top 1.000 + SafeHeightOffset 3), where "
        "0.20 added the 0.0117 mm by which the triangulation of the displayed part rose above its exact top "
        "(the core reads exact bounds now); the head comment '(guide B→median K0.5 P20 (study))' is written "
        "'[study]' (0.20 dropped the inner '(' and left 'study))')",
        only_retract_heights(4.01171, 4.0), commands=1502, length_mm=5220.472),
    ("0.20", "impeller_job.FCStd", "VolumeRoughing"): Difference(
        "our code: the sweep keeps the part out by the cutter grown by the allowance point by point (its corner "
        "narrower than its flutes, the hub curving up under it taken per point, not as one lift of every band), "
        "and its flat scales hold over the tool's reach where the hub's normal lines converge; where the hub's "
        "offsets fall away round the axis the keep-out is narrower across (an ellipse, thin bands below the "
        "corner): S5 cuts more of each channel, its outer passes nearer the blades; the passes' outlines are "
        "simplified within the tolerance of every point they had (fewer points). The same 7 passes, clear "
        "of the part by the allowance, cutting at least the 594.6 mm saved (the rule checks all three)",
        rebuilt_sweep(passes=7, saved_cutting_mm=594.567), commands=1762, length_mm=990.950),
}


def as_written_when_saved(obj, commands):
    """Our operation's commands without what every one of them gained after these documents were saved: the
    moves up to the clearance height, across and back up at the end (clearance_moves.via_clearance), and the
    warning comment of a rotary program whose Job's post is not a tool-centre-point one. Only moves that are
    exactly those are taken out."""
    from hsmplanner.app.clearance_moves import MOTION

    if not is_ours(obj):
        return commands
    kept = [c for c in commands if not c.Name.startswith("(WARNING: this program turns rotary axes")]
    moves = [i for i, c in enumerate(kept) if c.Name in MOTION]
    if len(moves) < 4:
        return kept
    up, across, back = (kept[i] for i in (moves[0], moves[1], moves[-1]))
    height = up.Parameters.get("Z")
    added = (up.Name == across.Name == back.Name == "G0" and set(up.Parameters) == {"Z"} == set(back.Parameters)
             and across.Parameters.get("Z") == height == back.Parameters["Z"])
    return [c for i, c in enumerate(kept) if not (added and i in (moves[0], moves[1], moves[-1]))]


def path_problems(saved_with, name, record, saved_paths, document):
    """Each recomputed path against documents.json (count, length): equal, or differing only as the table
    says; the table's entries must still be needed. Our operations' paths are compared as they were written
    when the documents were saved (as_written_when_saved)."""
    problems = []
    for obj_name, as_saved in record["path_commands_and_length_as_saved"].items():
        obj = document.getObject(obj_name)
        now = as_written_when_saved(obj, list(obj.Path.Commands))
        count, length = len(now), path_length(now)
        same = count == as_saved["commands"] and abs(length - as_saved["length_mm"]) <= LENGTH_TOLERANCE_MM
        same = same and [c.toGCode() for c in now] == [c.toGCode() for c in saved_paths[obj_name]]
        difference = EXPECTED_DIFFERENCES.get((saved_with, name, obj_name))
        if difference is None:
            if not same:
                problems.append("%s %s: %d commands, %.3f mm after recompute; saved %d, %.3f mm: explain it in "
                                "EXPECTED_DIFFERENCES" % (name, obj_name, count, length, as_saved["commands"],
                                                          as_saved["length_mm"]))
            continue
        if same:
            problems.append("%s %s comes out as saved: drop it from EXPECTED_DIFFERENCES" % (name, obj_name))
            continue
        problems += ["%s %s: %s" % (name, obj_name, p) for p in difference.rule(obj, saved_paths[obj_name], now)]
        if (count, round(length, 3)) != (difference.commands, difference.length_mm):
            problems.append("%s %s: %d commands, %.3f mm; the table says %s, %s: update it and the docs"
                            % (name, obj_name, count, length, difference.commands, difference.length_mm))
    return problems


def saved_path_problems(record, saved_paths):
    """The paths as opened are those documents.json describes (else the data and the record disagree)."""
    problems = []
    for obj_name, as_saved in record["path_commands_and_length_as_saved"].items():
        commands = saved_paths.get(obj_name)
        if commands is None:
            problems.append("%s: no path after opening" % obj_name)
        elif (len(commands) != as_saved["commands"]
              or abs(path_length(commands) - as_saved["length_mm"]) > LENGTH_TOLERANCE_MM):
            problems.append("%s as opened: %d commands, %.3f mm; documents.json says %d, %.3f mm"
                            % (obj_name, len(commands), path_length(commands), as_saved["commands"],
                               as_saved["length_mm"]))
    return problems
