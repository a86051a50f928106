"""Parametric "Roughing volume" (Part::FeaturePython): the volume to remove between a stock and a part, its
faces classed crossable / facing crossable / not crossable, and its partition into sub-volumes by one of the
five slicings of the roughing paper. Thin: properties wired to hsmplanner.roughing.

Its Shape is what the 3D view shows (Display): the volume to remove (a compound of one solid per region), or
the sub-volumes (a compound of their solids). FaceColorIndex says, per face of Shape, its class or its slice,
so that the view provider colours the faces from saved properties only. Both shapes are kept (hidden
VolumeShape and SubVolumeShape, saved with the document), so that switching Display computes nothing; and
InputSignature, a fingerprint of the inputs the saved result was computed from, lets a recompute whose
inputs did not change (a touch, a reopened document, a cancelled panel) reuse it. In memory the last volume
and the recent partitions are kept, so that trying strategies does not compute stock − part again.

A bad input (ValueError from our checks or the core) or a failed boolean (RuntimeError from the core) is
reported on one line in the Report view, the object stays valid with empty results; Cancel in the progress
dialog (hsmplanner.Cancelled) keeps the previous result and leaves the object to recompute.

The Proxy class name is saved in documents: never rename it.
"""
import collections
import hashlib

import FreeCAD
import Part

import hsmplanner
from hsmplanner import roughing
from hsmplanner._core import roughing as core

from hsmplanner.geometry import shape_from_brep
from ..properties import HIDDEN, add_inputs, add_results
from ..feedrate import is_job
from ..progress import freecad_progress, in_background, staged
from ..property_limits import PropertyLimits
from ..compat import set_shape
from ..proxy_state import NoSavedState
from .parts import is_test_part, is_test_part_stock, stock_of

TYPE_NAME = "Part::FeaturePython"
_SETTINGS = core.PartitionSettings()  # the core's defaults (each written once, in C++)

STRATEGY_NONE = "None (volume only)"
STRATEGY_KEYS = ["S1", "S2", "S3", "S4", "S5"]
STRATEGIES = [STRATEGY_NONE] + [roughing.STRATEGY_LABELS[key] for key in STRATEGY_KEYS]
FACE_CLASSES, SUB_VOLUMES = "Face classes", "Sub-volumes"
DISPLAYS = [FACE_CLASSES, SUB_VOLUMES]
# FaceColorIndex of a face with Display = Face classes (the core's FaceClass names, in this order)
CLASS_NAMES = ["crossable", "facing_crossable", "not_crossable"]
DISPLAY_FALLBACK = "Display: no sub-volumes (Strategy is None or failed): the face classes are shown"

