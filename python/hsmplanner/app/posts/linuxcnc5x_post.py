"""LinuxCNC 2.9 post for 5-axis machines with TCP kinematics (xyzac-trt-kins, xyzbc-trt-kins): X Y Z are the tool
tip in the workpiece frame and the rotary axes are written as the Job's A, B, C (degrees), which the kinematics
turn into joint positions. FreeCAD post contract: export(objectslist, filename, argstring).

The machine (--machine; default the operations' Machine, else linuxcnc-2.9-xyzac-trt) is checked against the
Machine the operations were computed for (their A B C are its angles: another machine is refused, naming both): the program may turn only its rotary axes,
within their travel. G64 P blends within the tolerance; feeds in mm/min.

    freecad: Job > Output > Processor 'hsm_linuxcnc5x' (a clone's `make build` links this file into the Macro
             folder, the Debian package into CAM's folder of posts)
    python:  linuxcnc5x_post.export([job] + job.Operations.Group, "part.ngc", "--machine=linuxcnc-2.9-xyzac-trt")
"""
import argparse
import shlex

from hsmplanner.app.posts.processor import processor_class
from hsmplanner.app.posts.writer import (ROTARY, ProgramWriter, add_common_arguments, check_rotary_axes, job_of,
                                         operations_machine, post_machine, rotary_axes_of)

TOOLTIP = "LinuxCNC 2.9, 5 axes with TCP kinematics (xyzac-trt): tool tip X Y Z and A B C, G64 P, feeds in mm/min"

DEFAULT_MACHINE = "linuxcnc-2.9-xyzac-trt"
parser = argparse.ArgumentParser(prog="hsm_linuxcnc5x", add_help=False)
parser.add_argument("--machine", default="", help="the machine (preset name or JSON file) whose rotary axes the "
                    "Job's A B C are (default: the operations' Machine, else %s)" % DEFAULT_MACHINE)
parser.add_argument("--tolerance", type=float, default=0.01, help="G64 P blending tolerance, mm (default 0.01)")
add_common_arguments(parser, precision=4)
TOOLTIP_ARGS = parser.format_help()


def check_travel(objectslist, machine):
    """ValueError naming the operation, the move and the axis when an angle is outside the axis's travel."""
    limits = {axis.name: axis for axis in machine.rotary_axes if not axis.continuous}
    for obj in objectslist:
        path = getattr(obj, "Path", None)
        if path is None or hasattr(obj, "Operations"):
            continue
        for number, command in enumerate(path.Commands, 1):
            for letter in ROTARY:
                axis = limits.get(letter)
                value = command.Parameters.get(letter)
                if axis is not None and value is not None and not axis.min_position <= value <= axis.max_position:
                    raise ValueError("%s, move %d: %s%g is outside the travel of %s on '%s' [%g, %g] deg"
                                     % (obj.Label, number, letter, value, letter, machine.name, axis.min_position,
                                        axis.max_position))


def export(objectslist, filename, argstring):
    """Write the program of `objectslist` (a Job, its tool controllers and operations) to `filename`."""
    args = parser.parse_args(shlex.split(argstring or ""))
    if not args.tolerance > 0:
        raise ValueError("--tolerance must be positive, got %g" % args.tolerance)
    machine = post_machine(objectslist, args.machine, DEFAULT_MACHINE, "LinuxCNC 5-axis")
    if not machine.rotary_axes or not machine.tool_tip_programmed:
        whose = " (the operations' Machine)" if not args.machine and operations_machine(objectslist) else ""
        raise ValueError("machine '%s'%s is not a LinuxCNC machine with TCP kinematics: use a 5-axis preset such as "
                         "linuxcnc-2.9-xyzac-trt (the operation's Machine, recomputed), or FreeCAD's linuxcnc post for "
                         "3 axes" % (machine.name, whose))
    check_rotary_axes(rotary_axes_of(objectslist), machine)
    check_travel(objectslist, machine)
    writer = ProgramWriter(args, comment_format="(%s)")
    job = job_of(objectslist)
    name = args.program_name or (job.Label if job is not None else "program")
    writer.comment("%s - LinuxCNC 5-axis post of HSM Planner, machine %s (%s, tool tip programmed)"
                   % (name, machine.name, machine.kinematics))
    writer.block("G17 G21 G90 G94 G40 G49 G80")
    writer.block("G64 P%g" % args.tolerance)
    writer.objects(objectslist, tool_call="T%d M6 G43")
    writer.block("M5")
    writer.block("M2")
    return writer.text(filename)


# FreeCAD 1.1's CAM takes this class (named after the linked file, hsm_linuxcnc5x_post.py) for its Post Process
# command and a Job's post-processor list; on 1.0 it wraps export() above.
_processor = processor_class("Hsm_Linuxcnc5X", export, TOOLTIP, parser)
if _processor is not None:
    Hsm_Linuxcnc5X = _processor
