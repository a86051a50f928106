"""Shared bits of the FreeCAD-layer tests."""
import os
import subprocess
import tempfile
import unittest

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


def slot_roughing_job(name, strategy, **slot):
    """A document with the slanted slot block (its properties `slot`), a Roughing volume of `strategy`, a Job
    with the paper's torus and a Volume roughing of that volume: (document, part, stock, job, controller, op).
    Not recomputed."""
    import FreeCAD
    from hsmplanner.app.roughing import volume as roughing_object, operation as roughing_op, parts as roughing_parts
    from hsmplanner.app.compat import create_job

    document = FreeCAD.newDocument(name)
    part, stock = roughing_parts.create_slanted_slot_block(document)
    for key, value in slot.items():
        setattr(part, key, value)
    document.recompute()
    volume = roughing_object.create(part, stock, Strategy=strategy)
    job = create_job([part])
    controller = roughing_op.torus_controller(job)
    op = roughing_op.CreateVolumeRoughing("Roughing", parentJob=job)
    op.Volume = volume
    return document, part, stock, job, controller, op


def only_on_freecad(release, why):
    """A test that can hold on one FreeCAD release only ("1.1", "1.0"): skipped on the others with a reason that
    says where it holds and why (run_tests.py counts and lists these)."""
    from hsmplanner.app.compat import freecad_version

    running = "%d.%d" % freecad_version()
    return unittest.skipUnless(running == release, "holds on FreeCAD %s only (this is %s): %s"
                               % (release, running, why))


def motions(op):
    """The motion commands of an operation's path (comments left out)."""
    from hsmplanner.app.clearance_moves import MOTION

    return [c for c in op.Path.Commands if c.Name in MOTION]


def check_clearance_start_and_end(test_case, op, height):
    """As CAM's own operations: up to `height` first (G0 Z only), across at it, the operation's first move at or
    below it, and back up to it at the end (G0 Z only)."""
    moves = motions(op)
    test_case.assertGreater(len(moves), 3, op.Label)
    up, across, first, last = moves[0], moves[1], moves[2], moves[-1]
    test_case.assertEqual((up.Name, set(up.Parameters)), ("G0", {"Z"}), up.toGCode())
    test_case.assertAlmostEqual(up.Parameters["Z"], height, places=6)
    test_case.assertEqual(across.Name, "G0")
    test_case.assertTrue({"X", "Y", "Z"} <= set(across.Parameters), across.toGCode())
    test_case.assertAlmostEqual(across.Parameters["Z"], height, places=6)
    test_case.assertEqual((across.Parameters["X"], across.Parameters["Y"]),
                          (first.Parameters["X"], first.Parameters["Y"]), "across to above the first move")
    test_case.assertLessEqual(first.Parameters["Z"], height + 1e-6)
    test_case.assertEqual((last.Name, set(last.Parameters)), ("G0", {"Z"}), last.toGCode())
    test_case.assertAlmostEqual(last.Parameters["Z"], height, places=6)