_INPUTS = [
    # type, name, group, tooltip, default
    ("App::PropertyLink", "Part", "Roughing", "the part: a closed solid (a test part, a Body, a Job's model)", None),
    ("App::PropertyLink", "Stock", "Roughing",
     "the blank: a Path/CAM Job's stock (or the Job), or any closed solid that contains the part", None),
    ("App::PropertyEnumeration", "Strategy", "Roughing",
     "how the volume is cut into sub-volumes (the paper's S1-S5), or not at all", STRATEGIES),
    ("App::PropertyLength", "Step", "Partition",
     "distance between slicing surfaces: the axial engagement, e.g. 8 mm for a Ø8 tool", _SETTINGS.step),
    ("App::PropertyInteger", "Region", "Partition",
     "the region (solid of the volume to remove, one per channel of an impeller) to partition: 1 = the largest; "
     "0 = all regions (slow on the impeller: up to seconds per channel)", 1),
    ("App::PropertyAngle", "SetupResolution", "Partition (S3)",
     "S3: the setup directions are searched down to this spacing", _SETTINGS.setup_resolution_deg),
    ("App::PropertyLength", "SetupGrid", "Partition (S3)",
     "S3: spacing of the volume's points whose reach is counted", _SETTINGS.setup_grid),
    ("App::PropertyEnumeration", "Display", "Display",
     "the 3D view shows the volume with its faces coloured by class, or the sub-volumes in alternating colours "
     "by slice", DISPLAYS),
]
_OUTPUTS = [
    ("App::PropertyInteger", "RegionCount", "regions (solids) of the volume to remove, e.g. one per channel"),
    ("App::PropertyFloat", "Volume", "the volume to remove, stock − part, mm³"),
    ("App::PropertyFloat", "StockVolume", "the stock's volume, mm³"),
    ("App::PropertyFloat", "PartVolume", "the part's volume, mm³"),
    ("App::PropertyFloatList", "RegionVolumes", "volume of each region, largest first, mm³"),
    ("App::PropertyStringList", "FaceClassCounts",
     "per region, its surfaces by class (the faces of one surface count once)"),
    ("App::PropertyInteger", "SubVolumeCount", "sub-volumes of the partition"),
    ("App::PropertyFloatList", "SubVolumes", "volume of each sub-volume, in slicing order, mm³"),
    ("App::PropertyIntegerList", "SubVolumeSlices",
     "slice of each sub-volume: 0 at the reference surface, then inwards"),
    ("App::PropertyIntegerList", "SubVolumeRegions", "region of each sub-volume"),
    ("App::PropertyVector", "SetupDirection",
     "S3: the tool axis of the setup (of the first region partitioned); zero for the other strategies"),
    ("App::PropertyFloat", "SetupReach", "S3: share (0-1) of the volume a straight tool along SetupDirection reaches"),
    ("App::PropertyStringList", "Warnings", "what the computation had to decide or could not do"),
    ("App::PropertyIntegerList", "FaceColorIndex",
     "per face of Shape: its class (0 crossable, 1 facing crossable, 2 not crossable), or its slice with Display "
     "= Sub-volumes (what the 3D view colours)"),
]
_STORED = [  # hidden: the result of both displays and what it was computed from
    ("Part::PropertyPartShape", "VolumeShape", "the volume to remove: one solid per region"),
    ("App::PropertyIntegerList", "VolumeFaceClasses", "class of each face of VolumeShape"),
    ("Part::PropertyPartShape", "SubVolumeShape", "the sub-volumes: their solids"),
    ("App::PropertyIntegerList", "SubVolumeFaceSlices", "slice of each face of SubVolumeShape"),
    ("App::PropertyString", "InputSignature", "fingerprint of the inputs of the saved result"),
]
INPUT_NAMES = [entry[1] for entry in _INPUTS]

# The task panel's ranges (mm, degrees); the core refuses more (a step beyond the volume, too many slices).
LIMITS = {"Step": (0.5, 500.0), "Region": (0, 999), "SetupResolution": (0.5, 45.0), "SetupGrid": (0.25, 50.0)}
PARTITION_CACHE = 12  # partitions kept in memory


def _solids(shape):
    return [shape] if shape.ShapeType == "Solid" else list(shape.Solids)


def shape_fingerprint(shape):
    """What identifies a shape's geometry across saving and reopening (BREP text does not: tolerances and
    flags are rewritten): topology counts, volume, area and every vertex, rounded well above their noise."""
    digest = hashlib.sha1()
    digest.update(("%s %d %d %d %d %.9g %.9g" % (shape.ShapeType, len(shape.Solids), len(shape.Faces), len(shape.Edges),
                                                len(shape.Vertexes), shape.Volume, shape.Area)).encode())
    for vertex in shape.Vertexes:
        digest.update(("%.6f %.6f %.6f;" % (vertex.X, vertex.Y, vertex.Z)).encode())
    return digest.hexdigest()


def jobs(document):
    return [o for o in document.Objects if is_job(o)]


def job_stock(job):
    return getattr(job, "Stock", None)


def is_job_stock(obj):
    return obj is not None and any(job_stock(job) == obj for job in jobs(obj.Document))


def has_solid(obj):
    shape = getattr(obj, "Shape", None)
    return shape is not None and not shape.isNull() and len(shape.Solids) > 0


