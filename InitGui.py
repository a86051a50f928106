# HSM Planner: exec'd by the FreeCAD GUI after every Init.py. Registers the workbench of the copy Init.py loaded
# (its python/ on sys.path); the real code is in python/hsmplanner/gui.
def _hsm_planner_loaded_here():
    import inspect
    import os
    import sys

    here = os.path.normpath(os.path.dirname(os.path.abspath(inspect.currentframe().f_code.co_filename)))
    return os.path.join(here, "python") in sys.path


if _hsm_planner_loaded_here():
    import FreeCADGui as _hsm_gui
    from hsmplanner.gui.workbench import HSMPlannerWorkbench

    _hsm_gui.addWorkbench(HSMPlannerWorkbench())
    del _hsm_gui
del _hsm_planner_loaded_here
