"""What the package's CMake asks FreeCAD (packaging/layout.cmake): where its modules and CAM's posts are, its
version and its Qt binding's. Run by freecadcmd as a file: FreeCAD 1.1's `freecadcmd -c` ended with
"Application unexpectedly terminated" on the same statements given on one line."""
import os
import sys

import FreeCAD
import Path.Preferences
import PySide

modules = os.path.realpath(FreeCAD.getResourceDir() + "Mod")
posts = os.path.realpath(os.path.join(Path.Preferences.pathPostSourcePath(), "scripts"))
sys.stdout.write("HSM_MOD=%s\nHSM_POSTS=%s\nHSM_FREECAD=%s.%s\nHSM_PYSIDE=%s\n"
                 % (modules, posts, FreeCAD.Version()[0], FreeCAD.Version()[1], PySide.__version__))
sys.stdout.flush()