def default_stock(part):
    """The stock that goes with `part`: a test part's own stock, the stock of the Job whose model holds
    (a clone of) it, or of the document's only Job; else None."""
    if part is None:
        return None
    if is_test_part(part):
        return stock_of(part)
    candidates = jobs(part.Document)
    holding = [job for job in candidates if any(model == part or (getattr(model, "Objects", None) or [None])[0] == part
                                                 for model in getattr(getattr(job, "Model", None), "Group", []))]
    for job in holding or (candidates if len(candidates) == 1 else []):
        if job_stock(job) is not None:
            return job_stock(job)
    return None


def part_and_stock(first, second):
    """(part, stock) of two solids picked in any order: a stock object (a test part's, a Job's) is the stock;
    else the larger solid."""
    for a, b in ((first, second), (second, first)):
        if is_test_part_stock(b) or is_job_stock(b) or is_job(b):
            return a, b
    return (first, second) if first.Shape.Volume <= second.Shape.Volume else (second, first)


def linked_solid(obj, name):
    """(object, shape) that the link property `name` of the roughing volume points to, checked."""
    target = getattr(obj, name)
    what = "the part (a closed solid)" if name == "Part" else "the blank (a Job's stock or a solid around the part)"
    if target is None:
        raise ValueError("%s is not set: link %s" % (name, what))
    if is_job(target):
        if name != "Stock":
            raise ValueError("Part is the Job %s: link the part (the Job's model), not the Job" % target.Label)
        if job_stock(target) is None:
            raise ValueError("Stock is the Job %s, which has no stock: give the Job a stock or link a solid"
                             % target.Label)
        target = job_stock(target)
    shape = getattr(target, "Shape", None)
    if shape is None or shape.isNull():
        raise ValueError("%s %s has no shape: recompute it, or link %s" % (name, target.Label, what))
    return target, shape


def shown_display(obj):
    """The display the Shape holds: Sub-volumes only when there are sub-volumes."""
    if obj.Display == SUB_VOLUMES and not obj.SubVolumeShape.isNull():
        return SUB_VOLUMES
    return FACE_CLASSES


def class_counts(solid):
    """'crossable 3, facing_crossable 1, not_crossable 2': the surfaces of a RemovalSolid by class (a surface
    split into several faces, by a periodic seam, counts once)."""
    first = {}
    for group, face_class in zip(solid.face_groups, solid.face_classes):
        first.setdefault(group, face_class.name)
    counts = collections.Counter(first.values())
    return ", ".join("%s %d" % (name, counts.get(name, 0)) for name in CLASS_NAMES)


class StrategyRefused(ValueError):
    """The volume to remove was computed, the strategy cannot partition it (its reference face is missing): the
    volume and its face classes stay, with no sub-volumes."""


