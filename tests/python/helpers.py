"""Shared bits of the FreeCAD-layer tests."""
import os
import subprocess
import tempfile

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SYSTEM_PYTHON = "/usr/bin/python3"


def run(command, **kwargs):
    """Run a command, return CompletedProcess with text output (never raises on a non-zero exit)."""
    return subprocess.run(command, capture_output=True, text=True, timeout=300, **kwargs)


def temporary_directory(test_case):
    """A temporary directory removed when the test ends."""
    folder = tempfile.TemporaryDirectory(prefix="hsm-test-")
    test_case.addCleanup(folder.cleanup)
    return folder.name
