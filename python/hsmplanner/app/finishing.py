"""Finishing toolpaths as FreeCAD Path commands: the glue between Path/CAM operations and the core.

Pure functions (no document object is created here): the areas of a Guide curve net object, a ball-end
tool in a Job, core moves turned into Path commands.
"""
import FreeCAD
import Path

import hsmplanner
from hsmplanner.toolpaths import face_number

from .job_controllers import usable_or_added
from .compat import cam_menu_name, cam_module, create_tool_bit, tool_shape_id
from .guide_curve_net_object import net_curve_edges

AREA_CHOICES = ["Elementary areas of the net", "Between the boundaries"]


def exact_top(shape):
    """The highest z of `shape`'s geometry. Shape.BoundBox reads the triangulation FreeCAD's 3D view leaves on
    a displayed part and the looser control points of one never displayed, so retracts taken from it differed
    between the GUI and freecadcmd for the same document."""
    return shape.optimalBoundingBox(False, False).ZMax


def net_curves(net):
    """The curves of a Guide curve net object as core curves, B1 to B2 (its CurveShapes)."""
    return [hsmplanner.as_curve(edge) for edge in net_curve_edges(net)]


def net_areas(net, areas=AREA_CHOICES[0]):
    """(first, second) curve pairs: each elementary area, or the one area between the boundaries."""
    curves = net_curves(net)
    if areas == AREA_CHOICES[1]:
        return [(curves[0], curves[-1])]
    return list(zip(curves, curves[1:]))


def net_part(net):
    """The solid and the bottom face number the net lies on."""
    if not net.BottomFace:
        raise ValueError("the guide curve net %s has no bottom face: pick the face it lies on" % net.Label)
    part, subs = net.BottomFace
    return part.Shape, face_number(subs[0] if not isinstance(subs, str) else subs)


def is_ball_end(tool):
    """True for a ball end mill: a ToolBit on FreeCAD's ballend shape, or a legacy tool of type BallEndMill."""
    shape = tool_shape_id(tool)
    return "ballend" in shape


def job_ball_end(document):
    """(diameter mm, feed mm/min, spindle rpm) of the first ball-end tool controller of a Job of `document`,
    or None: what an analysis of this document should assume by default."""
    for job in (o for o in document.Objects if hasattr(o, "Operations") and hasattr(o, "Tools")):
        for controller in job.Tools.Group:
            tool = getattr(controller, "Tool", None)
            if tool is not None and is_ball_end(tool):
                feed = float(controller.HorizFeed.getValueAs("mm/min"))
                return float(tool.Diameter), feed, float(controller.SpindleSpeed)
    return None


def check_tool(controller, tool):
    """Refuses a tool controller that ball-end finishing cannot use: not a ball end mill (the cusp and gouge
    checks assume a ball), or a cutting feed of 0 (FreeCAD's default controller: the path would cut at F0)."""
    label = getattr(controller, "Label", "the tool controller")
    if not is_ball_end(tool):
        kind = tool_shape_id(tool) or type(tool).__name__
        raise ValueError("%s holds a %s tool (%s, Ø%s): ball-end finishing needs a ball end mill; add one "
                         "(%s ▸ ToolBit library, shape ballend) and choose its tool controller"
                         % (label, kind, getattr(tool, "Label", "?"), getattr(tool, "Diameter", "?"),
                            cam_menu_name()))
    if not controller.HorizFeed.Value > 0:
        raise ValueError("%s has a horizontal feed of 0 mm/min: the path would cut at F0; set its HorizFeed "
                         "(and VertFeed)" % label)


def is_usable(controller):
    """True for a tool controller that ball-end finishing can use (see check_tool)."""
    try:
        check_tool(controller, getattr(controller, "Tool", None))
    except ValueError:
        return False
    return True


# What a new finishing operation gets when its Job has no usable tool controller: the guidance-curve paper's
# Ø4 mm ball end mill, at the middle of its feeds (2, 4, 6 m/min).
DEFAULT_BALL_END = dict(diameter=4.0, feed_mm_min=4000.0, spindle_rpm=18000)


def finishing_controller(job, chosen=None):
    """The tool controller a new finishing operation takes: `chosen` (FreeCAD's pick) if it is a ball end mill
    with a feed, else the Job's first such controller, else a new Ø4 mm ball end at F4000 added to the Job
    (and said in the report view). FreeCAD's default controller, a Ø5 mm flat end mill with feeds of 0, would
    only make the operation fail."""
    def add(job, number):
        return (ball_end_controller(job, number=number, replace=False, **DEFAULT_BALL_END),
                "Ø%g mm, F%g mm/min, S%g" % (DEFAULT_BALL_END["diameter"], DEFAULT_BALL_END["feed_mm_min"],
                                             DEFAULT_BALL_END["spindle_rpm"]))

    return usable_or_added(job, chosen, is_usable, add, "ball end mill with a feed")


def moves_to_commands(moves, feed, plunge_feed=None):
    """Path commands of core moves; feeds in mm/s (FreeCAD's unit). A G1 that goes down from a rapid is a
    plunge and runs at the plunge feed."""
    plunge_feed = plunge_feed or feed
    commands, previous_rapid = [], True
    for x, y, z, rapid in moves:
        if rapid:
            commands.append(Path.Command("G0", {"X": x, "Y": y, "Z": z}))
        else:
            commands.append(Path.Command("G1", {"X": x, "Y": y, "Z": z, "F": plunge_feed if previous_rapid else feed}))
        previous_rapid = bool(rapid)
    return commands


def ball_end_controller(job, diameter=4.0, feed_mm_min=4000.0, spindle_rpm=18000, number=2, replace=True):
    """A ball-end ToolBit and its tool controller, added to `job` (FreeCAD's own tool classes).

    replace: remove the Job's other tool controllers, so that new operations take this one (headless,
    FreeCAD 0.20 cannot choose among several: PathUtils.findToolController fails)."""
    if replace:
        for old in list(job.Tools.Group):
            job.Tools.removeObject(old)
            tool = getattr(old, "Tool", None)
            job.Document.removeObject(old.Name)
            if tool is not None and hasattr(tool, "Name") and job.Document.getObject(tool.Name):
                job.Document.removeObject(tool.Name)
    tool_controller = cam_module("tool_controller")
    bit = create_tool_bit("Ball%g" % diameter, "Ball end mill Ø%g mm" % diameter, "ballend", diameter)
    controller = tool_controller.Create("TC: Ball Ø%g" % diameter, bit, number)
    controller.HorizFeed = FreeCAD.Units.Quantity("%g mm/min" % feed_mm_min)
    controller.VertFeed = FreeCAD.Units.Quantity("%g mm/min" % min(feed_mm_min, 2000.0))
    controller.SpindleSpeed = spindle_rpm
    job.Proxy.addToolController(controller)
    return controller