class RoughingVolume(PropertyLimits, NoSavedState):
    LIMITS = LIMITS

    def __init__(self, obj):
        add_inputs(obj, _INPUTS)
        add_results(obj, _OUTPUTS)
        add_results(obj, _STORED, mode=HIDDEN)
        obj.Proxy = self
        self.forget()

    def forget(self):
        self.error, self.cancelled, self.refused = None, False, False
        self.volume_cache = None  # (key, VolumeToRemove, part BREP)
        self.partition_cache = collections.OrderedDict()

    # --- inputs ---------------------------------------------------------------------------------------------
    @staticmethod
    def strategy_key(obj):
        return None if obj.Strategy == STRATEGY_NONE else roughing.strategy(obj.Strategy).name

    def settings(self, obj):
        key = self.strategy_key(obj)
        return dict(strategy=key, step=obj.Step.Value, region=obj.Region,
                    setup_resolution_deg=obj.SetupResolution.Value if key == "S3" else None,
                    setup_grid=obj.SetupGrid.Value if key == "S3" else None)

    @staticmethod
    def inputs(obj):
        part, part_shape = linked_solid(obj, "Part")
        stock, stock_shape = linked_solid(obj, "Stock")
        if part == stock:
            raise ValueError("Part and Stock are both %s: link the blank the part is machined from as Stock"
                             % part.Label)
        return part_shape, stock_shape

    # --- computing ------------------------------------------------------------------------------------------
    def execute(self, obj):
        if not hasattr(self, "partition_cache"):  # a proxy restored without its in-memory state
            self.forget()
        self.error, self.cancelled, self.refused = None, False, False
        try:
            self.run(obj)
        except hsmplanner.Cancelled:
            self.cancelled = True
            FreeCAD.Console.PrintWarning("%s: cancelled: the previous result is kept (recompute to compute it again)\n"
                                         % obj.Label)
            _stay_touched(obj)
        except (ValueError, RuntimeError) as error:  # bad input, or the core's boolean failed: one line
            self.error = str(error) or type(error).__name__
            FreeCAD.Console.PrintError("%s: %s\n" % (obj.Label, self.error))
            self.refused = isinstance(error, StrategyRefused)
            if not self.refused:
                self.failed(obj)

    def run(self, obj):
        """Computes what changed and stores the result; raises ValueError, RuntimeError or Cancelled."""
        part_shape, stock_shape = self.inputs(obj)
        settings = self.settings(obj)
        volume_key = (shape_fingerprint(part_shape), shape_fingerprint(stock_shape))
        signature = hashlib.sha1(repr((volume_key, sorted(settings.items()))).encode()).hexdigest()
        if signature == obj.InputSignature and not obj.VolumeShape.isNull():
            self.show(obj)  # the saved result is of these inputs: only the display may have changed
            return
        cached = self.volume_cache is not None and self.volume_cache[0] == volume_key
        with freecad_progress("%s: volume to remove%s" % (obj.Label, ", partition" if settings["strategy"] else "")) \
                as progress:
            stage_volume, stage_partitions = staged(progress, [0 if cached else 1, 2 if settings["strategy"] else 0])
            if not cached:
                part_brep = hsmplanner.as_brep(part_shape.copy())  # without the display's triangulation
                volume = in_background(roughing.volume_to_remove, stock_shape.copy(), part_brep,
                                       progress=stage_volume)
                self.volume_cache = (volume_key, volume, part_brep)
                self.partition_cache.clear()
            _, volume, part_brep = self.volume_cache
            try:
                partitions = self.partitions(obj, volume, part_brep, volume_key, settings, stage_partitions)
            except ValueError as error:  # a strategy this volume cannot take: the volume itself still shows
                self.store(obj, volume, [])
                obj.InputSignature = ""
                self.show(obj)
                raise StrategyRefused(str(error)) from None
            # stored and drawn with the dialog open: the drawing serves the GUI's events (progress.breathe)
            self.store(obj, volume, partitions)
            obj.InputSignature = signature
            self.show(obj)

    def computed(self, obj, progress=None):
        """(VolumeToRemove, part BREP, stock BREP, [(region index, Partition)]) of the object's inputs, from
        the caches when they hold them (a reopened document computes them again, reporting to `progress`): for
        the operations that sweep the sub-volumes. Raises as a recompute does."""
        if not hasattr(self, "partition_cache"):
            self.forget()
        part_shape, stock_shape = self.inputs(obj)
        settings = self.settings(obj)
        volume_key = (shape_fingerprint(part_shape), shape_fingerprint(stock_shape))
        stage_volume, stage_partitions = staged(progress, [1, 2])
        if self.volume_cache is None or self.volume_cache[0] != volume_key:
            part_brep = hsmplanner.as_brep(part_shape.copy())
            volume = in_background(roughing.volume_to_remove, stock_shape.copy(), part_brep, progress=stage_volume)
            self.volume_cache = (volume_key, volume, part_brep)
            self.partition_cache.clear()
        _, volume, part_brep = self.volume_cache
        partitions = self.partitions(obj, volume, part_brep, volume_key, settings, stage_partitions)
        return volume, part_brep, hsmplanner.as_brep(stock_shape.copy()), partitions

    def partitions(self, obj, volume, part_brep, volume_key, settings, progress):
        """[(region index, Partition)] of the regions asked for (Region), from the cache when computed before."""
        if settings["strategy"] is None:
            return []
        count = len(volume.solids)
        region = settings["region"]
        if not 0 <= region <= count:
            raise ValueError("Region %d: the volume to remove has %d region%s: give 1 to %d (1 = the largest), or "
                             "0 for all" % (region, count, "" if count == 1 else "s", count))
        indices = list(range(count)) if region == 0 else [region - 1]
        stages = staged(progress, [1] * len(indices))
        result = []
        for index, stage in zip(indices, stages):
            key = (volume_key, index, tuple(sorted((k, v) for k, v in settings.items() if k != "region")))
            if key not in self.partition_cache:
                self.partition_cache[key] = in_background(
                    roughing.partition,
                    volume.solids[index], part_brep, settings["strategy"], step=settings["step"],
                    setup_resolution_deg=settings["setup_resolution_deg"], setup_grid=settings["setup_grid"],
                    progress=stage)
                while len(self.partition_cache) > PARTITION_CACHE:
                    self.partition_cache.popitem(last=False)
            elif stage is not None:
                stage(1.0)
            result.append((index, self.partition_cache[key]))
        return result

    def store(self, obj, volume, partitions):
        regions, classes = [], []
        for solid in volume.solids:
            shape = shape_from_brep(solid.brep)
            regions += _solids(shape)
            classes += [CLASS_NAMES.index(c.name) for c in solid.face_classes]
        volume_shape = Part.Compound(regions)
        if len(volume_shape.Faces) != len(classes):
            raise RuntimeError("the volume's %d faces do not match the core's %d classes: report it"
                               % (len(volume_shape.Faces), len(classes)))
        pieces, slices, volumes, piece_slices, piece_regions = [], [], [], [], []
        warnings = list(volume.warnings)
        if volume.fuzzy_retry:
            warnings.append("the boolean stock − part needed a fuzzy value (near-coincident faces)")
        for index, partition in partitions:
            for sub_volume in partition.sub_volumes:
                for solid in _solids(shape_from_brep(sub_volume.brep)):
                    pieces.append(solid)
                    slices += [sub_volume.slice] * len(solid.Faces)
                volumes.append(sub_volume.volume)
                piece_slices.append(sub_volume.slice)
                piece_regions.append(index + 1)
            prefix = "region %d: " % (index + 1) if len(partitions) > 1 else ""
            warnings += [prefix + warning for warning in partition.warnings]
        sub_shape = Part.Compound(pieces) if pieces else Part.Shape()
        if pieces and len(sub_shape.Faces) != len(slices):
            raise RuntimeError("the sub-volumes' faces do not add up (%d, %d): report it" % (len(sub_shape.Faces),
                                                                                          len(slices)))
        for warning in warnings:
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, warning))
        obj.VolumeShape, obj.VolumeFaceClasses = volume_shape, classes
        obj.SubVolumeShape, obj.SubVolumeFaceSlices = sub_shape, slices
        obj.RegionCount = len(volume.solids)
        obj.Volume, obj.StockVolume, obj.PartVolume = volume.volume, volume.stock_volume, volume.part_volume
        obj.RegionVolumes = [solid.volume for solid in volume.solids]
        obj.FaceClassCounts = [class_counts(solid) for solid in volume.solids]
        obj.SubVolumeCount = len(volumes)
        obj.SubVolumes, obj.SubVolumeSlices, obj.SubVolumeRegions = volumes, piece_slices, piece_regions
        setup = partitions[0][1] if partitions and self.strategy_key(obj) == "S3" else None
        obj.SetupDirection = FreeCAD.Vector(*[float(x) for x in setup.setup_direction]) if setup else FreeCAD.Vector()
        obj.SetupReach = float(setup.setup_reach) if setup else 0.0
        obj.Warnings = warnings

    def show(self, obj):
        """Shape and FaceColorIndex of the display asked for (FaceColorIndex last: the view redraws on it)."""
        if shown_display(obj) == SUB_VOLUMES:
            shape, codes = obj.SubVolumeShape, list(obj.SubVolumeFaceSlices)
        else:
            shape, codes = obj.VolumeShape, list(obj.VolumeFaceClasses)
        warnings = [w for w in obj.Warnings if w != DISPLAY_FALLBACK]
        if obj.Display == SUB_VOLUMES and shown_display(obj) != SUB_VOLUMES:
            warnings.append(DISPLAY_FALLBACK)
        if warnings != list(obj.Warnings):
            obj.Warnings = warnings
        set_shape(obj, shape.copy() if not shape.isNull() else Part.Shape())
        obj.FaceColorIndex = codes

    def failed(self, obj):
        """Empties the result (a bad input leaves no result that looks valid)."""
        obj.VolumeShape, obj.VolumeFaceClasses = Part.Shape(), []
        obj.SubVolumeShape, obj.SubVolumeFaceSlices = Part.Shape(), []
        obj.InputSignature = ""
        obj.RegionCount, obj.Volume, obj.StockVolume, obj.PartVolume = 0, 0.0, 0.0, 0.0
        obj.RegionVolumes, obj.FaceClassCounts = [], []
        obj.SubVolumeCount, obj.SubVolumes, obj.SubVolumeSlices, obj.SubVolumeRegions = 0, [], [], []
        obj.SetupDirection, obj.SetupReach = FreeCAD.Vector(), 0.0
        obj.Warnings = []
        set_shape(obj, Part.Shape())
        obj.FaceColorIndex = []

    def onDocumentRestored(self, obj):
        self.forget()


