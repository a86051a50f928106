"""One place for what differs between FreeCAD 0.20 (Path workbench, PathScripts) and 1.x (CAM workbench).

FreeCAD 0.21 moved the Python modules from PathScripts.* to Path.* (Path.Op.Base, Path.Main.Job…);
FreeCAD 1.0 renamed the workbench to CAM (CAMWorkbench, commands CAM_*, preferences Mod/CAM) and kept the
Python package `Path`. Everything else in HSM Planner asks this module instead of importing those names.
"""
import importlib

import FreeCAD


def freecad_version():
    """(major, minor) of the running FreeCAD as integers."""
    major, minor = FreeCAD.Version()[:2]
    return int(major), int(minor)


def is_cam_era():
    """True from FreeCAD 1.0 on, where the Path workbench is called CAM."""
    return freecad_version() >= (1, 0)


def cam_workbench_name():
    return "CAMWorkbench" if is_cam_era() else "PathWorkbench"


def cam_command_name(name):
    """Name of a built-in Path/CAM command: cam_command_name('Job') is 'Path_Job' on 0.20, 'CAM_Job' on 1.x."""
    return ("CAM_" if is_cam_era() else "Path_") + name


def cam_menu_name():
    """The menu of the Path/CAM workbench, as a message tells a user where to find a command."""
    return "CAM" if is_cam_era() else "Path"


def cam_preferences_path():
    return "User parameter:BaseApp/Preferences/Mod/" + ("CAM" if is_cam_era() else "Path")


# Each entry: the module name on 0.21+/1.x first, then on 0.20.
_MODULES = {
    "op": ("Path.Op.Base", "PathScripts.PathOp"),
    "op_gui": ("Path.Op.Gui.Base", "PathScripts.PathOpGui"),
    "job": ("Path.Main.Job", "PathScripts.PathJob"),
    "job_gui": ("Path.Main.Gui.Job", "PathScripts.PathJobGui"),
    "tool_controller": ("Path.Tool.Controller", "PathScripts.PathToolController"),
    "tool_bit": ("Path.Tool.Bit", "PathScripts.PathToolBit"),
    "icon_view_provider": ("Path.Base.Gui.IconViewProvider", "PathScripts.PathIconViewProvider"),
    "utils": ("Path.Base.Util", "PathScripts.PathUtil"),
    "post_processor": ("Path.Post.Processor", "PathScripts.PostUtils"),
    "custom_op": ("Path.Op.Custom", "PathScripts.PathCustom"),
}


def cam_module(role):
    """The Path/CAM module that plays `role` (see _MODULES) in the running FreeCAD."""
    try:
        candidates = _MODULES[role]
    except KeyError:
        raise ValueError("unknown Path/CAM module role %r: use one of %s" % (role, ", ".join(sorted(_MODULES))))
    errors = []
    for name in candidates:
        try:
            return importlib.import_module(name)
        except ImportError as error:
            errors.append("%s: %s" % (name, error))
    raise ImportError("no Path/CAM module for %r in FreeCAD %d.%d (%s)" % ((role,) + freecad_version() + ("; ".join(errors),)))


def post_module(name):
    """A FreeCAD post-processor module by short name, e.g. post_module('linuxcnc')."""
    for module in ("Path.Post.scripts.%s_post" % name, "PathScripts.post.%s_post" % name):
        try:
            return importlib.import_module(module)
        except ImportError:
            continue
    raise ImportError("FreeCAD has no post-processor named %r: check the name (e.g. 'linuxcnc', 'grbl')" % name)


def create_tool_bit(name, shape_file):
    """A ToolBit of `shape_file` in the active document, made inside the caller's transaction. Once CAM's GUI is
    loaded, the module's Factory is its GUI factory, which opens and commits a transaction of its own ("Create
    ToolBit"): that ends the caller's, and what the caller adds after it lands in no undo step. The App factory
    makes the ToolBit here; in the GUI it gets the view provider the GUI factory would attach."""
    module = cam_module("tool_bit")
    bit = module.ToolBitFactory().Create(name, shape_file)
    if FreeCAD.GuiUp and getattr(bit, "ViewObject", None) is not None:
        cam_module("icon_view_provider").Attach(bit.ViewObject, name)
    return bit


def create_job(models, name="Job"):
    """A Path/CAM Job on `models`; in the GUI with its view provider, as FreeCAD's own command makes it
    (a Job without one breaks the operations' task panels)."""
    if FreeCAD.GuiUp:
        return cam_module("job_gui").Create(list(models), openTaskPanel=False)
    return cam_module("job").Create(name, list(models))
