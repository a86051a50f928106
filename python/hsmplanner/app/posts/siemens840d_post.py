"""Siemens SINUMERIK 840D post-processor (FreeCAD post contract: export(objectslist, filename, argstring)).

High-speed finishing programs as the 840D wants them: CYCLE832 with the machining tolerance (which selects
G642 rounding, SOFT and the compressor), ';' comments, N numbers, modal words written only when they change,
feeds in mm/min, T/D/M6 tool calls and S/M3 spindle from the tool controllers.

Five-axis: operations whose moves carry A, B or C (the angles of the Job's machine) are written between TRAORI
and TRAFOOF, the tool tip programmed (TRAORI after the tool change and its length compensation, as in Siemens'
examples; TRAFOOF before the next); the orientation as those angles (--orientation=angles, the default), or as
the tool-axis vector A3= B3= C3= they give on --machine (--orientation=vectors, with ORIWKS ORIVECT: the
controller interpolates the tool axis on the great circle in the workpiece frame and uses its own kinematics).

    freecad: Job > Output > Processor 'hsm_siemens840d' (a clone's `make build` links this file into the Macro
             folder, the Debian package into CAM's folder of posts)
    python:  siemens840d_post.export([job] + job.Operations.Group, "part.mpf", "--tolerance=0.01")
"""
import argparse
import shlex

from hsmplanner.app.posts.processor import processor_class
from hsmplanner.app.posts.writer import (ProgramWriter, add_common_arguments, check_rotary_axes, job_of,
                                         post_machine, rotary_axes_of)

TOOLTIP = "Siemens 840D: CYCLE832(tolerance), G642, SOFT, ';' comments, N numbers, feeds in mm/min"

parser = argparse.ArgumentParser(prog="hsm_siemens840d", add_help=False)
parser.add_argument("--tolerance", type=float, default=0.01, help="CYCLE832 tolerance, mm (default 0.01)")
parser.add_argument("--orientation", choices=("angles", "vectors"), default="angles",
                    help="5-axis moves: the machine's A B C as given, or tool-axis vectors A3 B3 C3 (needs --machine)")
parser.add_argument("--machine", default="", help="the machine of the Job's A B C (a preset name or JSON file; "
                    "default: the operations' Machine): checks the rotary axes, and gives the vectors")
add_common_arguments(parser, precision=3)
TOOLTIP_ARGS = parser.format_help()


def export(objectslist, filename, argstring):
    """Write the program of `objectslist` (a Job, its tool controllers and operations) to `filename`."""
    args = parser.parse_args(shlex.split(argstring or ""))
    if not args.tolerance > 0:
        raise ValueError("--tolerance must be positive, got %g" % args.tolerance)
    rotary = rotary_axes_of(objectslist)
    machine = post_machine(objectslist, args.machine, None, "840D")
    if machine is not None:
        check_rotary_axes(rotary, machine)
    writer = ProgramWriter(args, radius_letter="CR=", rotary_mode=args.orientation if rotary else "angles",
                           machine=machine)
    job = job_of(objectslist)
    name = args.program_name or (job.Label if job is not None else "program")
    writer.comment("%s - Siemens 840D post of HSM Planner" % name)
    writer.block("G17 G90 G71 G94 G40")
    writer.block("CYCLE832(%g,1,1)" % args.tolerance)  # 1 = _FINISH: G642, SOFT, COMPCAD within the tolerance
    writer.block("G642 SOFT")
    if rotary:
        writer.comment("5-axis: tool tip programmed, rotary axes %s, TRAORI after each tool change" % ", ".join(rotary))
        writer.transform_with(["TRAORI"] + (["ORIWKS ORIVECT"] if args.orientation == "vectors" else []), "TRAFOOF")
    writer.objects(objectslist)
    writer.finish()
    writer.block("CYCLE832()")
    writer.block("M5")
    writer.block("M30")
    return writer.text(filename)


# FreeCAD 1.1's CAM takes this class (named after the linked file, hsm_siemens840d_post.py) for its Post Process
# command and a Job's post-processor list; on 1.0 it wraps export() above.
_processor = processor_class("Hsm_Siemens840D", export, TOOLTIP, parser)
if _processor is not None:
    Hsm_Siemens840D = _processor
