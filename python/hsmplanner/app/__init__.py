"""FreeCAD App layer of HSM Planner: document objects and Path/CAM operations (needs FreeCAD, not its GUI).

Proxy classes live in modules of this package whose names are recorded in saved documents: a module that moves
keeps its old name in hsmplanner_legacy_modules.RENAMED, or saved documents lose their objects.
"""
