"""Path/CAM operation "Volume roughing": the sub-volumes of a Roughing volume object swept into a toolpath
(cpp/roughing/sweep.hpp), on the machine chosen for it (its rotary axes give the A/B/C of the moves).

Thin, as FreeCAD's own operations: properties wired to hsmplanner.roughing through app/roughing/commands.
The tool is the operation's tool controller: a torus (FreeCAD's bullnose: corner radius = diameter / 2 −
FlatRadius), a flat end mill or a ball end. Post the result with our 840D post (TRAORI) or the LinuxCNC 5-axis
post, with --machine the operation's Machine; a strategy that tilts the tool on a 3-axis Machine is refused
when the operation computes. Proxy classes are recorded in saved documents: never rename them.
"""
import FreeCAD
import Path

import hsmplanner
from hsmplanner import feedsim, roughing

from ..clearance_moves import via_clearance
from ..compat import cam_module, create_tool_bit, tool_corner_radius, tool_shape_id
from ..job_controllers import usable_or_added
from ..op_comments import comment_text, mend_leading_comments
from ..property_limits import PropertyLimits
from ..properties import refresh_choices
from ..finishing import exact_top
from ..progress import freecad_progress, in_background, staged
from .commands import program_clearance, sweep_commands, work_plane_comments

PathOp = cam_module("op")

_DEFAULTS = roughing._core.roughing.SweepSettings()  # each default written once, in C++
DEFAULT_MACHINE = "mikron-ucp710-ac-840d"
MEND_RESOLUTION = 0.2  # mm: the removal model that finds the rapids that would cut the stock left
LIMITS = {"RadialEngagement": (1.0, 100.0), "Allowance": (0.0, 10.0), "RampAngle": (0.5, 90.0),
          "StepUpMinimum": (0.0, 100.0), "StepUpScallop": (0.01, 10.0), "PushOut": (0.0, 10.0)}
LINK_CLEARANCE = 5.0  # mm above the stock: the links' clearance (roughing.join_paths)
REST_SPACING = 0.4  # mm between the points of the stock a rest roughing reads (the removal model's at 0.2 mm)
# Posts that write a program of tool tip and rotary axes for a controller that keeps the tip on the path (tool
# centre point: the 840D's TRAORI, LinuxCNC's TCP kinematics). A 3-axis post writes the same words, which a
# machine without TCP runs as joint moves: the tool then leaves the path (the Job's post, chosen by its name).
TCP_POSTS = ("hsm_siemens840d", "hsm_linuxcnc5x")


def tcp_post_warning(job, commands):
    """The warning for a program whose moves turn rotary axes when the Job's chosen post is not a tool-centre-
    point one, or None (no rotary move, no post chosen yet, or a TCP post)."""
    post = str(getattr(job, "PostProcessor", "") or "")
    if not post or post in TCP_POSTS:
        return None
    if not any(letter in c.Parameters for c in commands for letter in "ABC"):
        return None
    return ("WARNING: this program turns rotary axes with the tool tip programmed, but the Job's post '%s' does "
            "not write tool-centre-point programs: on a machine without TCP the tool leaves the path. Choose "
            "hsm_siemens840d (TRAORI) or hsm_linuxcnc5x as the Job's post, or a 3-axis Machine for this "
            "operation" % post)


def cutter_of(tool):
    """The core Cutter of a FreeCAD tool (ToolBit or legacy): its kind from the shape, diameter and corner."""
    shape = tool_shape_id(tool)
    diameter = float(getattr(tool, "Diameter", 0.0))
    if diameter <= 0:
        raise ValueError("the tool controller's tool has no diameter: choose a torus, flat or ball end mill")
    if "bullnose" in shape or "torus" in shape:
        return roughing.cutter("torus", diameter=diameter, corner_radius=tool_corner_radius(tool))
    if "ballend" in shape:
        return roughing.cutter("ball", diameter=diameter)
    if "endmill" in shape:
        return roughing.cutter("flat", diameter=diameter)
    raise ValueError("tool shape '%s' is not a roughing cutter: use a bullnose (torus), endmill or ballend ToolBit"
                     % (shape or "unknown"))


