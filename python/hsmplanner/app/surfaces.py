"""Test surfaces of the machining-direction paper, built with Part (pure functions)."""
import math

import FreeCAD
import Part


def cylinder_top(radius=10.0, half_width=6.0, length=50.0):
    """Case 1: the top of a cylinder of `radius` about Y (|x| ≤ half_width), z up."""
    half = math.asin(half_width / radius)
    surface = Part.Cylinder()
    surface.Radius = radius
    surface.Axis = FreeCAD.Vector(0, 1, 0)
    surface.Center = FreeCAD.Vector(0, 0, 0)
    face = surface.toShape(-half, half, 0.0, length)
    # Part.Cylinder's angle 0 points along X: turn it so that the middle of the face is on top.
    face.rotate(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 1, 0), -90)
    return face


def valleys(size=100.0, height=15.0, wavelength=45.0, angle_deg=45.0, grid=41):
    """A case-2-like surface in a size × size × height box: valleys running at angle_deg from X, of concave
    radius wavelength²/(2π²·height) at their bottoms (6.8 mm by default: tight enough for a Ø10 ball to
    slow the machine across them)."""
    a = math.radians(angle_deg)
    across = (-math.sin(a), math.cos(a))
    rows = []
    for i in range(grid):
        row = []
        for j in range(grid):
            x, y = size * i / (grid - 1), size * j / (grid - 1)
            u = x * across[0] + y * across[1]
            row.append(FreeCAD.Vector(x, y, 0.5 * height * (1.0 - math.cos(2.0 * math.pi * u / wavelength))))
        rows.append(row)
    surface = Part.BSplineSurface()
    surface.interpolate(rows)
    return Part.Face(surface)
