"""Colours shared by the PNG pictures and the 3D view, with no import (the workbench reads them at load,
without matplotlib)."""

# 5-axis roughing: the faces' classes and the sub-volumes, alternating slice by slice. The stock skin is
# drawn see-through in the 3D view: blue over the green floor stays readable.
FACE_CLASS_COLORS = {
    "crossable": (0.25, 0.55, 0.95),         # blue: air, or stock that goes; the tool may pass
    "facing_crossable": (0.25, 0.75, 0.30),  # green: the floor the slicing may follow
    "not_crossable": (0.92, 0.35, 0.20),     # red: the part's walls
}
SLICE_COLORS = ((0.99, 0.70, 0.28), (0.30, 0.70, 0.78))
