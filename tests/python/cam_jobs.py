"""A Job of FreeCAD CAM's own operations on a test block, made headless as CAM's own tests make them: what the
cycle time and the feed-rate analysis must read. The block (100 x 60 x 20 mm) has a pocket 40 x 20 x 5 mm on
top and two Ø12 through holes."""
import FreeCAD
import Part

from hsmplanner.app.compat import cam_module, create_job, freecad_version

# (operation module, name, the faces or edges it works on: "top", "pocket", "holes", "pocket edges", "pocket
# edge", or None for the whole model, settings)
OPERATIONS = [
    ("Path.Op.Profile", "Profile", None, {}),
    ("Path.Op.PocketShape", "PocketShape", "pocket", {}),
    ("Path.Op.Adaptive", "Adaptive", "pocket", {}),
    ("Path.Op.MillFace", "Face", "top", {"BoundaryShape": "Stock"}),  # 1.0 faces nothing in "Boundbox"
    ("Path.Op.Drilling", "Drilling", "holes", {}),
    ("Path.Op.Drilling", "PeckDrilling", "holes", {"PeckEnabled": True, "PeckDepth": 3.0}),
    ("Path.Op.Drilling", "DwellDrilling", "holes", {"DwellEnabled": True, "DwellTime": 0.5}),
    ("Path.Op.Helix", "Helix", "holes", {}),
    ("Path.Op.Engrave", "Engrave", "pocket edges", {}),
    ("Path.Op.Slot", "Slot", "pocket edge", {}),
    ("Path.Op.Deburr", "Deburr", "pocket edges", {}),
]
# Dressups CAM applies to an operation above: (module, the operation dressed)
DRESSUPS = [("Path.Dressup.Tags", "Profile"), ("Path.Dressup.DogboneII", "PocketShape")]


def block_part(document):
    box = Part.makeBox(100, 60, 20)
    pocket = Part.makeBox(40, 20, 5, FreeCAD.Vector(10, 10, 15))
    holes = [Part.makeCylinder(6, 30, FreeCAD.Vector(x, y, -5)) for x, y in ((75, 20), (75, 40))]
    shape = box.cut(pocket).cut(Part.makeCompound(holes)).removeSplitter()
    part = document.addObject("Part::Feature", "CamBlock")
    part.Shape = shape
    document.recompute()
    return part


def features(part):
    """Face and edge names of the block's features."""
    faces = part.Shape.Faces
    named = {}
    tops = [i for i, f in enumerate(faces, 1) if f.Surface.__class__.__name__ == "Plane"
            and abs(f.normalAt(0, 0).z - 1) < 1e-9]
    named["top"] = ["Face%d" % max(tops, key=lambda i: faces[i - 1].BoundBox.ZMax)]
    named["pocket"] = ["Face%d" % i for i in tops if abs(faces[i - 1].BoundBox.ZMax - 15.0) < 1e-6]
    named["holes"] = ["Face%d" % i for i, f in enumerate(faces, 1) if f.Surface.__class__.__name__ == "Cylinder"]
    floor = faces[int(named["pocket"][0][4:]) - 1]
    named["pocket edges"] = ["Edge%d" % (i + 1) for i, e in enumerate(part.Shape.Edges)
                             if any(e.isSame(w) for w in floor.OuterWire.Edges)]
    named["pocket edge"] = named["pocket edges"][:1]
    return named


def cam_job(document, operations=OPERATIONS):
    """(part, job, {name: operation}) with the Job's default controller given feeds (a 5 mm end mill at 800 / 300
    mm/min, rapids 3000 / 1500), every operation recomputed."""
    import importlib

    part = block_part(document)
    job = create_job([part])
    controller = job.Tools.Group[0]
    controller.HorizFeed = FreeCAD.Units.Quantity("800 mm/min")
    controller.VertFeed = FreeCAD.Units.Quantity("300 mm/min")
    controller.HorizRapid = FreeCAD.Units.Quantity("3000 mm/min")
    controller.VertRapid = FreeCAD.Units.Quantity("1500 mm/min")
    controller.SpindleSpeed = 10000
    named = features(part)
    ops = {}
    for module_name, name, where, settings in operations:
        op = create_operation(importlib.import_module(module_name), name, job)
        if where is not None:
            op.Base = [(part, named[where])]
        for key, value in settings.items():
            setattr(op, key, value)
        ops[name] = op
    document.recompute()
    return part, job, ops


def dress(document, ops, dressups=DRESSUPS):
    """{module: dressup} of CAM's dressups on the operations `ops` holds, put in the Job before the operation
    they dress as CAM's dressup commands put them (some modules' Create does it, others leave it to the
    command), recomputed."""
    import importlib

    made = {}
    for module, base in dressups:
        dressup = importlib.import_module(module).Create(ops[base])
        job = ops[base].Proxy.getJob(ops[base])
        if dressup not in job.Operations.Group:
            job.Proxy.addOperation(dressup, ops[base])
        made[module] = dressup
    document.recompute()
    return made


def create_operation(module, name, job):
    """An operation as CAM's command makes it (module.Create). FreeCAD 1.0's Drilling and Helix Create look for
    every hole of the Job's model before the proxy has read the model (a TypeError on None): there the proxy
    is made as Create makes it, without that search (the caller sets Base)."""
    proxy_class = {"Path.Op.Drilling": "ObjectDrilling", "Path.Op.Helix": "ObjectHelix"}.get(module.__name__)
    if proxy_class and freecad_version() < (1, 1):
        op = job.Document.addObject("Path::FeaturePython", name)
        op.Proxy = getattr(module, proxy_class)(op, name, job)
        return op
    return module.Create(name, parentJob=job)


def custom_op(job, name, lines):
    """CAM's Custom operation with `lines` of G-code, recomputed."""
    op = cam_module("custom_op").Create(name, parentJob=job)
    op.Gcode = list(lines)
    job.Document.recompute()
    return op
