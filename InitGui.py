# HSM Planner: exec'd by the FreeCAD GUI after every Init.py. Registers the workbench; the real code is
# in python/hsmplanner/gui (Init.py put python/ on sys.path).
import FreeCADGui as _hsm_gui
from hsmplanner.gui.workbench import HSMPlannerWorkbench

_hsm_gui.addWorkbench(HSMPlannerWorkbench())
