"""Child of tests/python/bad_inputs.py: runs the cases given in $HSM_BAD_INPUT_CASES (JSON, freecadcmd), one
JSON line per case. Its memory is limited, so that a runaway case fails instead of taking the machine."""
import contextlib
import json
import math
import os
import re
import resource
import sys
import tempfile
import traceback
from unittest import mock

import FreeCAD
import numpy as np
import Part

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import bad_inputs  # noqa: E402
import hsmplanner as h  # noqa: E402

REPO = bad_inputs.REPO
SEVEN_LINES = "G1 X10 F6000\nG1 X0\nG1 X10\nG1 X0\nG1 X10\nG1 X0\nM30\n"
GCODE_OK = bad_inputs.GCODE_OK


def master_shape():
    shape = Part.Shape()
    shape.importBrepFromString(open(os.path.join(REPO, "tests", "data", "master_bottom_feature.brep")).read())
    return shape


def tilted(degrees):
    """A 40 x 30 x 5 mm plate whose top face is Face1, tilted `degrees` from horizontal about Y."""
    top = Part.makePlane(40, 30)
    top.rotate(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 1, 0), -degrees)
    return Part.Compound([top])


def plate(size):
    """A size x size mm horizontal face on its own."""
    return Part.Compound([Part.makePlane(size, size)])


def holed_plate():
    """A 30 x 20 x 5 mm plate with a 6 mm through hole at (15, 10)."""
    return Part.makeBox(30, 20, 5).cut(Part.makeCylinder(3, 5, FreeCAD.Vector(15, 10, 0)))


def top_face(shape):
    return next(i for i, f in enumerate(shape.Faces, 1) if f.BoundBox.ZMin > 4.999 and f.Surface.__class__.__name__ == "Plane")


def lowest_feed_z(moves, centre=(15.0, 10.0), radius=3.0):
    """The lowest tool tip of the feed moves over the hole (sampled every 0.05 mm along each move)."""
    lowest = math.inf
    for a, b in zip(moves[:-1], moves[1:]):
        if b[3] or a[3]:
            continue
        n = max(2, int(np.linalg.norm(b[:2] - a[:2]) / 0.05))
        for t in np.linspace(0.0, 1.0, n):
            p = a[:3] + t * (b[:3] - a[:3])
            if math.hypot(p[0] - centre[0], p[1] - centre[1]) < radius - 0.05:
                lowest = min(lowest, p[2])
    return lowest


def endless_file(size):
    path = os.path.join(tempfile.mkdtemp(prefix="hsm-bad-"), "endless.ngc")
    with open(path, "w") as stream:
        chunk = "X" * (1 << 20)
        for _ in range(size >> 20):
            stream.write(chunk)
    return path


def machine_with(**overrides):
    data = json.load(open(os.path.join(REPO, "resources", "machines", "linuxcnc-2.9.json")))
    for key, value in overrides.items():
        data["axes"]["X"][key] = value
    return data


def new_document():
    return FreeCAD.newDocument("BadInputs")


def new_master():
    from hsmplanner.app import master_feature_object
    return master_feature_object.create(new_document())


def new_net():
    from hsmplanner.app import guide_curve_net_object
    master = new_master()
    return guide_curve_net_object.create(master.Document, (master, master.Boundary1), (master, master.Boundary2),
                                         (master, master.BottomFace))


def new_direction():
    from hsmplanner.app import direction_object
    master = new_master()
    return direction_object.create(document=master.Document)


def job_with_default_controller():
    from hsmplanner.app.compat import create_job
    master = new_master()
    return master, create_job([master])


def new_planes():
    from hsmplanner.app import finishing_ops
    master, job = job_with_default_controller()
    op = finishing_ops.CreateParallelPlaneFinishing("Planes", parentJob=job)
    op.Face = (master, master.BottomFace)
    return op


def status_error(obj):
    """Raises the error a recompute left on the object, as the user reads it in the report view."""
    obj.Document.recompute()
    if not obj.isValid():
        raise ValueError(obj.getStatusString())
    return obj


def empty_job():
    """A CAM Job on the master feature with no operation."""
    return job_with_default_controller()[1]


def one_rapid_op():
    """A CAM Custom operation of one rapid, in a Job."""
    from hsmplanner.app.compat import cam_module
    job = empty_job()
    op = cam_module("custom_op").Create("Rapid", parentJob=job)
    op.Gcode = ["G0 X1 Y1 Z5"]
    job.Document.recompute()
    return job


