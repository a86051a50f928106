"""Colours of HSM Planner views: the roles of curves, the elementary areas, the roughing volume."""
from hsmplanner.plots import palette as _PALETTE

CURVE_COLORS = {
    "boundary": (0.10, 0.10, 0.10),
    "median": (0.85, 0.10, 0.10),
    "intermediate": (0.10, 0.30, 0.85),
}
REGION_BORDER = (0.55, 0.55, 0.55)

# Distinct, light enough that the curves read on top of them.
AREA_PALETTE = [
    (0.99, 0.75, 0.44), (0.65, 0.85, 0.62), (0.62, 0.78, 0.95), (0.96, 0.62, 0.70), (0.85, 0.76, 0.96),
    (0.99, 0.90, 0.55), (0.60, 0.90, 0.88), (0.92, 0.80, 0.70), (0.78, 0.90, 0.55), (0.90, 0.68, 0.90),
]


def area_color(index):
    return AREA_PALETTE[index % len(AREA_PALETTE)]


def view_color(rgb, transparency=0.0):
    """A colour of a view object's DiffuseColor or LineColorArray, `transparency` in [0, 1]: FreeCAD 1.0 reads
    the fourth value as the transparency, 1.1 as the alpha (1 − transparency; 0 would draw nothing)."""
    from hsmplanner.app.compat import freecad_version

    return tuple(rgb) + ((1.0 - transparency) if freecad_version() >= (1, 1) else transparency,)


# Roughing volume: the faces' classes, and the sub-volumes in alternating colours by slice: the PNG
# pictures' colours (hsmplanner.plots.palette), in FaceColorIndex order.
FACE_CLASS_COLORS = [_PALETTE.FACE_CLASS_COLORS[name] for name in ("crossable", "facing_crossable", "not_crossable")]
FACE_CLASS_LABELS = ["crossable", "facing crossable", "not crossable"]
FACE_CLASS_TIPS = ["stock skin: the tool may pass through it",
                   "a face of the part that sees the stock skin (a hub, a slot's floor): slices may follow it",
                   "any other face of the part (blade sides, slot walls)"]
SLICE_COLORS = list(_PALETTE.SLICE_COLORS)
# ASCII: the 3D view's legend font (Coin's SoText2) has no "…" and drew "&" for it.
SLICE_LABELS = ["even slices (0, 2, 4...)", "odd slices (1, 3, 5...)"]