class _TouchAfterRecompute:
    """Document observer that touches a cancelled roughing volume once the recompute is over, so that it is
    still to be recomputed (FreeCAD clears the touched flag when execute returns; touching it from execute, or
    from a timer that FreeCAD's recompute lets run, makes FreeCAD execute it again at once, uncancelled)."""

    def __init__(self, obj):
        self.document, self.name = obj.Document.Name, obj.Name

    def slotRecomputedDocument(self, document):
        if document.Name != self.document:
            return
        FreeCAD.removeDocumentObserver(self)
        obj = document.getObject(self.name)
        if obj is not None and getattr(obj.Proxy, "cancelled", False):  # not computed since
            obj.touch()


def _stay_touched(obj):
    """After a cancelled recompute the object keeps its previous result and must still be recomputed."""
    FreeCAD.addDocumentObserver(_TouchAfterRecompute(obj))


def create(part=None, stock=None, document=None, name="RoughingVolume", recompute=True, **properties):
    """Add a roughing volume of `part` (a document object holding a solid) in `stock` (default: the test part's
    stock, or the Job's), with any property given by name (Strategy='S5', Step=6, Region=0…), recomputed when
    both are known (unless recompute=False)."""
    document = document or (part.Document if part is not None else FreeCAD.ActiveDocument)
    if document is None:
        raise ValueError("no document: open or create one first")
    unknown = sorted(set(properties) - set(INPUT_NAMES))
    if unknown:
        raise ValueError("a Roughing volume has no property %s: use %s" % (", ".join(map(repr, unknown)),
                                                                           ", ".join(INPUT_NAMES)))
    obj = document.addObject(TYPE_NAME, name)
    RoughingVolume(obj)
    if part is not None:
        obj.Part = part
    stock = stock if stock is not None else default_stock(part)
    if stock is not None:
        obj.Stock = stock
    strategy = properties.pop("Strategy", None)
    if strategy is not None:
        obj.Strategy = strategy_label(strategy)
    for key, value in properties.items():
        setattr(obj, key, value)
    if recompute and obj.Part is not None and obj.Stock is not None:
        obj.recompute()
    return obj


def strategy_label(value):
    """The Strategy enumeration's label of 'S3', 3, a Strategy, a label, or None / 'None'."""
    if value is None or (isinstance(value, str) and value.strip().lower().startswith("none")):
        return STRATEGY_NONE
    return roughing.STRATEGY_LABELS[roughing.strategy(value).name]
