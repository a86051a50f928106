"""The HSM Planner workbench. InitGui.py registers it; everything else is imported on activation."""
import FreeCADGui

from hsmplanner.resources import icon


class HSMPlannerWorkbench(FreeCADGui.Workbench):
    MenuText = "HSM Planner"
    ToolTip = "Plan and evaluate high-speed milling strategies: guide-curve finishing, feed-rate simulation"
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
