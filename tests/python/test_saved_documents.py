"""Documents saved by HSM Planner with FreeCAD 0.20.2 and 1.0.0 open in this FreeCAD: every object with its proxy
(ours and the Job's), every property today's code defines, and paths that recompute as saved or differ only as
saved_documents.EXPECTED_DIFFERENCES says, and why."""
import os
import tempfile
import unittest

import FreeCAD
import Path

import saved_documents as documents


class _SavedDocument:
    """One saved document, opened from a copy; test_a/b before any recompute, test_c recomputes."""

    SAVED_WITH, NAME = None, None

    @classmethod
    def setUpClass(cls):
        cls.record = documents.saved_record(cls.SAVED_WITH)[cls.NAME]
        folder = tempfile.TemporaryDirectory(prefix="hsm-test-")
        cls.addClassCleanup(folder.cleanup)
        cls.folder = folder.name
        cls.document = documents.open_copy(cls.SAVED_WITH, cls.NAME, cls.folder)
        cls.saved_paths = documents.paths_of(cls.document)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def test_a_every_object_comes_back_with_its_proxy(self):
        self.assertEqual(documents.proxy_problems(self.document, self.record["objects"]), [])
        self.assertEqual(documents.job_problems(self.document), [])
        self.assertEqual(documents.saved_path_problems(self.record, self.saved_paths), [])

    def test_b_our_objects_have_every_property_of_today(self):
        scratch = FreeCAD.newDocument("FreshObjects")
        try:
            fresh = documents.fresh_objects(scratch)
            self.assertEqual(documents.property_problems(self.document, fresh), [])
        finally:
            FreeCAD.closeDocument(scratch.Name)

    def test_c_recomputed_paths_are_as_saved_or_as_explained(self):
        self.assertEqual(documents.recompute_all(self.document), [])
        self.assertEqual(documents.path_problems(self.SAVED_WITH, self.NAME, self.record, self.saved_paths, self.document), [])


def _test_class(saved_with, name):
    """A TestCase of one saved document, named after it (test_saved_documents.Saved020MasterStudy…)."""
    title = "".join(part.title() for part in name.replace(".FCStd", "").split("_"))
    class_name = "Saved%s%s" % (saved_with.replace(".", ""), title)
    return type(class_name, (_SavedDocument, unittest.TestCase), {"SAVED_WITH": saved_with, "NAME": name})


for _saved_with, _names in documents.SAVED_WITH.items():
    for _name in _names:
        _case = _test_class(_saved_with, _name)
        globals()[_case.__name__] = _case
del _case


def command(text):
    return Path.Command(text)


class _Op:
    Label = "guide (study)"


class TheRulesRefuseOtherDifferences(unittest.TestCase):
    """The expected-difference rules accept their difference only: each fails on a path that differs more."""

    saved = [command("(guide study))"), command("G0 X1 Y2 Z4.01171"), command("G1 X1 Y2 Z0 F5"),
             command("G0 X1 Y2 Z4.01171")]

    def retracts(self, now):
        return documents.only_retract_heights(4.01171, 4.0)(_Op(), self.saved, now)

    def test_lowered_retracts_and_the_bracketed_comment_pass(self):
        now = [command("(guide [study])"), command("G0 X1 Y2 Z4"), command("G1 X1 Y2 Z0 F5"), command("G0 X1 Y2 Z4")]
        self.assertEqual(self.retracts(now), [])

    def test_a_moved_cut_a_shifted_retract_or_the_old_comment_fail(self):
        moved_cut = [command("(guide [study])"), command("G0 X1 Y2 Z4"), command("G1 X1 Y2.1 Z0 F5"),
                     command("G0 X1 Y2 Z4")]
        shifted = [command("(guide [study])"), command("G0 X1.5 Y2 Z4"), command("G1 X1 Y2 Z0 F5"),
                   command("G0 X1 Y2 Z4")]
        old_comment = [command("(guide study))")] + self.saved[1:2] + [command("G1 X1 Y2 Z0 F5"),
                                                                       command("G0 X1 Y2 Z4")]
        self.assertRegex(" ".join(self.retracts(moved_cut)), "move 1: G1")
        self.assertRegex(" ".join(self.retracts(shifted)), "move 0: G0 X1.5")
        self.assertRegex(" ".join(self.retracts(old_comment)), "head comment")

    def test_no_change_at_all_says_the_entry_is_stale(self):
        self.assertRegex(" ".join(self.retracts([command("(guide [study])")] + self.saved[1:])), "drop it")

    def test_the_rebuilt_sweep_rule_catches_fewer_passes_a_gouge_or_less_cutting(self):
        rule = documents.rebuilt_sweep(passes=7, saved_cutting_mm=100.0)
        saved = [command("(op)"), command("G1 X0 Y0 Z0 F5")]
        now = [command("(op)"), command("G1 X1 Y0 Z0 F5")]

        def op(passes=7, closest=0.53, cutting=101.0):
            return _Sweep(passes, FreeCAD.Units.Quantity(0.5, "mm"), FreeCAD.Units.Quantity(closest, "mm"),
                          FreeCAD.Units.Quantity(cutting, "mm"))

        self.assertEqual(rule(op(), saved, now), [])
        self.assertRegex(" ".join(rule(op(passes=6), saved, now)), "6 passes, 7 saved")
        self.assertRegex(" ".join(rule(op(closest=0.45), saved, now)), "closest approach 0.4500 mm under")
        self.assertRegex(" ".join(rule(op(cutting=90.0), saved, now)), "cutting length 90.000 mm, 100.000 mm saved")
        self.assertRegex(" ".join(rule(op(), saved, [command("(other)")] + now[1:])), "head comment")


class _Sweep:
    def __init__(self, passes, allowance, closest, cutting):
        self.Passes, self.Allowance, self.ClosestApproach, self.CuttingLength = passes, allowance, closest, cutting


class TheDataIsThere(unittest.TestCase):
    def test_each_set_of_documents_and_its_record(self):
        for saved_with, names in documents.SAVED_WITH.items():
            record = documents.saved_record(saved_with)
            self.assertEqual(sorted(record), sorted(names), saved_with)
            for name in names:
                self.assertTrue(os.path.isfile(os.path.join(documents.data_folder(saved_with), name)), name)
        for (saved_with, name, obj), difference in documents.EXPECTED_DIFFERENCES.items():
            record = documents.saved_record(saved_with)
            self.assertIn(obj, record[name]["path_commands_and_length_as_saved"], (saved_with, name, obj))
            self.assertTrue(difference.reason)


if __name__ == "__main__":
    unittest.main()