def default_controller_finishing():
    """The user switches a finishing operation to FreeCAD's default controller (a flat end mill at F0; its label
    is "TC: Default Tool" on 1.0, "TC: 5mm Endmill" on 1.1)."""
    from hsmplanner.app.compat import tool_shape_id
    op = new_planes()
    op.ToolController = [o for o in op.Document.Objects if hasattr(o, "ToolNumber")
                         and tool_shape_id(o.Tool) == "endmill"][0]
    return status_error(op)


def feedrate_of_zero_feed():
    from hsmplanner.app import feedrate
    master, job = job_with_default_controller()
    op = new_custom(job)
    return feedrate.simulate_object(op)


def new_custom(job):
    from hsmplanner.app.compat import cam_module
    op = cam_module("custom_op").Create("Custom", parentJob=job)
    op.Gcode = ["G0 X0 Y0 Z5", "G1 Z-1 F0", "G1 X10"]
    job.Document.recompute()
    return op


def new_slot_roughing(**properties):
    """A roughing volume of the slanted slot block in its stock, computed (S1 unless told)."""
    from hsmplanner.app.roughing import volume as roughing_object, parts as roughing_parts
    part, stock = roughing_parts.create_slanted_slot_block(new_document())
    properties.setdefault("Strategy", "S1")
    obj = roughing_object.create(part, stock, **properties)
    obj.Document.recompute()
    return obj


def new_solid(shape, name="Solid", document=None):
    """A Part::Feature holding `shape` in the document (a new one by default)."""
    obj = (document or new_document()).addObject("Part::Feature", name)
    obj.Shape = shape
    return obj


def roughing_error(obj):
    """Recomputes the roughing volume and raises its error as the Report view's one line says it; checks that
    the object stays valid with no result left that looks valid (RuntimeError otherwise)."""
    obj.Document.recompute()
    if not obj.isValid():
        raise RuntimeError("the roughing volume is marked invalid: %s" % obj.getStatusString())
    if obj.Proxy.error is None:
        return obj
    if obj.SubVolumeCount or not obj.SubVolumeShape.isNull():
        raise RuntimeError("a failed roughing volume kept sub-volumes")
    if (obj.Volume != 0.0 or not obj.Shape.isNull()) and not obj.Proxy.refused:
        raise RuntimeError("a failed roughing volume kept a result")  # only a refused strategy keeps the volume
    raise ValueError(obj.Proxy.error)


@contextlib.contextmanager
def cancelling_progress(label):
    """freecad_progress as the GUI's with Cancel pressed at once."""
    yield lambda done: False


def cancelled_roughing():
    """A roughing volume recomputed with Cancel pressed: (cancelled, still valid, its previous sub-volumes kept)."""
    from hsmplanner.app.roughing import volume as roughing_object
    obj = new_slot_roughing()
    before = list(obj.SubVolumes)
    obj.Strategy = roughing_object.strategy_label("S5")
    with mock.patch.object(roughing_object, "freecad_progress", cancelling_progress):
        obj.Document.recompute()
    return obj.Proxy.cancelled, obj.isValid(), list(obj.SubVolumes) == before and len(before) == 4


def run(case):
    namespace = dict(globals())
    part = master_shape()
    namespace.update(part=part, b1=part.Edge13, b2=part.Edge14, face=part.Face4)
    report = dict(name=case["name"])
    try:
        exec(case["code"], namespace)
    except Exception as error:
        message = str(error)
        report.update(raised=type(error).__name__, message=message)
        if "error" in case:
            ok = type(error).__name__ == case["error"] and case["words"] in message
            report.update(outcome="ok" if ok else "wrong error")
        else:
            report.update(outcome="unexpected error", detail=traceback.format_exc()[-1500:])
        return report
    if "error" in case:
        report.update(outcome="no error", detail="expected %s with %r" % (case["error"], case["words"]))
        return report
    try:
        ok = bool(eval(case["check"], namespace))
    except Exception as error:
        ok, report["detail"] = False, "check raised %r" % error
    report.update(outcome="ok" if ok else "check failed", result=repr(namespace.get("result"))[:300])
    return report


def main():
    resource.setrlimit(resource.RLIMIT_AS, (bad_inputs.MEMORY_LIMIT_BYTES, bad_inputs.MEMORY_LIMIT_BYTES))
    for case in json.loads(os.environ["HSM_BAD_INPUT_CASES"]):
        # each marker on a line of its own: FreeCAD's progress text ("Recompute... (100 %)") ends without one
        print("\nHSM-CASE-START " + json.dumps(case["name"]), flush=True)
        report = run(case)
        for document in list(FreeCAD.listDocuments().values()):
            FreeCAD.closeDocument(document.Name)
        print("\nHSM-CASE-RESULT " + json.dumps(report), flush=True)


main()
