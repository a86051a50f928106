"""Settings of the core as its own structs: each default is written once, in C++ (help(hsmplanner._core.X)
lists them); Python passes only what the caller gave."""


def core_settings(kind, **values):
    """A default-constructed core settings struct `kind` with the fields given (None keeps the default)."""
    settings = kind()
    for name, value in values.items():
        if value is None:
            continue
        if not hasattr(settings, name):
            raise TypeError("%s has no setting %r" % (kind.__name__, name))
        setattr(settings, name, value)
    return settings


def default(kind, name):
    """The core's default of one setting."""
    return getattr(kind(), name)
