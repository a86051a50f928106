"""Settings of the core as its own structs: each default is written once, in C++ (help(hsmplanner._core.X)
lists them); Python passes only what the caller gave."""


def core_settings(settings_type, /, **values):
    """A default-constructed core settings struct of `settings_type` with the fields given (None keeps the
    default)."""
    settings = settings_type()
    for name, value in values.items():
        if value is None:
            continue
        if not hasattr(settings, name):
            raise TypeError("%s has no setting %r" % (settings_type.__name__, name))
        try:
            setattr(settings, name, value)
        except TypeError:  # pybind11's own message names no setting
            raise TypeError("%s.%s cannot be %r (%s): give a %s" % (
                settings_type.__name__, name, value, type(value).__name__,
                type(getattr(settings, name)).__name__)) from None
    return settings


def default(kind, name):
    """The core's default of one setting."""
    return getattr(kind(), name)


def enum_value(kind, value, what):
    """A core enum value from itself or its name ('b1_to_b2'); ValueError names the input and the choices."""
    if isinstance(value, kind):
        return value
    try:
        return kind.__members__[str(value)]
    except KeyError:
        raise ValueError("%s %r is unknown: use one of %s" % (what, value, ", ".join(kind.__members__))) from None
