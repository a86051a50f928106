"""Adding the properties of our document objects from their tables (inputs the user edits, results the object
computes), as every object declares them."""

READ_ONLY, HIDDEN = 1, 2  # FreeCAD's editor modes


def add_inputs(obj, inputs):
    """(type, name, group, tooltip, default) rows; a default of None is left to FreeCAD."""
    for prop_type, name, group, tooltip, default in inputs:
        obj.addProperty(prop_type, name, group, tooltip)
        if default is not None:
            setattr(obj, name, default)


def add_results(obj, results, mode=READ_ONLY, group="Result"):
    """(type, name, tooltip) rows the object computes: read-only, or hidden (mode=HIDDEN)."""
    for prop_type, name, tooltip in results:
        obj.addProperty(prop_type, name, group, tooltip)
        obj.setEditorMode(name, mode)


def refresh_choices(obj, name, choices):
    """An enumeration saved by an earlier version offers today's `choices` (a machine added since), keeping the
    value it was saved with when it is still one of them."""
    choices = list(choices)
    if name not in obj.PropertiesList or obj.getEnumerationsOfProperty(name) == choices:
        return
    value = getattr(obj, name)
    setattr(obj, name, choices)
    if value in choices:
        setattr(obj, name, value)
