"""The master bottom feature: the test part of the guidance-curve paper (its Fig. 1), built with Part.

A forging-die cavity: a curved bottom face about 140 mm long between two drafted flanks. Seen from above,
boundary 1 (the edge between the bottom and flank 1) has an inflection and a small-radius bump; boundary 2
curves gently the other way, so the two are far from parallel. The cavity is open at both ends (x = 0 and
x = length), where it would run into the next cavities of the die.

Pure functions: parameters in, Part shapes out. The document object lives in master_feature_object.py.
"""
import math
from dataclasses import dataclass

import FreeCAD
import Part

# Plan-view shapes of the two boundaries for a 140 × 50 mm cavity, as (x, y) points that a cubic
# B-spline interpolates. Points beyond 0..140 extend the flanks past the open ends so that the cut
# through the block is clean. Boundary 1: rises into a tight bump near x = 50 (radius under 10 mm),
# falls through an inflection and rises again. Boundary 2: one gentle concave sweep.
_BOUNDARY_1 = [(-10, 1.0), (0, 1.5), (20, 3.0), (36, 8.0), (46, 15.5), (52, 16.5), (58, 12.0),
               (70, 4.0), (90, 0.0), (110, 2.0), (130, 9.0), (140, 12.0), (150, 14.5)]
_BOUNDARY_2 = [(-10, 53.0), (0, 52.0), (25, 48.5), (50, 42.0), (75, 40.0), (100, 44.5),
               (125, 53.0), (140, 57.0), (150, 59.5)]
_REFERENCE_LENGTH = 140.0
_REFERENCE_WIDTH = 50.0


@dataclass(frozen=True)
class MasterFeatureParameters:
    """Dimensions in mm and degrees. Defaults reproduce the paper's 140 mm feature."""

    length: float = 140.0        # along X, the machining direction of the paper ("L140")
    width: float = 50.0          # nominal distance between the boundaries at x = 0
    depth: float = 25.0          # mean depth of the bottom below the top of the block
    sag: float = 5.0             # the bottom dips this much more at mid-length
    draft_angle: float = 5.0     # flank draft from vertical, degrees (forging dies need draft)

    def validate(self):
        checks = [
            (40.0 <= self.length <= 2000.0, "length %g mm is outside 40..2000 mm" % self.length),
            (10.0 <= self.width <= 1000.0, "width %g mm is outside 10..1000 mm" % self.width),
            (5.0 <= self.depth <= 500.0, "depth %g mm is outside 5..500 mm" % self.depth),
            (0.0 <= self.sag < self.depth * 0.8, "sag %g mm must be >= 0 and below 0.8 x depth" % self.sag),
            (0.0 <= self.draft_angle <= 15.0, "draft angle %g° is outside 0..15°" % self.draft_angle),
        ]
        for ok, message in checks:
            if not ok:
                raise ValueError("master bottom feature: " + message)


@dataclass
class MasterFeature:
    """The part and the names of the sub-shapes the guidance-curve strategy starts from."""

    shape: Part.Shape           # the die block with its cavity, one solid
    bottom_face: str            # e.g. "Face7": the curved bottom
    boundary_1: str             # e.g. "Edge12": bottom/flank-1 edge (the one with the bump)
    boundary_2: str             # bottom/flank-2 edge


def boundary_curve(params, which, z=0.0, shift=0.0):
    """Plan-view boundary `which` (1 or 2) as a B-spline at height z, moved by `shift` mm in Y."""
    sx = params.length / _REFERENCE_LENGTH
    sy = params.width / _REFERENCE_WIDTH
    points = _BOUNDARY_1 if which == 1 else _BOUNDARY_2
    curve = Part.BSplineCurve()
    curve.interpolate([FreeCAD.Vector(x * sx, y * sy + shift, z) for x, y in points])
    return curve


def bottom_height(params, x, y):
    """Height of the bottom surface: a valley along X, concave across, with a twist."""
    u = x / params.length
    v = (y - 0.5 * params.width) / (0.5 * params.width)
    return (-params.depth - params.sag * math.sin(math.pi * u) + 0.12 * params.width * v * v
            + 0.04 * params.width * v * math.sin(2.0 * math.pi * u))


