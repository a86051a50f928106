"""What the package's CMake asks FreeCAD (packaging/layout.cmake): where its modules and CAM's posts are, its
version and its Qt binding. Run by freecadcmd as a file: FreeCAD 1.1's `freecadcmd -c` ended with
"Application unexpectedly terminated" on the same statements given on one line."""
import os
import sys

import FreeCAD
import Path.Preferences
from PySide import QtCore  # noqa: F401 (FreeCAD's PySide loads the binding it maps to)

modules = os.path.realpath(FreeCAD.getResourceDir() + "Mod")
posts = os.path.realpath(os.path.join(Path.Preferences.pathPostSourcePath(), "scripts"))
# The Qt binding FreeCAD's PySide module maps to (Debian's packages are named after it: python3-pyside6.*,
# python3-pyside2.*); PySide.__version__ is Qt's version (5.15 for PySide2), not the binding's.
binding = next(name for name in ("PySide6", "PySide2") if name in sys.modules)
sys.stdout.write("HSM_MOD=%s\nHSM_POSTS=%s\nHSM_FREECAD=%s.%s\nHSM_PYSIDE=%s\n"
                 % (modules, posts, FreeCAD.Version()[0], FreeCAD.Version()[1], binding.lower()))
sys.stdout.flush()
