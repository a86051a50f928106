"""Runs tests/python/test_*.py in freecadcmd: `freecadcmd tests/python/run_tests.py [PATTERN]`.

freecadcmd exits 0 after an uncaught exception, so the result is turned into the exit code here.
hsmplanner is not put on sys.path: it must come from the workbench linked into FreeCAD's Mod folder.

With HSM_TEST_CLAIMS=DIR in the environment (freecadcmd takes every option for itself), several of these
processes share the test classes (scripts/run-tests.sh starts one per core): each takes the next class no
other has claimed (a file created in DIR), the slowest first, so that they end together. Each prints its tests, the slowest ones, and the tests that hold on another FreeCAD only (skipped
here with a reason that starts with ONLY_ON, see helpers.only_on_freecad).
"""
import glob
import os
import sys
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ONLY_ON = "holds on FreeCAD"
# The test classes that take longest (20 s to 2 min each on two cores), started first so the processes end
# together; every other class after them, in name order.
SLOWEST_FIRST = ["test_examples.RoughingPathsExample", "test_examples.RoughingStudyExample",
                 "test_examples.StrategyStudyExample", "test_examples.MachiningDirectionExample",
                 "test_program_clearance.PostedPrograms", "test_examples.GuidanceStudyExample",
                 "test_bad_inputs.BadInputs", "test_saved_documents.Saved020ImpellerJob", "test_study.Study"]


class TimedResult(unittest.TextTestResult):
    def startTest(self, test):
        self._started = time.monotonic()
        super().startTest(test)

    def stopTest(self, test):
        super().stopTest(test)
        self.timings = getattr(self, "timings", [])
        self.timings.append((time.monotonic() - self._started, test.id()))


def test_classes(pattern):
    """{"module.Class": suite of its tests} of the modules matching `pattern`, the slowest first."""
    classes = {}

    def collect(suite):
        for item in suite:
            if isinstance(item, unittest.TestSuite):
                collect(item)
            else:
                key = "%s.%s" % (type(item).__module__, type(item).__name__)
                classes.setdefault(key, unittest.TestSuite()).addTest(item)

    for path in sorted(glob.glob(os.path.join(HERE, pattern))):
        collect(unittest.defaultTestLoader.loadTestsFromName(os.path.splitext(os.path.basename(path))[0]))
    rank = {name: i for i, name in enumerate(SLOWEST_FIRST)}
    return dict(sorted(classes.items(), key=lambda item: (rank.get(item[0], len(rank)), item[0])))


def claimed(claims, name):
    """True when this process claims module `name` (no other process did)."""
    try:
        os.close(os.open(os.path.join(claims, name), os.O_CREAT | os.O_EXCL | os.O_WRONLY))
    except FileExistsError:
        return False
    return True


def report(result, seconds):
    durations = sorted(getattr(result, "timings", []), reverse=True)
    print("slowest: " + ", ".join("%s %.0f s" % (name.split(".", 1)[-1], s) for s, name in durations[:6]))
    only = [(test.id(), reason) for test, reason in result.skipped if reason.startswith(ONLY_ON)]
    print("tests that hold on another FreeCAD only: %d%s" % (len(only), "".join(
        "\n  %s (%s)" % (name, reason) for name, reason in only)))
    print("this process: %d tests in %.0f s, %d failures, %d errors, %d skipped" % (
        result.testsRun, seconds, len(result.failures), len(result.errors), len(result.skipped)))


def main():
    args = sys.argv[1:]
    pattern = next((a for a in args if a.startswith("test_")), "test_*.py")
    claims = os.environ.get("HSM_TEST_CLAIMS") or None
    if HERE not in sys.path:
        sys.path.insert(0, HERE)
    start = time.monotonic()
    loader = unittest.defaultTestLoader
    if claims is None:
        suite = loader.discover(HERE, pattern=pattern, top_level_dir=HERE)
        result = unittest.TextTestRunner(verbosity=2, stream=sys.stdout, resultclass=TimedResult).run(suite)
        ran = result.testsRun
    else:
        result, ran = None, 0
        for name, tests in test_classes(pattern).items():
            if not claimed(claims, name):
                continue
            class_result = unittest.TextTestRunner(verbosity=2, stream=sys.stdout, resultclass=TimedResult).run(tests)
            if result is None:
                result = class_result
            else:
                result.failures += class_result.failures
                result.errors += class_result.errors
                result.skipped += class_result.skipped
                result.unexpectedSuccesses += class_result.unexpectedSuccesses
                result.testsRun += class_result.testsRun
                result.timings = getattr(result, "timings", []) + getattr(class_result, "timings", [])
            ran += class_result.testsRun
        if result is None:
            print("this process: 0 tests (every test class was taken by the other processes)")
            sys.stdout.flush()
            raise SystemExit(0)
    report(result, time.monotonic() - start)
    sys.stdout.flush()
    ok = result.wasSuccessful() and (ran > 0 or claims is not None)
    raise SystemExit(0 if ok else 1)


main()