def torus_controller(job, diameter=8.0, corner_radius=1.0, feed_mm_min=2000.0, spindle_rpm=12000, number=3,
                     replace=True):
    """A bullnose ToolBit (default: the roughing paper's Ø8 r1 torus) and its tool controller, added to `job`.

    replace: the Job's only one (headless FreeCAD 0.20 cannot choose among several for a new operation)."""
    if replace:
        for old in list(job.Tools.Group):
            job.Tools.removeObject(old)
            job.Document.removeObject(old.Name)
    tool_controller = cam_module("tool_controller")
    bit = create_tool_bit("Torus%g" % diameter, "Torus Ø%g r%g" % (diameter, corner_radius), "bullnose", diameter,
                          corner_radius)
    controller = tool_controller.Create("TC: Torus Ø%g r%g" % (diameter, corner_radius), bit, number)
    controller.HorizFeed = FreeCAD.Units.Quantity("%g mm/min" % feed_mm_min)
    controller.VertFeed = FreeCAD.Units.Quantity("%g mm/min" % (0.5 * feed_mm_min))
    controller.SpindleSpeed = spindle_rpm
    job.Proxy.addToolController(controller) if hasattr(job.Proxy, "addToolController") else job.Tools.addObject(controller)
    return controller


# What a new Volume roughing operation gets when its Job has no roughing cutter with a feed: the roughing
# paper's Ø8 r1 torus, at its 2 m/min.
DEFAULT_TORUS = dict(diameter=8.0, corner_radius=1.0, feed_mm_min=2000.0, spindle_rpm=12000)


def check_controller(controller):
    """The core Cutter of a tool controller that roughing can use; ValueError naming what to set otherwise (no
    tool, a tool that is not a torus, flat or ball end, a feed of 0: FreeCAD's default controller)."""
    label = getattr(controller, "Label", "the tool controller")
    if controller is None or getattr(controller, "Tool", None) is None:
        raise ValueError("no tool controller: choose one with a torus (bullnose), flat or ball end mill")
    cutter = cutter_of(controller.Tool)
    if not controller.HorizFeed.Value > 0:
        raise ValueError("%s has a horizontal feed of 0 mm/min: the path would cut at F0; set its HorizFeed (and "
                         "VertFeed)" % label)
    return cutter


def is_roughing_controller(controller):
    try:
        check_controller(controller)
    except ValueError:
        return False
    return True


def roughing_controller(job, chosen=None):
    """The tool controller a new Volume roughing takes: `chosen` (FreeCAD's pick) if roughing can use it, else
    the Job's first such, else the paper's Ø8 r1 torus at F2000 added to the Job (and said in the Report
    view): FreeCAD's default controller has feeds of 0 and would only make the operation fail."""
    def add(job, number):
        return (torus_controller(job, number=number, replace=False, **DEFAULT_TORUS),
                "Ø%g r%g mm torus, F%g mm/min, S%g" % (DEFAULT_TORUS["diameter"], DEFAULT_TORUS["corner_radius"],
                                                       DEFAULT_TORUS["feed_mm_min"], DEFAULT_TORUS["spindle_rpm"]))

    return usable_or_added(job, chosen, is_roughing_controller, add, "roughing cutter with a feed")


RESULTS = [("Passes", "App::PropertyInteger", "passes of the last computation"),
           ("CuttingLength", "App::PropertyLength", "cutting path of the last computation"),
           ("ClosestApproach", "App::PropertyLength", "least distance from the tool to the part, checked independently"),
           ("RegionsSwept", "App::PropertyInteger", "regions of the volume swept and joined"),
           ("RapidsFed", "App::PropertyInteger",
            "approaches that would have cut stock left as rapids, fed into it instead")]


