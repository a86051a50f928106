"""Module names that saved documents hold and that moved, resolved to their successors: FreeCAD 0.20's Path
modules (so that documents saved with FreeCAD 0.20 restore the proxies of their Job, stock, setup sheet, tool
controllers and tool bits), and HSM Planner's own roughing modules, gathered into hsmplanner.app.roughing.

A saved document records each proxy by module and class ("PathScripts.PathJob", "ObjectJob"). FreeCAD 0.21
moved those modules to Path.* (Path.Main.Job…) and FreeCAD 1.0 keeps no alias for them (only
PathScripts.PathPropertyBag, for tool-bit files): such a document opens with the Job's Proxy None, its
operations are no longer in a Job and cannot recompute. The classes themselves kept their names and their
saved state (none), and the new modules' onDocumentRestored upgrade their properties, so an import alias is
all it takes.

Outside the hsmplanner package on purpose: Init.py installs it at start-up, before any document opens, and
importing hsmplanner would load the compiled core in every FreeCAD session.
"""
import importlib
import importlib.abc
import importlib.util
import sys

# FreeCAD 0.20 module -> its 0.21+/1.x successor: what a Job and its resources (as HSM Planner's documents
# hold them) are saved as. Classes keep their names: ObjectJob, SetupSheet, StockFromBase, StockCreateBox,
# StockCreateCylinder, ToolController, ToolBit, and each Gui module's ViewProvider.
RENAMED = {
    "PathScripts.PathJob": "Path.Main.Job",
    "PathScripts.PathStock": "Path.Main.Stock",
    "PathScripts.PathSetupSheet": "Path.Base.SetupSheet",
    "PathScripts.PathToolController": "Path.Tool.Controller",
    "PathScripts.PathToolBit": "Path.Tool.Bit",
    "PathScripts.PathJobGui": "Path.Main.Gui.Job",
    "PathScripts.PathSetupSheetGui": "Path.Base.Gui.SetupSheet",
    "PathScripts.PathToolControllerGui": "Path.Tool.Gui.Controller",
    "PathScripts.PathToolBitGui": "Path.Tool.Gui.Bit",
    "PathScripts.PathIconViewProvider": "Path.Base.Gui.IconViewProvider",
    "PathScripts.PathPropertyBagGui": "Path.Base.Gui.PropertyBag",
    # HSM Planner's own roughing modules, gathered into hsmplanner.app.roughing (their classes kept their names)
    "hsmplanner.app.roughing_parts": "hsmplanner.app.roughing.parts",
    "hsmplanner.app.roughing_object": "hsmplanner.app.roughing.volume",
    "hsmplanner.app.roughing_op": "hsmplanner.app.roughing.operation",
    "hsmplanner.app.roughing_commands": "hsmplanner.app.roughing.commands",
    "hsmplanner.app.roughing_study": "hsmplanner.app.roughing.study",
}


class _AliasLoader(importlib.abc.Loader):
    """Loads an old name as the module of its new name: one module object under both names (its classes are
    the very classes FreeCAD's commands test proxies against)."""

    def __init__(self, new_name):
        self.new_name = new_name
        self.new_spec = None

    def create_module(self, spec):
        module = importlib.import_module(self.new_name)
        self.new_spec = module.__spec__
        return module

    def exec_module(self, module):
        # The import system stamped the alias's spec on the module; it is still the new module.
        module.__spec__ = self.new_spec


class RenamedModuleFinder(importlib.abc.MetaPathFinder):
    """Consulted after Python's own finders: a FreeCAD that still has the old module (0.20) imports it."""

    def __init__(self, renamed):
        self.renamed = dict(renamed)

    def find_spec(self, name, path=None, target=None):
        new_name = self.renamed.get(name)
        if new_name is None:
            return None
        return importlib.util.spec_from_loader(name, _AliasLoader(new_name))


def install():
    """Adds the finder once (Init.py may run again when the workbench is reloaded)."""
    if not any(isinstance(finder, RenamedModuleFinder) for finder in sys.meta_path):
        sys.meta_path.append(RenamedModuleFinder(RENAMED))
