"""Probe paths: points of a face along a zigzag raster, as Path commands.

Not a finishing strategy (no tool radius, no gouge check): a path that follows a real face with the
short-block character of a CAM program, for the feed-rate simulator's examples and tests.
"""
import math

import numpy as np
import Path

import hsmplanner


def raster_on_face(face, pass_spacing=2.0, point_spacing=0.5, angle_deg=0.0):
    """Zigzag passes over `face` at `angle_deg` from X: a list of (N,3) arrays of points on the face."""
    if pass_spacing <= 0 or point_spacing <= 0:
        raise ValueError("pass spacing %g and point spacing %g must be positive" % (pass_spacing, point_spacing))
    box = face.BoundBox
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    corners = np.array([[x, y] for x in (box.XMin, box.XMax) for y in (box.YMin, box.YMax)])
    along, across = corners @ np.array([c, s]), corners @ np.array([-s, c])
    passes = []
    for k, offset in enumerate(np.arange(across.min() + pass_spacing / 2, across.max(), pass_spacing)):
        t = np.arange(along.min(), along.max() + point_spacing, point_spacing)
        plan = np.column_stack([t * c - offset * s, t * s + offset * c, np.full_like(t, box.ZMax + 1.0)])
        points, inside = hsmplanner.drop_on_face(face, plan)
        points = points[inside]
        if len(points) > 1:
            passes.append(points if k % 2 == 0 else points[::-1])
    return passes


def passes_to_commands(passes, feed_mm_min, safe_height):
    """Path commands for the passes: rapid above each start, plunge, G1 along, retract. F in mm/s (FreeCAD)."""
    feed = feed_mm_min / 60.0
    commands = [Path.Command("G0", {"Z": safe_height})]
    for points in passes:
        x, y, z = points[0]
        commands.append(Path.Command("G0", {"X": x, "Y": y}))
        commands.append(Path.Command("G1", {"Z": z, "F": feed}))
        commands += [Path.Command("G1", {"X": px, "Y": py, "Z": pz, "F": feed}) for px, py, pz in points[1:]]
        commands.append(Path.Command("G0", {"Z": safe_height}))
    return commands


def make_probe_job(part, feed_mm_min=4000.0, pass_spacing=2.0, point_spacing=0.5, name="Job"):
    """A Path/CAM Job on `part` (a master bottom feature) with a Custom operation holding the raster of its
    bottom face: a real Job, operation and tool controller that posts and simulates like any other."""
    from .compat import cam_module, create_job

    job = create_job([part], name)
    op = cam_module("custom_op").Create("ProbeRaster", parentJob=job)
    bottom = part.Shape.getElement(part.BottomFace)
    passes = raster_on_face(bottom, pass_spacing, point_spacing)
    op.Gcode = [c.toGCode() for c in passes_to_commands(passes, feed_mm_min, bottom.BoundBox.ZMax + 5.0)]
    part.Document.recompute()
    return job, op
