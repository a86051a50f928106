"""The block writer our posts share: N numbers, comments, modal words written only when they change, numbers
without trailing zeros, feeds in mm/min, and the rotary axes of 4- and 5-axis programs.

FreeCAD's Path commands carry the rotary axes as A, B, C (degrees) of the machine chosen for the Job; a post
writes them as they are ("angles"), or, for the 840D with TRAORI, as the tool-axis vector they give on that
machine ("vectors": A3= B3= C3=, which any 840D with its own kinematics turns back into its angles)."""
import numpy as np

MOTION = ("G0", "G1", "G2", "G3")
ROTARY = "ABC"


def add_common_arguments(parser, precision):
    """The options every post of ours takes: number format, N numbers, comments, program name, and FreeCAD's
    editor flags (accepted, not used)."""
    parser.add_argument("--precision", type=int, default=precision, help="decimals of coordinates (default %d)"
                        % precision)
    parser.add_argument("--no-line-numbers", action="store_true", help="no N numbers")
    parser.add_argument("--line-increment", type=int, default=10, help="N step (default 10)")
    parser.add_argument("--no-comments", action="store_true", help="leave out comments")
    parser.add_argument("--program-name", default="", help="name in the header (default: the Job's label)")
    parser.add_argument("--no-show-editor", action="store_true", help="(accepted for FreeCAD compatibility)")
    parser.add_argument("--show-editor", action="store_true", help="(accepted for FreeCAD compatibility)")


def rotary_axes_of(objects):
    """The rotary axis letters (of A, B, C) that any Path command of `objects` moves."""
    used = set()
    for obj in objects:
        path = getattr(obj, "Path", None)
        if path is None or hasattr(obj, "Operations"):
            continue
        for command in path.Commands:
            used.update(letter for letter in ROTARY if letter in command.Parameters)
    return "".join(sorted(used))


def check_rotary_axes(used, machine):
    """ValueError when the program turns an axis `machine` (a MachineModel) has not."""
    names = "".join(axis.name for axis in machine.rotary_axes)
    missing = [letter for letter in used if letter not in names]
    if missing:
        raise ValueError("the operations turn %s but machine '%s' has %s: choose the Job's machine with --machine"
                         % (", ".join(missing), machine.name,
                            "rotary axes " + ", ".join(names) if names else "no rotary axes"))


def operations_machine(objects):
    """The one Machine (a preset name) the operations of `objects` were computed for, or None when none has one;
    ValueError when they name several (one program runs on one machine)."""
    names = {}
    for obj in objects:
        name = getattr(obj, "Machine", None)
        if isinstance(name, str) and name and hasattr(obj, "Path") and not hasattr(obj, "Operations"):
            names.setdefault(name, obj.Label)
    if len(names) > 1:
        raise ValueError("the operations were computed for different machines (%s): one program runs on one machine; "
                         "set the same Machine on each" % ", ".join("%s: %s" % (label, name)
                                                                   for name, label in sorted(names.items())))
    return next(iter(names), None)


def post_machine(objects, asked, default, post):
    """The MachineModel a post writes for: `asked` (--machine), else the operations' Machine, else `default`
    (None: no machine). ValueError naming both when the operations were computed for another machine than
    the one asked: their A B C are that machine's angles."""
    from hsmplanner import feedsim

    computed = operations_machine(objects)
    name = asked or computed or default
    if not name:
        return None
    machine = feedsim.load_machine(name)
    if computed and feedsim.load_machine(computed).name != machine.name:
        operation = next(o.Label for o in objects if getattr(o, "Machine", None) == computed)
        raise ValueError("%s post: %s was computed for machine '%s', not '%s' (--machine): its A B C are that "
                         "machine's angles; post with --machine=%s, or set the operation's Machine to %s and "
                         "recompute" % (post, operation, computed, machine.name, computed, machine.name))
    return machine


