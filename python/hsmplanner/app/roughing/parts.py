"""Parametric test parts of 5-axis roughing (Part::FeaturePython): the slanted slot block and the impeller of
the roughing paper, built by the core (hsmplanner.roughing), each with its stock as a document object.

One build gives both shapes: the part object's Shape is the part, and its read-only StockShape (saved with
the document) the blank; the companion "… stock" object (TestPartStock) links to the part and shows that
blank, placed where the part is. FreeCAD recomputes the part before its stock (the link is a dependency), so
the impeller is built once per recompute; a recompute that does not change the parameters (a moved part, a
touch) reuses the last build held in memory.

Proxy class names are saved in documents: never rename them.
"""
import FreeCAD

from hsmplanner import roughing
from hsmplanner._core import roughing as core

from hsmplanner.geometry import shape_from_brep
from ..property_limits import PropertyLimits
from ..compat import set_shape
from ..proxy_state import NoSavedState

TYPE_NAME = "Part::FeaturePython"

_SLOT = core.SlantedSlotParameters()
_WHEEL = core.ImpellerParameters()

# (property type, name, core field, tooltip, default from the core) of each part
SLOT_PARAMETERS = [
    ("App::PropertyLength", "Length", "length", "the block along X", _SLOT.length),
    ("App::PropertyLength", "Width", "width", "the block along Y (the slot runs along it)", _SLOT.width),
    ("App::PropertyLength", "Height", "height", "the block along Z", _SLOT.height),
    ("App::PropertyLength", "SlotWidth", "slot_width", "width of the slot, normal to its axis", _SLOT.slot_width),
    ("App::PropertyLength", "SlotDepth", "slot_depth",
     "depth of the slot along its axis, from the top face at the axis", _SLOT.slot_depth),
    ("App::PropertyAngle", "Tilt", "tilt_deg", "the slot's axis from Z, about Y: a tool along Z cannot reach under "
     "its overhanging side (0° to under 60°)", _SLOT.tilt_deg),
]
IMPELLER_PARAMETERS = [
    ("App::PropertyInteger", "Blades", "blades", "number of blades (2 to 24): one channel between two blades",
     _WHEEL.blades),
    ("App::PropertyLength", "HubInletRadius", "hub_inlet_radius", "radius of the hub at the inlet plane",
     _WHEEL.hub_inlet_radius),
    ("App::PropertyLength", "OutletRadius", "outlet_radius", "radius of the outlet cylinder", _WHEEL.outlet_radius),
    ("App::PropertyLength", "Height", "height", "from the outlet's hub side to the inlet plane", _WHEEL.height),
    ("App::PropertyLength", "ChannelHeight", "channel_height", "from hub to shroud (the blades' height)",
     _WHEEL.channel_height),
    ("App::PropertyAngle", "Lean", "lean_deg", "angular shift of the blades from hub to tip: the channels are undercut",
     _WHEEL.lean_deg),
    ("App::PropertyAngle", "Wrap", "wrap_deg", "angular shift of the blades from inlet to outlet", _WHEEL.wrap_deg),
    ("App::PropertyLength", "Thickness", "thickness", "blade thickness", _WHEEL.thickness),
    ("App::PropertyLength", "BaseThickness", "base_thickness", "hub body below the outlet", _WHEEL.base_thickness),
]

# Property ranges (mm, degrees): beyond them the core would build a part nobody machines, or take minutes.
# The core checks what depends on several values (the slot fits the block, the blades fit the inlet).
SLOT_LIMITS = {"Length": (1.0, 1000.0), "Width": (1.0, 1000.0), "Height": (1.0, 1000.0), "SlotWidth": (0.5, 1000.0),
               "SlotDepth": (0.5, 1000.0), "Tilt": (0.0, 59.0)}
IMPELLER_LIMITS = {"Blades": (2, 24), "HubInletRadius": (1.0, 500.0), "OutletRadius": (2.0, 1000.0),
                   "Height": (1.0, 1000.0), "ChannelHeight": (0.5, 500.0), "Lean": (-30.0, 30.0),
                   "Wrap": (-120.0, 120.0), "Thickness": (0.1, 100.0), "BaseThickness": (0.5, 500.0)}


def _value(quantity):
    return quantity.Value if hasattr(quantity, "Value") else quantity


