"""Feed-rate simulation of FreeCAD Path/CAM objects: a Job, an operation, or any object with a Path.

Pure functions here; the document object is feedrate_object.py.
"""
from hsmplanner import feedsim


def is_job(obj):
    return hasattr(obj, "Operations") and hasattr(obj.Operations, "Group")


def is_simulatable(obj):
    return obj is not None and (is_job(obj) or hasattr(obj, "Path"))


def program_commands(obj):
    """Path commands as the machine would get them: for a Job, each active operation in order, with its tool
    controller's tool change when the tool changes (as FreeCAD's posts emit them); else the object's Path."""
    if is_job(obj):
        commands, tool = [], None
        for op in obj.Operations.Group:
            if not getattr(op, "Active", True) or not hasattr(op, "Path"):
                continue
            controller = getattr(op, "ToolController", None)
            if controller is not None and controller is not tool and hasattr(controller, "Path"):
                commands += controller.Path.Commands
                tool = controller
            commands += op.Path.Commands
        return commands
    if hasattr(obj, "Path"):
        return list(obj.Path.Commands)
    raise ValueError("%s has no toolpath: pick a Path/CAM Job or operation" % getattr(obj, "Label", obj))


def operations(obj):
    """The active operations of a Job, or the object itself."""
    if is_job(obj):
        return [op for op in obj.Operations.Group if getattr(op, "Active", True) and hasattr(op, "Path")]
    return [obj]


def check_feeds(obj):
    """Refuses a path that cuts at F0 (FreeCAD's default tool controller has feeds of 0 and operations then
    write F0, which no machine runs): the message names the operation, its tool controller and the fix."""
    for op in operations(obj):
        feed = None
        for command in op.Path.Commands:
            feed = command.Parameters.get("F", feed)
            if command.Name in ("G1", "G01", "G2", "G02", "G3", "G03") and feed is not None and not feed > 0:
                controller = getattr(op, "ToolController", None)
                raise ValueError("%s cuts at F0 (%s): its tool controller%s has no feed; set the controller's "
                                 "HorizFeed and VertFeed" % (op.Label, command.toGCode().strip(),
                                 " '%s'" % controller.Label if controller is not None else ""))


def check_current(obj):
    """Refuses an operation whose path is not the one its properties give: its last recompute failed (the path
    kept is an older one), or it changed since (it waits for a recompute). The message names the operation and
    the reason."""
    for op in operations(obj):
        state = list(getattr(op, "State", []) or [])
        if "Invalid" in state or not op.isValid():
            reason = op.getStatusString() if hasattr(op, "getStatusString") else "its recompute failed"
            raise ValueError("%s failed to recompute (%s): its path is an older one; fix the operation and "
                             "recompute it before timing it" % (op.Label, reason))
        if "Touched" in state:
            raise ValueError("%s has changed since its path was computed: recompute it (Ctrl+R) before timing it"
                             % op.Label)


def simulate_object(obj, machine=feedsim.DEFAULT_MACHINE, blocks=True, trace_period=None):
    """Simulate a Job or an operation; FreeCAD's feeds (mm/s) are read as they are stored. An operation that
    failed or is waiting for a recompute is refused (check_current)."""
    check_current(obj)
    check_feeds(obj)
    commands = program_commands(obj)
    if not commands:
        raise ValueError("%s has an empty toolpath: recompute it first" % obj.Label)
    return feedsim.simulate(commands, machine, blocks=blocks, trace_period=trace_period)


def machine_choices():
    return feedsim.machine_names()
