"""The stock's top and bottom from exact geometry, for the heights FreeCAD derives from them.

FreeCAD's operation base reads OpStockZMin/OpStockZMax from the stock's Shape.BoundBox, and a stock made
from the models sizes itself by the models' Shape.BoundBox: both read the triangulation the 3D view leaves on
a displayed part and the looser control points of one never displayed. The Safe and Clearance heights
(expressions on OpStockZMax) and every retract taken from them then differed between the GUI and freecadcmd
for the same document.
"""
import FreeCAD


def exact_box(shapes):
    """The exact box (geometry only) of the non-empty shapes among `shapes`; None when there is none."""
    box = None
    for shape in shapes:
        if shape is None or shape.isNull():
            continue
        part = shape.optimalBoundingBox(False, False)
        box = part if box is None else box.united(part)
    return box


def exact_stock_z(job):
    """(bottom, top) of the Job's stock, exact; None when the Job has no stock shape."""
    stock = getattr(job, "Stock", None)
    if stock is None:
        return None
    base = getattr(stock, "Base", None)
    if base is not None and hasattr(stock, "ExtZpos"):  # the models' box grown by the stock's extents
        models = exact_box(o.Shape for o in getattr(base, "Group", []) if hasattr(o, "Shape"))
        if models is not None:
            return models.ZMin - stock.ExtZneg.Value, models.ZMax + stock.ExtZpos.Value
    box = exact_box([stock.Shape]) if hasattr(stock, "Shape") else None
    return None if box is None else (box.ZMin, box.ZMax)


def use_exact_stock_depths(obj, job):
    """Sets the operation's OpStockZMin/OpStockZMax to the stock's exact bottom and top (from opUpdateDepths,
    before FreeCAD evaluates the height expressions)."""
    heights = exact_stock_z(job) if job is not None else None
    if heights is None or not hasattr(obj, "OpStockZMax"):
        return
    obj.OpStockZMin = FreeCAD.Units.Quantity(heights[0], FreeCAD.Units.Length)
    obj.OpStockZMax = FreeCAD.Units.Quantity(heights[1], FreeCAD.Units.Length)
