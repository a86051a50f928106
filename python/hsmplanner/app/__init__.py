"""FreeCAD App layer of HSM Planner: document objects and Path/CAM operations (needs FreeCAD, not its GUI).

Proxy classes live in modules of this package whose names are recorded in saved documents: never rename them.
"""
