"""Siemens SINUMERIK 840D post-processor (FreeCAD post contract: export(objectslist, filename, argstring)).

High-speed finishing programs as the 840D wants them: CYCLE832 with the machining tolerance (which selects
G642 rounding, SOFT and the compressor), ';' comments, N numbers, modal words written only when they change,
feeds in mm/min, T/D/M6 tool calls and S/M3 spindle from the tool controllers.

    freecad: Job > Output > Processor 'hsm_siemens840d' (the workbench links this file into the Macro folder)
    python:  siemens840d_post.export([job] + job.Operations.Group, "part.mpf", "--tolerance=0.01")
"""
import argparse
import shlex

TOOLTIP = "Siemens 840D: CYCLE832(tolerance), G642, SOFT, ';' comments, N numbers, feeds in mm/min"

parser = argparse.ArgumentParser(prog="hsm_siemens840d", add_help=False)
parser.add_argument("--tolerance", type=float, default=0.01, help="CYCLE832 tolerance, mm (default 0.01)")
parser.add_argument("--precision", type=int, default=3, help="decimals of coordinates (default 3)")
parser.add_argument("--no-line-numbers", action="store_true", help="no N numbers")
parser.add_argument("--line-increment", type=int, default=10, help="N step (default 10)")
parser.add_argument("--no-comments", action="store_true", help="leave out ';' comments")
parser.add_argument("--program-name", default="", help="name in the header (default: the Job's label)")
parser.add_argument("--no-show-editor", action="store_true", help="(accepted for FreeCAD compatibility)")
parser.add_argument("--show-editor", action="store_true", help="(accepted for FreeCAD compatibility)")
TOOLTIP_ARGS = parser.format_help()

MOTION = ("G0", "G1", "G2", "G3")


class _Writer:
    def __init__(self, args):
        self.args, self.lines, self.number = args, [], 0
        self.modal = {}

    def block(self, text):
        if not self.args.no_line_numbers:
            self.number += self.args.line_increment
            text = "N%d %s" % (self.number, text)
        self.lines.append(text)

    def comment(self, text):
        if not self.args.no_comments:
            self.lines.append("; " + text.strip().strip("()").strip())

    def number_word(self, letter, value):
        text = ("%." + str(self.args.precision) + "f") % value
        text = text.rstrip("0").rstrip(".") if "." in text else text
        return letter + (text if text not in ("-0", "") else "0")

    def motion(self, command):
        p = command.Parameters
        words = []
        if self.modal.get("G") != command.Name or command.Name in ("G2", "G3"):
            words.append(command.Name)
            self.modal["G"] = command.Name
        for axis in "XYZ":
            if axis in p:
                word = self.number_word(axis, p[axis])
                if self.modal.get(axis) != word or command.Name in ("G2", "G3"):
                    words.append(word)
                    self.modal[axis] = word
        for offset in "IJK":
            if offset in p and command.Name in ("G2", "G3"):
                words.append(self.number_word(offset, p[offset]))
        if "R" in p and command.Name in ("G2", "G3"):
            words.append(self.number_word("CR=", p["R"]))
        if "F" in p and command.Name != "G0":
            word = self.number_word("F", p["F"] * 60.0)  # FreeCAD stores mm/s; the 840D reads mm/min
            if self.modal.get("F") != word:
                words.append(word)
                self.modal["F"] = word
        if words and words != [command.Name]:  # a motion word alone moves nothing
            self.block(" ".join(words))

    def tool(self, controller):
        self.comment("tool: %s" % controller.Label)
        self.block("T%d D1 M6" % controller.ToolNumber)
        speed = getattr(controller, "SpindleSpeed", 0)
        if speed:
            self.block("S%d %s" % (speed, "M4" if getattr(controller, "SpindleDir", "Forward") == "Reverse" else "M3"))
        self.modal.clear()

    def command(self, command):
        name = command.Name
        if name.startswith("("):
            self.comment(name)
        elif name in MOTION:
            self.motion(command)
        elif name in ("M6",):
            pass  # tool changes come from the tool controllers
        else:
            words = [name] + [self.number_word(k, v) for k, v in sorted(command.Parameters.items())]
            self.block(" ".join(words))


def export(objectslist, filename, argstring):
    """Write the program of `objectslist` (a Job, its tool controllers and operations) to `filename`."""
    args = parser.parse_args(shlex.split(argstring or ""))
    if not args.tolerance > 0:
        raise ValueError("--tolerance must be positive, got %g" % args.tolerance)
    writer = _Writer(args)
    job = next((o for o in objectslist if hasattr(o, "Operations")), None)
    name = args.program_name or (job.Label if job is not None else "program")
    writer.comment("%s - Siemens 840D post of HSM Planner" % name)
    writer.block("G17 G90 G71 G94 G40")
    writer.block("CYCLE832(%g,1,1)" % args.tolerance)  # 1 = _FINISH: G642, SOFT, COMPCAD within the tolerance
    writer.block("G642 SOFT")
    for obj in objectslist:
        if not hasattr(obj, "Path") or hasattr(obj, "Operations"):
            continue
        if hasattr(obj, "ToolNumber"):
            writer.tool(obj)
            continue
        writer.comment("operation: %s" % obj.Label)
        for command in obj.Path.Commands:
            writer.command(command)
    writer.block("CYCLE832()")
    writer.block("M5")
    writer.block("M30")
    text = "\n".join(writer.lines) + "\n"
    if filename and filename != "-":
        with open(filename, "w") as stream:
            stream.write(text)
    return text
