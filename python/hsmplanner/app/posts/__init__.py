"""Post-processors of HSM Planner, with FreeCAD's post contract: export(objectslist, filename, argstring)."""
