"""HSM Planner core API: planning and evaluation of high-speed milling strategies.

This package imports without FreeCAD. It re-exports the compiled core (hsmplanner._core) with small
adapters that accept FreeCAD shapes, BREP text or numpy arrays. The FreeCAD layers live in the
subpackages hsmplanner.app (document objects, Path/CAM operations) and hsmplanner.gui (workbench).
"""
try:
    from . import _core
except ImportError as error:  # the module is built by `make build`; say so instead of a bare ImportError
    raise ImportError(
        "hsmplanner._core is not built or was built for another Python: run `make build` in the "
        "HSM Planner folder (the module is built for FreeCAD's /usr/bin/python3). Cause: %s" % error
    ) from error

from ._core import (BSplineCurve, Cancelled, ControllerKind, CurveNet, CurveRole, NetCurve, NetMode, ShapeSummary, Sweep,
                    __version__)
from .curvenet import area_regions, as_curve, curve_net, guidance_curves, intermediate_curve
from .direction import optimal_direction, simulated_directions
from .feedsim import DEFAULT_MACHINE, load_machine, machine_names, simulate, simulate_moves
from .geometry import as_brep, drop_on_face, sample_curve, shape_summary
from .toolpaths import guide_finishing, parallel_finishing

__all__ = ["BSplineCurve", "Cancelled", "ControllerKind", "CurveNet", "CurveRole", "DEFAULT_MACHINE", "NetCurve", "NetMode",
           "ShapeSummary", "Sweep", "__version__", "area_regions", "as_brep", "as_curve", "curve_net", "drop_on_face",
           "guide_finishing", "guidance_curves", "intermediate_curve", "load_machine", "machine_names",
           "optimal_direction", "parallel_finishing", "sample_curve", "shape_summary", "simulate", "simulate_moves",
           "simulated_directions"]
