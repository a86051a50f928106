"""Runs every tests/python/test_*.py in freecadcmd: `freecadcmd tests/python/run_tests.py [PATTERN]`.

freecadcmd exits 0 after an uncaught exception, so the result is turned into the exit code here.
hsmplanner is not put on sys.path: it must come from the workbench linked into FreeCAD's Mod folder.
"""
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    pattern = next((a for a in sys.argv[1:] if a.startswith("test_")), "test_*.py")
    if HERE not in sys.path:
        sys.path.insert(0, HERE)
    suite = unittest.defaultTestLoader.discover(HERE, pattern=pattern, top_level_dir=HERE)
    result = unittest.TextTestRunner(verbosity=2, stream=sys.stdout).run(suite)
    sys.stdout.flush()
    raise SystemExit(0 if result.wasSuccessful() and result.testsRun > 0 else 1)


main()
