"""One place for what differs between FreeCAD 0.20 (Path workbench, PathScripts) and 1.x (CAM workbench).

FreeCAD 0.21 moved the Python modules from PathScripts.* to Path.* (Path.Op.Base, Path.Main.Job…);
FreeCAD 1.0 renamed the workbench to CAM (CAMWorkbench, commands CAM_*, preferences Mod/CAM) and kept the
Python package `Path`. Everything else in HSM Planner asks this module instead of importing those names.
"""
import importlib
import os

import FreeCAD


def freecad_version():
    """(major, minor) of the running FreeCAD as integers: (1, 1) for 1.1.3, (26, 3) for the year-numbered 26.3 that
    follows 1.1 (so comparisons such as >= (1, 1) hold for it), a development suffix ("3dev") left out."""
    return tuple(_leading_number(part) for part in FreeCAD.Version()[:2])


def _leading_number(text):
    digits = ""
    for character in str(text).strip():
        if not character.isdigit():
            break
        digits += character
    if not digits:
        raise ValueError("FreeCAD reports version %r: no number to read" % (FreeCAD.Version()[:2],))
    return int(digits)


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
    """A FreeCAD post-processor script by short name, e.g. post_module('linuxcnc'): a module whose
    export(objects, filename, arguments) writes the program. From 26.3 on FreeCAD's class-based posts took the
    short names and the scripts are `NAME_legacy_post`."""
    for module in ("Path.Post.scripts.%s_post" % name, "Path.Post.scripts.%s_legacy_post" % name,
                   "PathScripts.post.%s_post" % name):
        try:
            found = importlib.import_module(module)
        except ImportError:
            continue
        if hasattr(found, "export"):
            return found
    raise ImportError("FreeCAD has no post-processor named %r: check the name (e.g. 'linuxcnc', 'grbl')" % name)


def has_tool_assets():
    """True where FreeCAD's tool bits come from its tool library's assets (1.1: ToolBit.from_dict, shapes by
    id such as 'bullnose'); False where a ToolBit is made from a shape file (0.20, 1.0)."""
    try:
        from Path.Tool.toolbit import ToolBit
    except ImportError:
        return False
    return hasattr(ToolBit, "from_dict")


def tool_shape_id(tool):
    """The shape of a FreeCAD tool in lower case ('ballend', 'bullnose', 'endmill'…), whichever FreeCAD made it:
    1.1's ShapeType ('Bullnose'), 1.0's and 0.20's shape file (…/bullnose.fcstd), a legacy tool's ToolType."""
    for attribute in ("ShapeType", "ShapeID", "ShapeName", "BitShape"):
        value = str(getattr(tool, attribute, "") or "")
        if value and value != "Custom":
            return os.path.splitext(os.path.basename(value))[0].lower().replace(" ", "")
    return str(getattr(tool, "ToolType", "") or "").lower()


def tool_corner_radius(tool):
    """The corner radius of a bullnose tool, mm: 1.1's CornerRadius, or 1.0's Diameter / 2 − FlatRadius."""
    if hasattr(tool, "CornerRadius"):
        return float(tool.CornerRadius)
    return 0.5 * float(tool.Diameter) - float(getattr(tool, "FlatRadius", 0.0))


def create_tool_bit(name, label, shape_id, diameter, corner_radius=None):
    """A ToolBit of FreeCAD's tool shape `shape_id` ('ballend', 'bullnose') in the active document, made inside
    the caller's transaction: on 1.1 from its tool library (the shape asset), on 1.0 from the shape file.

    Once CAM's GUI is loaded, 1.0's ToolBit module's Factory is its GUI factory, which opens and commits a
    transaction of its own ("Create ToolBit"): that ends the caller's, and what the caller adds after it lands
    in no undo step. The App factory makes the ToolBit here; in the GUI it gets the view provider the GUI
    factory would attach (1.1's attach_to_doc attaches its own)."""
    if has_tool_assets():
        from Path.Tool.toolbit import ToolBit

        parameters = {"Diameter": "%g mm" % diameter}
        if corner_radius is not None:
            parameters["CornerRadius"] = "%g mm" % corner_radius
        bit = ToolBit.from_dict({"shape": shape_id, "name": label, "parameter": parameters})
        transaction = FreeCAD.getActiveTransaction()
        tool = bit.attach_to_doc(FreeCAD.ActiveDocument, label=name)
        if transaction is not None and FreeCAD.getActiveTransaction() is None:
            # 1.1's GUI ends the caller's transaction when the tool library makes the bit's body (in a document of
            # its own): what the caller adds next must still be undoable, under the same name
            FreeCAD.ActiveDocument.openTransaction(transaction[0])
        tool.Label = label
        return tool
    module = cam_module("tool_bit")
    shape_file = module.findToolShape(shape_id + ".fcstd")
    if not shape_file:
        raise RuntimeError("FreeCAD's %s.fcstd tool shape is missing from this installation" % shape_id)
    tool = module.ToolBitFactory().Create(name, shape_file)
    if FreeCAD.GuiUp and getattr(tool, "ViewObject", None) is not None:
        cam_module("icon_view_provider").Attach(tool.ViewObject, name)
    tool.Diameter = diameter
    if corner_radius is not None:
        tool.FlatRadius = 0.5 * diameter - corner_radius
    tool.Label = label
    return tool


def set_shape(obj, shape):
    """obj.Shape = shape. FreeCAD 1.1 names the new shape's elements after the old one's, and on an object
    restored from a FreeCAD 0.20 document that naming fails ("Unknown C++ exception"): there the old shape is
    dropped first, as an object with no shape yet takes any."""
    try:
        obj.Shape = shape
    except getattr(FreeCAD.Base, "FreeCADError", RuntimeError):
        import Part

        obj.Shape = Part.Shape()
        obj.Shape = shape


def create_job(models, name="Job"):
    """A Path/CAM Job on `models`; in the GUI with its view provider, as FreeCAD's own command makes it
    (a Job without one breaks the operations' task panels)."""
    if FreeCAD.GuiUp:
        return cam_module("job_gui").Create(list(models), openTaskPanel=False)
    return cam_module("job").Create(name, list(models))
