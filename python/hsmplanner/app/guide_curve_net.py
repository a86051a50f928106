"""Guide curve nets on FreeCAD shapes: a pure function from the picked edges and face to Part geometry.

The document object (guide_curve_net_object.py) and the GUI preview both call build_guide_curve_net().
"""
from dataclasses import dataclass, field

import Part

import hsmplanner
from hsmplanner import _core

FOUR_STEP = "4-step method"  # hsmplanner.guidance_curves; the other modes are the core's NetMode
# Modes as the user reads them (saved in documents: never rename) -> the core's.
MODES = {
    FOUR_STEP: None,
    "Boundary 1 to boundary 2": _core.NetMode.b1_to_b2,
    "Boundary 2 to boundary 1": _core.NetMode.b2_to_b1,
    "Median only": _core.NetMode.median,
    "Median to boundaries": _core.NetMode.median_to_boundaries,
    "Boundaries to median": _core.NetMode.boundaries_to_median,
}
DEFAULT_MODE = FOUR_STEP
# The core's defaults (each written once, in C++): K and K of the median of the 4-step method, its initial
# step P, the net's gap and fit tolerance.
_GUIDANCE = _core.GuidanceSettings()


@dataclass(frozen=True)
class NetParameters:
    mode: str = DEFAULT_MODE
    k: float = _GUIDANCE.k                        # ratio of the net (the 4-step method's K after the median)
    step: float = _GUIDANCE.net.step              # P, mm (the 4-step method's initial step)
    direction: tuple = None                       # machining direction; None = the boundaries' length direction
    min_gap: float = _GUIDANCE.net.min_gap        # mm
    fit_tolerance: float = _GUIDANCE.net.fit_tolerance  # mm
    k_median: float = _GUIDANCE.k_median          # 4-step method only

    def core_mode(self):
        try:
            return MODES[self.mode]
        except KeyError:
            raise ValueError("mode %r is unknown: use one of %s" % (self.mode, ", ".join(MODES)))


@dataclass
class GuideNetResult:
    net: object                              # hsmplanner.CurveNet
    report: object = None                    # hsmplanner GuidanceReport (4-step method only)
    edges: list = field(default_factory=list)    # Part.Edge per curve, B1 … B2
    regions: list = field(default_factory=list)  # per elementary area: (lower, upper, Part.Shape, area mm²)

    @property
    def labels(self):
        return [c.label for c in self.net.curves]

    def composed_area_names(self):
        """'MA1: B1|Cmed, Cmed|B2' … for each composed machining area."""
        labels = self.labels
        return ["MA%d: %s" % (j + 1, ", ".join("%s|%s" % (labels[a], labels[b]) for a, b in ma))
                for j, ma in enumerate(self.net.composed_areas())]


def _edge(brep):
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    return shape.Edges[0]


def build_guide_curve_net(boundary_1, boundary_2, face=None, parameters=NetParameters(), with_regions=True,
                          progress=None):
    """The net between two boundary shapes (edges or wires), on `face` if given, as Part geometry.

    with_regions=False skips the split of the face into elementary areas (the slow part: ~0.2 s), for
    live previews. progress: a callable progress(done) that cancels by returning False (curve_net's).
    """
    mode = parameters.core_mode()
    report = None
    if mode is None:
        net, report = hsmplanner.guidance_curves(
            boundary_1, boundary_2, direction=parameters.direction, face=face, step=parameters.step,
            k_median=parameters.k_median, k=parameters.k, min_gap=parameters.min_gap,
            fit_tolerance=parameters.fit_tolerance)
    else:
        net = hsmplanner.curve_net(boundary_1, boundary_2, parameters.k, parameters.step,
                                   direction=parameters.direction, mode=mode, face=face,
                                   min_gap=parameters.min_gap, fit_tolerance=parameters.fit_tolerance,
                                   progress=progress)
    result = GuideNetResult(net=net, report=report, edges=[_edge(c.to_brep()) for c in net.curves])
    if face is not None and with_regions:
        for lower, upper, brep, area in hsmplanner.area_regions(net, face):
            shape = Part.Shape()
            shape.importBrepFromString(brep)
            result.regions.append((lower, upper, shape, area))
    return result
