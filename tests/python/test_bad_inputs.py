"""Every bad input (tests/python/bad_inputs.py): each must raise the error that names
the input and the fix, or give a result that holds. The cases run in child processes, so that a crash, a
hang or runaway memory fails its case instead of killing this runner."""
import json
import unittest

import bad_inputs


class BadInputs(unittest.TestCase):
    reports = None

    @classmethod
    def setUpClass(cls):
        cls.reports = bad_inputs.run_cases()


def _case_test(name):
    def test(self):
        report = self.reports.get(name)
        self.assertIsNotNone(report, "%s did not run" % name)
        self.assertEqual(report["outcome"], "ok", json.dumps(report, indent=1))
    return test


for _index, _case in enumerate(bad_inputs.CASES):
    setattr(BadInputs, "test_%03d_%s" % (_index, "".join(c if c.isalnum() else "_" for c in _case["name"])[:60]),
            _case_test(_case["name"]))


class TheSuiteItself(unittest.TestCase):
    def test_it_holds_the_issue_cases_and_thirty_more(self):
        self.assertGreaterEqual(len(bad_inputs.CASES), 40 + 30)
        self.assertEqual(len({c["name"] for c in bad_inputs.CASES}), len(bad_inputs.CASES), "case names repeat")

    def test_a_crashing_case_fails_alone_and_the_others_still_run(self):
        crash = bad_inputs.raises("crash on purpose", "import os; os.abort()", "ValueError", "")
        fine = bad_inputs.raises("fine after the crash", "h.curve_net(b1, b2, 1.5, 5)", "ValueError", "K = 1.5")
        bad_inputs.CASES.extend([crash, fine])
        try:
            reports = bad_inputs.run_cases([crash["name"], fine["name"]])
        finally:
            del bad_inputs.CASES[-2:]
        self.assertEqual(reports[crash["name"]]["outcome"], "crash")
        self.assertEqual(reports[fine["name"]]["outcome"], "ok")
