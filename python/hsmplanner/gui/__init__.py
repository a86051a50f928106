"""FreeCAD GUI layer of HSM Planner: workbench, commands, task panels and view providers.

Kept apart from hsmplanner.app so that headless scripts never import Qt. View-provider classes are
recorded by module and class name in saved documents: never rename them.
"""
