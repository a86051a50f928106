"""GUI test of the installed package (`make test-package`, beside gui_workbench.py): FreeCAD loaded HSM Planner
from its own Mod folder, every module of the package imports there, every command is registered with its icon,
and the commands that make the test parts make them."""
import importlib
import os
import pkgutil
import sys

import FreeCAD
import FreeCADGui as Gui

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import GuiRun  # noqa: E402

run = GuiRun()
MOD_DIR = os.path.join(os.path.realpath(FreeCAD.getResourceDir() + "Mod"), "HSMPlanner")


@run.step
def loaded_from_freecads_mod_folder(run):
    import hsmplanner

    run.check("hsmplanner from FreeCAD's Mod folder", hsmplanner.__file__.startswith(MOD_DIR + os.sep),
              hsmplanner.__file__)
    workbench = Gui.listWorkbenches().get("HSMPlannerWorkbench")
    run.check("workbench listed", workbench is not None, str(list(Gui.listWorkbenches())))
    run.check("the workbench says where it was loaded from", workbench is not None and MOD_DIR in workbench.ToolTip,
              getattr(workbench, "ToolTip", ""))


@run.step
def every_module_imports(run):
    import hsmplanner

    names = [name for _, name, _ in pkgutil.walk_packages(hsmplanner.__path__, "hsmplanner.")]
    failed = []
    for name in names:
        try:
            importlib.import_module(name)
        except Exception as error:  # noqa: BLE001 (each failure is named in the verdict)
            failed.append("%s: %s" % (name, error))
    run.check("every module of the package imports", not failed and len(names) > 60, "%d modules; %s"
              % (len(names), failed))
    run.notes["modules"] = len(names)


@run.step
def every_command_with_its_icon(run):
    Gui.activateWorkbench("HSMPlannerWorkbench")
    from hsmplanner.gui.commands import COMMAND_NAMES

    commands = [name for name in COMMAND_NAMES if name != "Separator"]
    missing, no_icon = [], []
    for name in commands:
        command = Gui.Command.get(name)
        if command is None:
            missing.append(name)
        elif not os.path.isfile(command.getInfo().get("pixmap", "")):
            no_icon.append("%s: %r" % (name, command.getInfo().get("pixmap")))
    run.check("every command registered", not missing, str(missing))
    run.check("every command's icon installed", not no_icon, str(no_icon))
    run.notes["commands"] = len(commands)


@run.step
def test_part_commands_make_their_parts(run):
    document = FreeCAD.newDocument("Package")
    for name in ("HSM_MasterBottomFeature", "HSM_SlantedSlotBlock", "HSM_Impeller"):
        before = len(document.Objects)
        Gui.runCommand(name)
        run.wait_until(lambda: len(document.Objects) > before and all(
            run.valid(o) for o in document.Objects[before:]), 60.0, "the objects of %s" % name)
    run.check("the test parts made", len(document.Objects) >= 5 and all(o.isValid() for o in document.Objects),
              str([(o.Name, o.State) for o in document.Objects]))
    Gui.SendMsgToActiveView("ViewFit")
    run.screenshot("package_test_parts")


run.start()
