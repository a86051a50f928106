"""The strategy study of finishing in a FreeCAD document: the grid from the text a user types
("0:180:15", "0.25,0.5"), the study's inputs from the selection or a Guide curve net object, and the chosen
row turned into a finishing operation in a Job. The study itself is hsmplanner.study; the panel is
hsmplanner.gui.strategy_study_panel (nothing here needs the GUI).
"""
from dataclasses import dataclass

from hsmplanner import _core, study

from . import finishing, finishing_ops, guide_curve_net_object
from .guide_curve_net import FOUR_STEP, MODES

# The panel's choices of guide nets with the median or not -> study.variants(median=… or net_modes=…).
MEDIAN_CHOICES = {"with and without": dict(median=(False, True)), "with the median": dict(median=(True,)),
                  "without the median": dict(median=(False,)),
                  "the paper's three": dict(net_modes=("b1_to_b2", "median_to_boundaries", "boundaries_to_median"))}
# Quick finishing by default: a study compares strategies, and a Ø10 ball at 0.1 mm cusp ranks them as the
# fine path would in a fraction of the time (each variant is a few seconds instead of a minute).
QUICK_FINISHING = dict(tool_diameter=10.0, cusp_height=0.1, tolerance=0.05)
parse_numbers = study.parse_range  # one parser of typed ranges, shared with the command line


def study_grid(planes="", k="", p="", median="with and without", four_step=False, feeds="4000",
               machine=None):
    """study.variants() from the panel's texts. ValueError names the field: a range that does not parse here,
    K outside ]0, 1[, P or a feed not positive, an empty grid… in study.variants."""
    if median not in MEDIAN_CHOICES:
        raise ValueError("median %r: use one of %s" % (median, ", ".join(MEDIAN_CHOICES)))
    return study.variants(planes_deg=parse_numbers(planes, "Plane angles"), k=parse_numbers(k, "K"),
                          p=parse_numbers(p, "P"), four_step=bool(four_step), **MEDIAN_CHOICES[median],
                          feeds_mm_min=parse_numbers(feeds, "Feeds"),
                          machines=(machine or study.feedsim.DEFAULT_MACHINE,))


@dataclass
class StudyInputs:
    """What a study runs on: the part (a document object), its bottom face's name, and the two boundaries as
    links (object, ['EdgeN', …]), as a Guide curve net holds them."""

    part: object
    face: str
    boundary_1: tuple
    boundary_2: tuple

    def document(self):
        """The studied part's document; ValueError when the part (or a boundary's object) was deleted or its
        document closed since it was picked."""
        for obj in (self.part, self.boundary_1[0], self.boundary_2[0]):
            if not in_document(obj):
                raise ValueError("the studied part or a boundary's object is no longer in its document (deleted, "
                                 "or the document closed): select the face and its boundaries again")
        return self.part.Document

    def shapes(self):
        """(part shape, face name, boundary 1 shape, boundary 2 shape): study.study's inputs."""
        self.document()
        return (self.part.Shape, self.face, guide_curve_net_object.linked_shape(self.boundary_1, "Boundary 1"),
                guide_curve_net_object.linked_shape(self.boundary_2, "Boundary 2"))

    def describe(self):
        self.document()
        edges = lambda link: "+".join(_names(link[1]))
        return "%s: %s between %s and %s" % (self.part.Label, self.face, edges(self.boundary_1), edges(self.boundary_2))


def in_document(obj):
    """Whether `obj` is still an object of an open document (a deleted one raises on every attribute; one
    removed but kept by undo is no longer the document's)."""
    try:
        return obj.Document is not None and obj.Document.getObject(obj.Name) is obj
    except (ReferenceError, RuntimeError):
        return False


def _names(subs):
    return [subs] if isinstance(subs, str) else list(subs)


WHAT_TO_SELECT = ("Select the bottom face and its two boundary edges (Ctrl+click: a face and two edges), or a "
                  "Guide curve net, then press Use the selection.")


def is_guide_curve_net(obj):
    return type(getattr(obj, "Proxy", None)).__name__ == "GuideCurveNet"


