"""Ranges of document-object properties: the same as the task panels', so that no edit in the property
editor or from a script reaches the core with a value the panel would refuse.

FreeCAD 0.20 cannot give a PropertyLength or PropertyFloat a range from Python (PropertyFloatConstraint
clamps silently, and changing a property's type would break saved documents), so the proxies clamp in
onChanged, with a warning that names the property, the value and the range. The panels take their spin-box
ranges from the same tables.
"""
import math

import FreeCAD


def _number(value):
    return value.Value if hasattr(value, "Value") else value


class PropertyLimits:
    """Mixin of a proxy: LIMITS maps a property name to its (lowest, highest) value, in the property's
    internal unit (mm, degrees)."""

    LIMITS = {}

    def onChanged(self, obj, prop):
        self.clamp(obj, prop)
        parent = super()
        if hasattr(parent, "onChanged"):
            parent.onChanged(obj, prop)

    def clamp(self, obj, prop):
        limits = self.LIMITS.get(prop)
        if limits is None or prop not in getattr(obj, "PropertiesList", ()):
            return
        value = _number(getattr(obj, prop))
        low, high = limits
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return
        clamped = low if math.isnan(value) else min(max(value, low), high)
        if clamped == value:
            return
        if isinstance(getattr(obj, prop), int):
            clamped = int(round(clamped))
        setattr(obj, prop, clamped)
        FreeCAD.Console.PrintWarning("%s: %s = %s is outside [%g, %g]: set to %g\n"
                                     % (obj.Label, prop, shown_value(obj, prop, value), low, high, clamped))


def shown_value(obj, prop, value):
    """The value as the warning names it: FreeCAD stores a negative length as 0 before a proxy sees it, so a
    typed -5 arrives as 0; the warning says so rather than blame a 0 the user never typed."""
    if value == 0 and obj.getTypeIdOfProperty(prop) == "App::PropertyLength":
        return "0 (or a negative length, which FreeCAD stores as 0)"
    return "%g" % value