def bottom_surface(params):
    """B-spline surface through a grid of bottom_height, wider than the cavity on every side."""
    margin_x, margin_y = 0.1 * params.length, 0.6 * params.width
    xs = [-margin_x + i * (params.length + 2 * margin_x) / 16 for i in range(17)]
    ys = [-margin_y + j * (params.width + 2 * margin_y) / 12 for j in range(13)]
    grid = [[FreeCAD.Vector(x, y, bottom_height(params, x, y)) for y in ys] for x in xs]
    surface = Part.BSplineSurface()
    surface.interpolate(grid)
    return surface


def _footprint_wire(params, z, spread):
    """Closed plan outline of the cavity at height z, each boundary moved outwards by `spread`."""
    b1 = boundary_curve(params, 1, z, -spread).toShape()
    b2 = boundary_curve(params, 2, z, +spread).toShape()
    end = Part.LineSegment(b1.Vertexes[-1].Point, b2.Vertexes[-1].Point).toShape()
    start = Part.LineSegment(b2.Vertexes[0].Point, b1.Vertexes[0].Point).toShape()
    b2.reverse()
    return Part.Wire([b1, end, b2, start])


def cavity_solid(params):
    """The material the cavity removes: drafted flanks above the bottom surface, past both ends."""
    top_z = 10.0
    low_z = -(params.depth + params.sag + 0.3 * params.width)
    spread = (top_z - low_z) * math.tan(math.radians(params.draft_angle))
    flanks = Part.makeLoft([_footprint_wire(params, low_z, 0.0), _footprint_wire(params, top_z, spread)],
                           True, True)
    below = Part.Face(bottom_surface(params)).extrude(FreeCAD.Vector(0, 0, low_z - 10.0 - params.depth))
    return flanks.cut(below)


def make_master_bottom_feature(params=None):
    """Build the die block with the cavity and name its bottom face and the two boundary edges."""
    params = params or MasterFeatureParameters()
    params.validate()
    block_y0 = -0.5 * params.width
    block = Part.makeBox(params.length, 2.0 * params.width, params.depth + params.sag + 0.4 * params.width,
                         FreeCAD.Vector(0, block_y0, -(params.depth + params.sag + 0.4 * params.width)))
    shape = block.cut(cavity_solid(params)).removeSplitter()
    solids = shape.Solids
    if len(solids) != 1:
        raise RuntimeError("master bottom feature: the cut gave %d solids instead of 1" % len(solids))
    shape = solids[0]
    bottom_index = _find_bottom_face(shape)
    b1, b2 = _find_boundaries(shape, bottom_index, params)
    return MasterFeature(shape, "Face%d" % (bottom_index + 1), "Edge%d" % (b1 + 1), "Edge%d" % (b2 + 1))


def _find_bottom_face(shape):
    """The bottom is the only non-planar face whose normal points up."""
    candidates = []
    for index, face in enumerate(shape.Faces):
        if isinstance(face.Surface, Part.Plane):
            continue
        u0, u1, v0, v1 = face.ParameterRange
        normal = face.normalAt(0.5 * (u0 + u1), 0.5 * (v0 + v1))
        if normal.z > 0.5:
            candidates.append((face.Area, index))
    if len(candidates) != 1:
        raise RuntimeError("master bottom feature: expected one bottom face, found %d" % len(candidates))
    return candidates[0][1]


def _find_boundaries(shape, bottom_index, params):
    """Bottom edges that do not lie in the open-end planes x = 0 and x = length; boundary 1 has lower y."""
    bottom = shape.Faces[bottom_index]
    edge_index = {edge.hashCode(): i for i, edge in enumerate(shape.Edges)}
    boundaries = []
    for edge in bottom.Edges:
        box = edge.BoundBox
        on_open_end = box.XLength < 1e-6 and (abs(box.XMin) < 1e-6 or abs(box.XMin - params.length) < 1e-6)
        if not on_open_end:
            boundaries.append((box.Center.y, edge_index[edge.hashCode()]))
    if len(boundaries) != 2:
        raise RuntimeError("master bottom feature: expected 2 boundary edges, found %d" % len(boundaries))
    boundaries.sort()
    return boundaries[0][1], boundaries[1][1]