class ObjectVolumeRoughing(PropertyLimits, PathOp.ObjectOp):
    LIMITS = LIMITS

    def opFeatures(self, obj):
        return PathOp.FeatureTool | PathOp.FeatureCoolant

    def initOperation(self, obj):
        obj.addProperty("App::PropertyLink", "Volume", "Roughing", "the Roughing volume whose sub-volumes are swept "
                        "(its Strategy, Step and Region)")
        obj.addProperty("App::PropertyEnumeration", "Machine", "Roughing", "the machine whose rotary axes the "
                        "moves' A/B/C are (post with --machine=this)")
        obj.Machine = feedsim.machine_names()
        obj.Machine = DEFAULT_MACHINE
        obj.addProperty("App::PropertyPercent", "RadialEngagement", "Roughing", "step between passes, % of the "
                        "tool diameter")
        obj.RadialEngagement = int(round(100 * _DEFAULTS.radial_engagement))
        obj.addProperty("App::PropertyLength", "Allowance", "Roughing", "stock left on the part")
        obj.Allowance = _DEFAULTS.allowance
        obj.addProperty("App::PropertyAngle", "RampAngle", "Roughing", "entries into material ramp at most this steep")
        obj.RampAngle = _DEFAULTS.ramp_angle_deg
        self.add_step_up_and_rest(obj, _DEFAULTS.step_up_minimum)
        self.add_push_out(obj, _DEFAULTS.push_out_most)
        self.add_results(obj)

    def add_step_up_and_rest(self, obj, minimum):
        """StepUpMinimum (`minimum` where the property is new), StepUpScallop and RestFrom."""
        if "StepUpMinimum" not in obj.PropertiesList:
            obj.addProperty("App::PropertyLength", "StepUpMinimum", "Roughing", "intermediate levels inside each "
                            "slice where the part leans (step-up), no nearer to each other; 0: one level per slice")
            obj.StepUpMinimum = minimum
            obj.addProperty("App::PropertyLength", "StepUpScallop", "Roughing", "step-up levels are added while the "
                            "staircase a leaning wall keeps is thicker than this across it")
            obj.StepUpScallop = _DEFAULTS.step_up_scallop
        if "RestFrom" not in obj.PropertiesList:
            obj.addProperty("App::PropertyLink", "RestFrom", "Roughing", "rest roughing: a Volume roughing before this "
                            "one; this cuts only the stock it (and its own RestFrom) left")

    def add_push_out(self, obj, most):
        """PushOut (`most` where the property is new)."""
        if "PushOut" not in obj.PropertiesList:
            obj.addProperty("App::PropertyLength", "PushOut", "Roughing", "how far each level's outline may move "
                            "from the safe keep-out towards the part, to the tool's exact clearance; 0: off")
            obj.PushOut = most

    def add_results(self, obj):
        """The Result properties, those a document saved before them lacks too."""
        for name, kind, tip in RESULTS:
            if name not in obj.PropertiesList:
                obj.addProperty(kind, name, "Result", tip)
                obj.setEditorMode(name, 1)

    def opOnDocumentRestored(self, obj):
        self.add_results(obj)
        refresh_choices(obj, "Machine", feedsim.machine_names())
        # A document saved before step-up keeps the program it was saved with: one level per slice.
        self.add_step_up_and_rest(obj, 0.0)
        self.add_push_out(obj, 0.0)

    def opSetDefaultValues(self, obj, job):
        obj.ToolController = roughing_controller(job, obj.ToolController)
        obj.OpToolDiameter = obj.ToolController.Tool.Diameter

    def opExecute(self, obj):
        """One line in the Report view for what the user must set (an empty path), not a traceback."""
        try:
            self.roughing(obj)
        except (ValueError, RuntimeError) as error:
            del self.commandlist[:]
            FreeCAD.Console.PrintError("%s: %s\n" % (obj.Label, error))

    def roughing(self, obj):
        with freecad_progress("%s: volume roughing" % obj.Label) as progress:
            self.compute(obj, progress)

    def compute(self, obj, progress):
        computing, checking = staged(progress, [4, 1])
        program = volume_roughing_program(obj, computing)
        for warning in program.warnings:
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, warning))
        if program.fed:
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, roughing.rapid_note(program.fed)))
        machine = feedsim.load_machine(obj.Machine)
        moves, cutter, part_brep = program.moves, program.cutter, program.part_brep
        commands = sweep_commands(moves, machine, 60.0 * self.horizFeed, 60.0 * self.vertFeed)
        if checking is not None and not checking(0.0):
            raise hsmplanner.Cancelled("%s: cancelled before its clearance check" % obj.Label)
        report = in_background(self.clearance, commands, moves, machine, part_brep, cutter, obj.Allowance.Value - 0.01)
        if report.too_close:
            FreeCAD.Console.PrintWarning("%s: %d tool positions come within %.3f mm of the part (allowance %.3f mm)\n"
                                         % (obj.Label, report.too_close, report.minimum, obj.Allowance.Value))
        mend_leading_comments(self.commandlist, obj)
        warning = tcp_post_warning(getattr(self, "job", None), commands)
        if warning:  # in the Report view, and in the program where whoever runs it reads it
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, warning))
            self.commandlist.append(Path.Command("(%s)" % comment_text(warning)))
        self.commandlist.extend(via_clearance(commands, clearance_height(commands, program, machine)))
        obj.Passes = program.passes
        obj.CuttingLength = program.cutting_length
        obj.ClosestApproach = max(0.0, report.minimum)
        obj.RegionsSwept = program.regions
        obj.RapidsFed = len(program.fed)

    @staticmethod
    def clearance(commands, moves, machine, part_brep, cutter, limit):
        """The program checked as the machine's controller runs it (its rotary axes interpolated linearly
        between blocks); on 3 axes (a 3+2 program is written in its work plane) the sweep's own moves."""
        if machine.rotary_axes:
            return program_clearance(commands, machine, part_brep, cutter, limit)[0]
        return roughing.check_clearance(moves, part_brep, cutter, limit)