class _RoughingTestPart(PropertyLimits, NoSavedState):
    """A test part of the core: properties -> the core's parameters -> Shape (the part) and StockShape."""

    GROUP = ""
    PARAMETERS = []

    def __init__(self, obj):
        for prop_type, name, _, tooltip, default in self.PARAMETERS:
            obj.addProperty(prop_type, name, self.GROUP, tooltip)
            setattr(obj, name, default)
        obj.addProperty("Part::PropertyPartShape", "StockShape", "Stock",
                        "the blank the part is machined from (shown by its stock object)")
        obj.setEditorMode("StockShape", 2)  # hidden: the stock object shows it
        self.add_outputs(obj)
        obj.Proxy = self
        self.forget()

    def add_outputs(self, obj):
        pass

    def forget(self):
        self.built = None  # (parameters, part, stock) of the last build

    def parameters(self, obj):
        """The core's parameters, as a sorted tuple of (field, value)."""
        return tuple(sorted((field, _value(getattr(obj, name))) for _, name, field, _, _ in self.PARAMETERS))

    def build(self, parameters):
        raise NotImplementedError

    def execute(self, obj):
        """Bad parameters raise the core's ValueError (it names the parameter and the fix): FreeCAD marks the
        object invalid with that message, and the document keeps its last good shapes."""
        parameters = self.parameters(obj)
        if getattr(self, "built", None) is None or self.built[0] != parameters:
            built = self.build(dict(parameters))
            self.built = (parameters, shape_from_brep(built.part_brep), shape_from_brep(built.stock_brep))
        _, part, stock = self.built
        obj.StockShape = stock.copy()
        self.set_outputs(obj, dict(parameters))
        set_shape(obj, part.copy())

    def set_outputs(self, obj, parameters):
        pass


class SlantedSlotBlock(_RoughingTestPart):
    """A block with a slot whose axis is tilted from Z: its volume to remove has 3 crossable faces (the slot's
    mouth), 1 facing crossable (the floor) and 2 not crossable (the walls)."""

    GROUP = "Slanted slot block"
    PARAMETERS = SLOT_PARAMETERS
    LIMITS = SLOT_LIMITS

    def add_outputs(self, obj):
        obj.addProperty("App::PropertyFloat", "RemovalVolume", "Stock",
                        "the volume to remove in closed form (slot width × slot depth × block width), mm³")
        obj.setEditorMode("RemovalVolume", 1)

    def build(self, parameters):
        return roughing.slanted_slot_block(**parameters)

    def set_outputs(self, obj, parameters):
        obj.RemovalVolume = roughing.slanted_slot_volume(**parameters)


class Impeller(_RoughingTestPart):
    """A radial compressor impeller (the paper's test part): hub, lofted blades, a blank of revolution with a
    planar inlet and a cylindrical outlet. Building it takes a few seconds."""

    GROUP = "Impeller"
    PARAMETERS = IMPELLER_PARAMETERS
    LIMITS = IMPELLER_LIMITS

    def build(self, parameters):
        return roughing.impeller(**parameters)


class TestPartStock(NoSavedState):
    """The stock of a roughing test part: its StockShape, placed where the part is (read-only here)."""

    def __init__(self, obj):
        obj.addProperty("App::PropertyLink", "Part", "Stock", "the test part whose blank this is")
        obj.setEditorMode("Part", 1)
        obj.setEditorMode("Placement", 1)  # follows the part
        obj.Proxy = self

    def execute(self, obj):
        part = obj.Part
        if part is None:
            raise ValueError("%s has no part: it is the stock of a test part that was deleted; delete it too"
                             % obj.Label)
        stock = getattr(part, "StockShape", None)
        if stock is None or stock.isNull():
            raise ValueError("%s has no stock yet: fix its parameters and recompute" % part.Label)
        if obj.Placement != part.Placement:
            obj.Placement = part.Placement
        set_shape(obj, stock.copy())


def is_test_part(obj):
    return isinstance(getattr(obj, "Proxy", None), _RoughingTestPart)


def is_test_part_stock(obj):
    return type(getattr(obj, "Proxy", None)).__name__ == "TestPartStock"


def stock_of(part):
    """The stock object of a test part, or None."""
    return next((o for o in getattr(part, "InList", []) if is_test_part_stock(o) and o.Part == part), None)


def _create(proxy_class, document, name):
    document = document or FreeCAD.ActiveDocument
    if document is None:
        raise ValueError("no document to add the %s to: open or create a document first" % proxy_class.GROUP.lower())
    part = document.addObject(TYPE_NAME, name)
    proxy_class(part)
    stock = document.addObject(TYPE_NAME, name + "Stock")
    TestPartStock(stock)
    stock.Label = part.Label + " stock"
    stock.Part = part
    part.recompute()
    stock.recompute()
    return part, stock


def create_slanted_slot_block(document=None, name="SlantedSlotBlock"):
    """Add the slanted slot block and its stock to `document` (the active one by default), recomputed:
    (part, stock)."""
    return _create(SlantedSlotBlock, document, name)


def create_impeller(document=None, name="Impeller"):
    """Add the impeller and its stock to `document` (the active one by default), recomputed: (part, stock).
    Takes a few seconds."""
    return _create(Impeller, document, name)
