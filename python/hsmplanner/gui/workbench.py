"""The HSM Planner workbench. InitGui.py registers it; everything else is imported on activation."""
import os

import FreeCADGui

from hsmplanner.resources import RESOURCES_DIR, icon


class HSMPlannerWorkbench(FreeCADGui.Workbench):
    MenuText = "HSM Planner"
    # Which copy FreeCAD loaded (a clone in the user's Mod folder or the package's): Init.py loads one.
    ToolTip = ("Plan and evaluate high-speed milling strategies: guide-curve finishing, feed-rate simulation "
               "(from %s)" % os.path.dirname(RESOURCES_DIR))
    Icon = icon("HSMPlanner")

    def Initialize(self):
        from hsmplanner.gui import commands

        commands.register_commands()
        self.appendToolbar("HSM Planner", commands.COMMAND_NAMES)
        self.appendMenu("HSM Planner", commands.COMMAND_NAMES)

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def GetClassName(self):
        return "Gui::PythonWorkbench"