def clearance_height(commands, program, machine):
    """The Z the operation starts and ends at (a roughing operation has no height properties): the highest
    point of its own program (its links run on a plane or a sphere clear of the stock) and, where the program is
    written in the part's frame, at least LINK_CLEARANCE above the stock's top. A 3+2 program on a 3-axis
    machine is written in its turned work plane, where the stock's top is not a height."""
    top = max(c.Parameters["Z"] for c in commands if "Z" in c.Parameters)
    if work_plane_comments(program.moves, machine):
        return top
    return max(top, program.stock_top + LINK_CLEARANCE)


class Program:
    """What a Volume roughing operation cuts, before posting: its moves (the regions joined, rapids fed where
    they would cut the stock left), its cutter, the part's BREP, the stock's top (mm), and what it says."""

    def __init__(self, moves, cutter, part_brep, fed, warnings, passes, cutting_length, regions, stock_top):
        self.moves, self.cutter, self.part_brep, self.fed, self.warnings = moves, cutter, part_brep, fed, warnings
        self.passes, self.cutting_length, self.regions = passes, cutting_length, regions
        self.stock_top = stock_top


def is_volume_roughing(obj):
    return obj is not None and type(getattr(obj, "Proxy", None)).__name__ == "ObjectVolumeRoughing"


def operations_before(obj):
    """The chain of RestFrom links of `obj`, first operation first; ValueError for a link that is not a Volume
    roughing operation, a loop, or one of another part or stock."""
    chain, seen, link = [], {obj.Name}, getattr(obj, "RestFrom", None)
    while link is not None:
        if not is_volume_roughing(link):
            raise ValueError("RestFrom %s is not a Volume roughing operation: link the roughing this one follows"
                             % link.Label)
        if link.Name in seen:
            raise ValueError("RestFrom of %s leads back to itself (through %s): break the loop" % (obj.Label, link.Label))
        seen.add(link.Name)
        chain.insert(0, link)
        link = getattr(link, "RestFrom", None)
    return chain


