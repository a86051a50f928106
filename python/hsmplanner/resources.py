"""Paths of the files shipped in resources/ (icons, machine models)."""
import os

RESOURCES_DIR = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", "resources"))


def icon(name):
    """Absolute path of resources/icons/<name>.svg."""
    return os.path.join(RESOURCES_DIR, "icons", name + ".svg")
