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


GOLDEN = os.path.join(REPO, "tests", "golden")


def check_golden(test_case, text, golden):
    """Compares `text` with tests/golden/`golden`; with HSM_REGENERATE_GOLDEN=1, writes it and skips the
    comparison (a file compared with itself proves nothing). Called last in a test: a skip ends it."""
    path = os.path.join(GOLDEN, golden)
    if os.environ.get("HSM_REGENERATE_GOLDEN") == "1":
        with open(path, "w") as stream:
            stream.write(text)
        test_case.skipTest("golden file %s regenerated (HSM_REGENERATE_GOLDEN=1): not compared" % golden)
    with open(path) as stream:
        test_case.assertEqual(text, stream.read(), "regenerate with HSM_REGENERATE_GOLDEN=1 if the change is meant")