def inputs_from_net(net):
    """A Guide curve net's bottom face and boundaries (a study needs the face: the net must have one)."""
    if not net.BottomFace or not net.Boundary1 or not net.Boundary2:
        raise ValueError("the Guide curve net %s needs its bottom face and both boundaries set" % net.Label)
    part, faces = net.BottomFace
    return StudyInputs(part, _names(faces)[0], (net.Boundary1[0], _names(net.Boundary1[1])),
                       (net.Boundary2[0], _names(net.Boundary2[1])))


def inputs_from_selection(picked):
    """The study's inputs from what is selected: `picked` is [(object, ['FaceN', 'EdgeM', …]), …] in the order of
    selection. A Guide curve net gives its own; else exactly one face and two edges, the first edge picked
    being boundary 1. ValueError says what to select."""
    nets = [obj for obj, _ in picked if is_guide_curve_net(obj)]
    if nets:
        return inputs_from_net(nets[0])
    faces = [(obj, name) for obj, names in picked for name in names if name.startswith("Face")]
    edges = [(obj, name) for obj, names in picked for name in names if name.startswith("Edge")]
    if len(faces) != 1 or len(edges) != 2:
        raise ValueError("%s (selected: %d face%s, %d edge%s)" % (WHAT_TO_SELECT, len(faces), "s"[:len(faces) != 1],
                                                                 len(edges), "s"[:len(edges) != 1]))
    (part, face), (o1, e1), (o2, e2) = faces[0], edges[0], edges[1]
    return StudyInputs(part, face, (o1, [e1]), (o2, [e2]))


def net_mode_label(variant):
    """The Guide curve net object's Mode of a study variant ('Boundary 1 to boundary 2', '4-step method'…)."""
    if variant["strategy"] == "4-step":
        return FOUR_STEP
    core_mode = getattr(_core.NetMode, variant["mode"])
    return next(label for label, mode in MODES.items() if mode == core_mode)


def study_controller(job, tool_diameter, feed_mm_min):
    """The Job's ball-end tool controller of this diameter and feed (the one the study simulated), added when
    the Job has none."""
    for controller in job.Tools.Group:
        tool = getattr(controller, "Tool", None)
        if (finishing.is_usable(controller) and abs(float(tool.Diameter) - tool_diameter) < 1e-6
                and abs(controller.HorizFeed.getValueAs("mm/min").Value - feed_mm_min) < 1e-6):
            return controller
    number = 1 + max([getattr(c, "ToolNumber", 0) for c in job.Tools.Group], default=0)
    return finishing.ball_end_controller(job, diameter=tool_diameter, feed_mm_min=feed_mm_min, number=number,
                                         replace=False)


def create_operation(row, inputs, job, controller, settings):
    """The study's row as a finishing operation in `job` (not recomputed): Parallel plane finishing at the
    row's angle, or Guide curve finishing on a new Guide curve net of the row's K, P and mode (the 4-step
    method: the net's own). `settings`: the study's finishing (tool_diameter, cusp_height, tolerance).
    Returns (operation, net or None). FreeCAD asks which tool controller to take when a Job without
    operations holds several: the GUI selects `controller` before calling this (FreeCAD takes a selected one)."""
    document = job.Document
    net = None
    if row["strategy"] == "planes":
        op = finishing_ops.CreateParallelPlaneFinishing("ParallelPlaneFinishing", parentJob=job)
        op.Face = (inputs.part, inputs.face)
        op.Angle = row["angle_deg"]
    else:
        values = dict(Mode=net_mode_label(row))
        if row["strategy"] == "guide":
            values.update(K=row["k"], Step=row["p"])
        net = guide_curve_net_object.create(document, inputs.boundary_1, inputs.boundary_2,
                                            (inputs.part, [inputs.face]), name="StudyNet", **values)
        net.Label = "Net %s" % study.short_name(row)
        op = finishing_ops.CreateGuideCurveFinishing("GuideCurveFinishing", parentJob=job)
        op.Net = net
        op.Areas = finishing.AREA_CHOICES[0]  # the net's elementary areas, as the study machined them
    op.ToolController = controller
    op.CuspHeight = settings["cusp_height"]
    op.Tolerance = settings["tolerance"]
    op.Label = "%s (study)" % study.short_name(row)
    return op, net