def volume_roughing_program(obj, progress=None):
    """The Program of a Volume roughing operation `obj`: its Roughing volume's regions swept with its tool and
    settings, joined; with RestFrom, only the stock the operations before left (simulated at 0.2 mm), S3's
    setup direction searched on it. ValueError or RuntimeError naming what to set; hsmplanner.Cancelled when
    `progress` (a callable of the share done) says stop."""
    if obj.Volume is None:
        raise ValueError("no Roughing volume: link one (Volume) to give the sub-volumes")
    cutter = check_controller(obj.ToolController)
    chain = operations_before(obj)
    inputs, rest_stage, sweeps, joining = staged(progress, [1, 2 if chain else 0, 4, 2])
    volume, part_brep, stock_brep, partitions = obj.Volume.Proxy.computed(obj.Volume, inputs)
    if not partitions:
        raise ValueError("%s has no strategy: choose one (S1 to S5) to partition the volume" % obj.Volume.Label)
    before = [(p.moves, p.cutter) for p in map(program_of, chain)]
    for op in chain:
        if op.Volume is None or op.Volume.Proxy.computed(op.Volume)[1:3] != (part_brep, stock_brep):
            raise ValueError("RestFrom %s roughs another part or stock than %s: link an operation on the same "
                             "part and stock" % (op.Label, obj.Volume.Label))
    rest = None
    if before:
        rest = in_background(roughing.simulate_removal, before[0][0], stock_brep, part_brep, tool=before[0][1],
                             resolution=MEND_RESOLUTION, rest_spacing=REST_SPACING, then=before[1:],
                             progress=rest_stage).rest
    passes, length, swept, warnings = 0, 0.0, [], []
    settings = obj.Volume.Proxy.settings(obj.Volume)
    for (index, partition), (setup, sweeping) in zip(partitions, pairs(staged(sweeps, [1, 3] * len(partitions)))):
        if rest is not None and settings["strategy"] == "S3":  # the setup direction for what is left
            partition = in_background(roughing.partition, volume.solids[index], part_brep, "S3", step=partition.step,
                                      setup_resolution_deg=settings.get("setup_resolution_deg"),
                                      setup_grid=settings.get("setup_grid"), rest=rest, progress=setup)
        paths = in_background(roughing.sweep, partition, volume.solids[index], part_brep, stock_brep, tool=cutter,
                              progress=sweeping, radial_engagement=obj.RadialEngagement / 100.0,
                              allowance=obj.Allowance.Value, ramp_angle_deg=obj.RampAngle.Value,
                              step_up_minimum=obj.StepUpMinimum.Value, step_up_scallop=obj.StepUpScallop.Value,
                              push_out=obj.PushOut.Value, rest=rest)
        warnings += ["region %d: %s" % (index + 1, w) for w in paths.warnings]
        passes += len(paths.passes)
        length += paths.cutting_length
        swept.append(paths)
    # The regions as one program, linked through the air; rapids kept out of the stock the program leaves at
    # their time (after the operations before); checked whole against the part, links included.
    moves, fed = in_background(lambda: roughing.keep_rapids_out_of_stock(
        roughing.join_paths(swept, stock_brep), stock_brep, part_brep,
        tool=cutter, resolution=MEND_RESOLUTION, after=before or None, progress=joining))
    stock_top = exact_top(obj.Volume.Proxy.inputs(obj.Volume)[1])
    program = Program(moves, cutter, part_brep, fed, warnings, passes, length, len(partitions), stock_top)
    obj.Proxy.program = program
    return program


def pairs(items):
    """[(items[0], items[1]), (items[2], items[3]), …]"""
    return list(zip(items[0::2], items[1::2]))


def program_of(op):
    """The Program an operation computed last (kept by its proxy), or computed now."""
    kept = getattr(op.Proxy, "program", None)
    return kept if kept is not None else volume_roughing_program(op)


def SetupProperties():
    return ["RadialEngagement", "Allowance", "RampAngle", "Machine", "StepUpMinimum", "StepUpScallop"]


def CreateVolumeRoughing(name, obj=None, parentJob=None):
    if obj is None:
        obj = FreeCAD.ActiveDocument.addObject("Path::FeaturePython", name)
    obj.Proxy = ObjectVolumeRoughing(obj, name, parentJob)
    return obj
