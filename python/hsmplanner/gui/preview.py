"""Live preview of a guide curve net in the 3D view (Coin nodes, no document object touched).

Curves are drawn by role; each elementary area is filled between its two curves (sampled, a little above
the face), which is what the eye needs while K and P move; the exact split of the face waits for OK.
"""
import FreeCADGui
import hsmplanner
import numpy as np
from pivy import coin

from .colors import CURVE_COLORS, area_color

SAMPLES = 120
LIFT = 0.3  # mm above the face, so that the fill does not fight with the face's own shading


class NetPreview:
    def __init__(self):
        self.root = coin.SoSeparator()
        self.root.setName("HSMGuideCurveNetPreview")
        self.view = None

    def attach(self):
        if self.view is None and FreeCADGui.ActiveDocument is not None:
            self.view = FreeCADGui.ActiveDocument.ActiveView
            self.view.getSceneGraph().addChild(self.root)

    def detach(self):
        if self.view is not None:
            try:
                self.view.getSceneGraph().removeChild(self.root)
            except RuntimeError:  # the view is gone already (document closed)
                pass
            self.view = None

    def clear(self):
        self.root.removeAllChildren()

    def show(self, net):
        """Draw a hsmplanner.CurveNet."""
        self.attach()
        self.clear()
        samples = [np.asarray(c.sample(SAMPLES)) for c in net.curves]
        samples = [s if s[-1, 0] >= s[0, 0] else s[::-1] for s in samples]  # boundaries may run backwards
        for index, (lower, upper) in enumerate(net.elementary_areas()):
            self.root.addChild(_strip(samples[lower], samples[upper], area_color(index)))
        for curve, points in zip(net.curves, samples):
            self.root.addChild(_polyline(points, CURVE_COLORS.get(curve.role.name, (0, 0, 0)),
                                         3.0 if curve.role != hsmplanner.CurveRole.boundary else 2.0))


def _polyline(points, color, width):
    group = coin.SoSeparator()
    material = coin.SoBaseColor()
    material.rgb = color
    style = coin.SoDrawStyle()
    style.lineWidth = width
    coords = coin.SoCoordinate3()
    coords.point.setValues(0, len(points), [tuple(p + (0, 0, 2 * LIFT)) for p in points])
    line = coin.SoLineSet()
    line.numVertices.setValue(len(points))
    for node in (material, style, coords, line):
        group.addChild(node)
    return group


def _strip(lower, upper, color):
    """Triangle strip between two polylines of the same length."""
    group = coin.SoSeparator()
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR  # flat colours: the areas read as a map, not as relief
    material = coin.SoMaterial()
    material.diffuseColor = color
    material.transparency = 0.2
    hints = coin.SoShapeHints()
    hints.vertexOrdering = coin.SoShapeHints.UNKNOWN_ORDERING
    coords = coin.SoCoordinate3()
    interleaved = np.empty((2 * len(lower), 3))
    interleaved[0::2] = lower
    interleaved[1::2] = upper
    interleaved[:, 2] += LIFT
    coords.point.setValues(0, len(interleaved), [tuple(p) for p in interleaved])
    strip = coin.SoTriangleStripSet()
    strip.numVertices.setValue(len(interleaved))
    for node in (light, material, hints, coords, strip):
        group.addChild(node)
    return group
