"""Build the master bottom feature (the guidance-curve paper's test part) and write it out.

    freecadcmd examples/master_bottom_feature.py [OUTPUT_DIR]      (default: out/)

Writes master_bottom_feature.FCStd (the parametric document object), .step (the solid), .brep (the
solid), master_bottom_feature.json (names of the bottom face and boundary edges, plan radii, inflections)
and master_bottom_feature.png (3D and plan views).
"""
import json
import os
import sys

import FreeCAD
import Import
import numpy as np
import Part

import hsmplanner
from hsmplanner import plan_analysis
from hsmplanner.app import master_feature_object
from hsmplanner.plots.curve_nets import plot_part_with_curves
from hsmplanner.scripting import output_dir, run_script


def describe_boundary(edge):
    points = hsmplanner.sample_curve(edge, 1401)
    radius, at = plan_analysis.min_radius_xy(points)
    return points, {
        "length_mm": round(edge.Length, 3),
        "min_plan_radius_mm": round(radius, 3),
        "min_plan_radius_at_mm": [round(v, 3) for v in points[at]],
        "inflections_at_mm": [[round(v, 2) for v in points[i]] for i in plan_analysis.inflection_indices(points)],
    }


def plan_gap(points_1, points_2, length):
    """Y distance between the boundaries in plan view, every millimetre along X."""
    xs = np.linspace(0.0, length, int(length) + 1)
    ys = [np.interp(xs, *p[np.argsort(p[:, 0])][:, :2].T) for p in (points_1, points_2)]
    return ys[1] - ys[0]


def main(argv):
    out = output_dir(argv)
    document = FreeCAD.newDocument("MasterBottomFeature")
    obj = master_feature_object.create(document)
    if not obj.isValid():
        raise RuntimeError("master bottom feature failed to recompute: %s" % obj.State)
    shape = obj.Shape
    base = os.path.join(out, "master_bottom_feature")
    document.saveAs(base + ".FCStd")
    Import.export([obj], base + ".step")
    shape.exportBrep(base + ".brep")

    bottom = shape.getElement(obj.BottomFace)
    b1_points, b1 = describe_boundary(shape.getElement(obj.Boundary1))
    b2_points, b2 = describe_boundary(shape.getElement(obj.Boundary2))
    gap = plan_gap(b1_points, b2_points, obj.Length.Value)
    summary = {
        "parameters": {p: getattr(obj, p).Value for p in ("Length", "Width", "Depth", "Sag", "DraftAngle")},
        "bottom_face": obj.BottomFace, "boundary_1": obj.Boundary1, "boundary_2": obj.Boundary2,
        "volume_mm3": round(hsmplanner.shape_summary(shape).volume, 1), "bottom_area_mm2": round(bottom.Area, 1),
        "boundary_1_detail": b1, "boundary_2_detail": b2,
        "boundary_gap_min_max_mm": [round(float(gap.min()), 2), round(float(gap.max()), 2)],
    }
    with open(base + ".json", "w") as stream:
        json.dump(summary, stream, indent=2)

    meshes = []
    for face in shape.Faces:
        if isinstance(face.Surface, Part.Plane) and face.Surface.Axis.z < 0.9:
            continue  # outer sides and underside of the block would hide the cavity in the picture
        vertices, triangles = face.tessellate(0.1)
        colour = (0.85, 0.65, 0.35) if face.isSame(bottom) else (0.62, 0.66, 0.72)
        meshes.append((np.array([tuple(v) for v in vertices]), np.array(triangles), colour))
    marks = [(b1["min_plan_radius_at_mm"][0], b1["min_plan_radius_at_mm"][1], "R %.1f" % b1["min_plan_radius_mm"])]
    marks += [(x, y, "inflection") for x, y, _ in b1["inflections_at_mm"]]
    plot_part_with_curves(
        meshes, [(b1_points, "#cc0000", "boundary 1 (%s)" % obj.Boundary1),
                 (b2_points, "#3465a4", "boundary 2 (%s)" % obj.Boundary2)],
        base + ".png", "Master bottom feature: %s between two flanks, open at x = 0 and x = %g mm"
        % (obj.BottomFace, obj.Length.Value), plan_marks=marks, plan_title="plan view of the boundaries")
    print("master bottom feature written to %s: bottom %s, boundaries %s and %s, plan radius of boundary 1 "
          "down to %.1f mm" % (out, obj.BottomFace, obj.Boundary1, obj.Boundary2, b1["min_plan_radius_mm"]))
    FreeCAD.closeDocument(document.Name)


run_script(main)