class ProgramWriter:
    """Blocks of one program. `comment_format` wraps a comment ('; %s' on the 840D, '(%s)' on LinuxCNC);
    `radius_letter` is how an arc's radius is written ('CR=' on the 840D)."""

    def __init__(self, args, comment_format="; %s", radius_letter="R", rotary_mode="angles", machine=None):
        self.args, self.lines, self.number = args, [], 0
        self.modal = {}
        self.comment_format, self.radius_letter = comment_format, radius_letter
        self.rotary_mode, self.machine = rotary_mode, machine
        self.angles = {letter: 0.0 for letter in ROTARY}
        self.transformation, self.transforming = None, False
        if rotary_mode == "vectors" and machine is None:
            raise ValueError("orientation vectors need the machine whose A, B, C the operations give: --machine NAME")

    def transform_with(self, on_blocks, off_block):
        """A 5-axis transformation (the 840D's TRAORI … TRAFOOF) switched on before the first move of an
        operation, after the tool change and its length compensation, and off before the next tool change and
        at the end (finish)."""
        self.transformation = (list(on_blocks), off_block)

    def transform(self, on):
        if self.transformation is None or on == self.transforming:
            return
        for text in (self.transformation[0] if on else [self.transformation[1]]):
            self.block(text)
        self.transforming = on

    def finish(self):
        self.transform(False)

    def block(self, text):
        if not self.args.no_line_numbers:
            self.number += self.args.line_increment
            text = "N%d %s" % (self.number, text)
        self.lines.append(text)

    def comment(self, text):
        if not self.args.no_comments:
            text = text.strip()
            if not self.comment_format.startswith("("):
                text = text.strip("()").strip()
            else:  # a '(' or ')' inside would nest or end it: LinuxCNC refuses both
                if text.startswith("(") and text.endswith(")"):
                    text = text[1:-1].strip()
                text = text.replace("(", "[").replace(")", "]")
            self.lines.append(self.comment_format % " ".join(text.split()))

    def number_word(self, letter, value, precision=None):
        text = ("%." + str(self.args.precision if precision is None else precision) + "f") % value
        text = text.rstrip("0").rstrip(".") if "." in text else text
        return letter + (text if text not in ("-0", "") else "0")

    def modal_word(self, key, word, words, always=False):
        if always or self.modal.get(key) != word:
            words.append(word)
            self.modal[key] = word

    def rotary_words(self, parameters, words):
        if not any(letter in parameters for letter in ROTARY):
            return
        for letter in ROTARY:
            if letter in parameters:
                self.angles[letter] = parameters[letter]
        if self.rotary_mode == "angles":
            for letter in ROTARY:
                if letter in parameters:
                    self.modal_word(letter, self.number_word(letter, parameters[letter]), words)
            return
        from hsmplanner import _core
        angles = [self.angles[axis.name] for axis in self.machine.rotary_axes] + [0.0]
        _, axis = _core.forward_kinematics(self.machine, np.zeros(3), angles[:2])
        vector = [self.number_word(letter, value, 6) for letter, value in zip(("A3=", "B3=", "C3="), axis)]
        if self.modal.get("vector") != vector:  # all three: on the 840D a component not written is 0
            words.extend(vector)
            self.modal["vector"] = vector

    def motion(self, command):
        p = command.Parameters
        name = command.Name
        arc = name in ("G2", "G3")
        words = []
        self.modal_word("G", name, words, always=arc)
        for axis in "XYZ":
            if axis in p:
                self.modal_word(axis, self.number_word(axis, p[axis]), words, always=arc)
        self.rotary_words(p, words)
        for offset in "IJK":
            if offset in p and arc:
                words.append(self.number_word(offset, p[offset]))
        if "R" in p and arc:
            words.append(self.number_word(self.radius_letter, p["R"]))
        if "F" in p and name != "G0":
            self.modal_word("F", self.number_word("F", p["F"] * 60.0), words)  # FreeCAD stores mm/s
        if words and words != [name]:  # a motion word alone moves nothing
            self.block(" ".join(words))

    def tool(self, controller, call="T%d D1 M6"):
        self.transform(False)  # a tool change runs without the transformation
        self.comment("tool: %s" % controller.Label)
        self.block(call % controller.ToolNumber)
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

    def objects(self, objectslist, tool_call="T%d D1 M6"):
        """The work offsets, tool controllers and operations of `objectslist` in their order. CAM's post list
        holds a work-offset entry (not a document object: its Path is the G54… word, and a move up to the
        clearance height before any but the first) ahead of each fixture's operations; a list without one (a
        script's [job, controllers…, operations…]) gets the Job's first work offset ahead of everything, so that
        both write the same program."""
        if not any(_is_work_offset(obj) for obj in objectslist):
            job = job_of(objectslist)
            fixtures = list(getattr(job, "Fixtures", []) or [])
            if fixtures:
                self.block(fixtures[0])
        for obj in objectslist:
            if _is_work_offset(obj):
                self.transform(False)  # the offset and the move up to the clearance height: 3 axes, as CAM's
                for command in obj.Path.Commands:
                    self.command(command)
                continue
            if not hasattr(obj, "Path") or hasattr(obj, "Operations"):
                continue
            if hasattr(obj, "ToolNumber"):
                self.tool(obj, tool_call)
                continue
            self.comment("operation: %s" % obj.Label)
            self.transform(True)
            for command in obj.Path.Commands:
                self.command(command)

    def text(self, filename):
        text = "\n".join(self.lines) + "\n"
        if filename and filename != "-":
            with open(filename, "w") as stream:
                stream.write(text)
        return text


def job_of(objects):
    """The Job the objects to post belong to: the one among them (a script's [job, …]), else the Job holding
    their operations (CAM's post list, as 1.0's Post Process gives a script, holds none); None if neither."""
    job = next((o for o in objects if hasattr(o, "Operations")), None)
    if job is not None:
        return job
    for obj in objects:
        for parent in getattr(obj, "InList", []) or []:
            if hasattr(parent, "Operations"):
                return parent
            job = next((p for p in getattr(parent, "InList", []) or [] if hasattr(p, "Operations")), None)
            if job is not None:
                return job
    return None


def _is_work_offset(obj):
    """CAM's work-offset entry of a post list (Path.Post.Processor's fixture object): a Path, not a document
    object."""
    return hasattr(obj, "Path") and not hasattr(obj, "TypeId") and getattr(obj, "Name", "") == "Fixture"
