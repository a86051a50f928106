# HSM Planner: exec'd by FreeCAD at start-up, in the GUI and in freecadcmd. FreeCAD puts this folder on
# sys.path (there is no __file__ here); add its python/ folder so that `import hsmplanner` works.
def _hsm_planner_add_python_path():
    import os
    import sys

    for entry in list(sys.path):
        package = os.path.join(entry, "python", "hsmplanner", "__init__.py")
        if os.path.isfile(package) and os.path.isfile(os.path.join(entry, "InitGui.py")):
            python_dir = os.path.join(entry, "python")
            if python_dir not in sys.path:
                sys.path.append(python_dir)
            return


_hsm_planner_add_python_path()
del _hsm_planner_add_python_path


# Documents saved with FreeCAD 0.20 name their Job's proxies by 0.20 module names (PathScripts.PathJob…):
# resolve those to FreeCAD 1.x's modules before any document opens.
import hsmplanner_legacy_modules as _hsm_legacy_modules

_hsm_legacy_modules.install()
del _hsm_legacy_modules
