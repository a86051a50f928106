# HSM Planner: exec'd by FreeCAD at start-up, in the GUI and in freecadcmd, from its folder: a clone linked into
# the user's Mod folder (`make build`) or the Debian package's copy in FreeCAD's own Mod folder. One copy is
# loaded: FreeCAD skips a system module folder named as a user one, and under other names a copy in the
# user's Mod folder goes before the system one. The loaded copy's python/ goes first on sys.path, so that
# `import hsmplanner` is that copy and no other one found on sys.path.
def _hsm_planner_load():
    import inspect
    import os
    import sys

    import FreeCAD

    def is_copy(folder):
        return os.path.isfile(os.path.join(folder, "InitGui.py")) and \
            os.path.isfile(os.path.join(folder, "python", "hsmplanner", "__init__.py"))

    here = os.path.normpath(os.path.dirname(os.path.abspath(inspect.currentframe().f_code.co_filename)))
    copies = [os.path.normpath(d) for d in getattr(FreeCAD, "__ModDirs__", []) if is_copy(d)] or [here]
    user_mod = os.path.realpath(os.path.join(FreeCAD.getUserAppDataDir(), "Mod"))
    users = [d for d in copies if os.path.dirname(d) == user_mod]
    loaded = (users or copies)[0]
    if loaded != here:
        FreeCAD.Console.PrintWarning("HSM Planner in %s not loaded: the one in %s is\n" % (here, loaded))
        return False
    python_dir = os.path.join(here, "python")
    if python_dir in sys.path:
        sys.path.remove(python_dir)
    sys.path.insert(0, python_dir)
    FreeCAD.Console.PrintLog("HSM Planner loaded from %s\n" % here)
    return True


if _hsm_planner_load():
    # Documents saved with FreeCAD 0.20 name their Job's proxies by 0.20 module names (PathScripts.PathJob…):
    # resolve those to FreeCAD 1.x's modules before any document opens.
    import hsmplanner_legacy_modules as _hsm_legacy_modules

    _hsm_legacy_modules.install()
    del _hsm_legacy_modules
del _hsm_planner_load
