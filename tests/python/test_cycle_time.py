"""The cycle time of a Job of FreeCAD CAM's own operations: every operation read by the simulator (no word
skipped), timed three ways, the Job as one program, the times written on the operations and kept current, and
an operation that failed or waits for a recompute refused by name."""
import unittest

import FreeCAD

from hsmplanner import feedsim
from hsmplanner.app import cycle_time, cycle_time_object, feedrate

import cam_jobs


class CamOperations(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("CycleTime")
        cls.part, cls.job, cls.ops = cam_jobs.cam_job(cls.document)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def test_every_operation_is_read_whole_by_the_simulator(self):
        for name, op in self.ops.items():
            with self.subTest(op=name):
                self.assertTrue(op.isValid(), "%s: %s" % (name, op.getStatusString()))
                self.assertGreater(len(op.Path.Commands), 3, name)
                result = feedsim.simulate(feedrate.program_commands(op), feedsim.DEFAULT_MACHINE,
                                          refuse_unknown_words=True)
                self.assertGreater(result.summary.total_time, 0.0, name)

    def test_drilling_cycles_are_timed_as_the_machine_moves_them(self):
        """G81, G83 (pecks) and G82 (dwell) expanded into their moves: a peck cycle takes longer than the plain
        one on the same holes, a dwell adds its 0.5 s per hole."""
        times = {name: cycle_time.operation_row(self.ops[name], feedsim.DEFAULT_MACHINE)
                 for name in ("Drilling", "PeckDrilling", "DwellDrilling")}
        for name, row in times.items():
            self.assertEqual(row["error"], "", name)
        self.assertGreater(times["PeckDrilling"]["simulated_s"], times["Drilling"]["simulated_s"] + 1.0)
        self.assertAlmostEqual(times["DwellDrilling"]["simulated_s"] - times["Drilling"]["simulated_s"], 1.0,
                               delta=0.05)  # two holes, 0.5 s each

    def test_the_job_timed_three_ways(self):
        rows, total = cycle_time.job_rows(self.job, feedsim.DEFAULT_MACHINE)
        self.assertEqual([row["label"] for row in rows], [op.Label for op in self.job.Operations.Group])
        for row in rows:
            with self.subTest(op=row["label"]):
                self.assertEqual(row["error"], "")
                self.assertIsNotNone(row["cam_s"], "CAM gave %r" % self.ops[row["name"]].CycleTime)
                self.assertGreater(row["simulated_s"], 0.0)
                self.assertGreaterEqual(row["simulated_s"], 0.99 * row["naive_s"])  # the machine is never faster
                self.assertTrue(row["held_by"])
                self.assertNotRegex(row["held_by"], r"(^| )0 %", "a share that rounds to 0 % is left out")
        self.assertEqual(total["error"], "")
        self.assertGreaterEqual(total["simulated_s"], 0.99 * sum(row["simulated_s"] for row in rows))
        text = cycle_time_object.summary_text(rows, total)
        self.assertIn(self.job.Label, text)

    def test_the_analysis_writes_the_times_on_the_operations_and_keeps_them_current(self):
        analysis = cycle_time_object.create(self.job)
        try:
            self.assertGreater(analysis.SimulatedTime, 0.0)
            self.assertEqual(list(analysis.Problems), [])
            for op in self.job.Operations.Group:
                self.assertGreater(op.SimulatedCycleTime, 0.0, op.Label)
                self.assertEqual(op.SimulatedOn, analysis.Machine)
                self.assertNotIn("Touched", op.State, "writing the time touched %s" % op.Label)
            self.assertAlmostEqual(self.job.SimulatedCycleTime, analysis.SimulatedTime)
            before = self.ops["Profile"].SimulatedCycleTime
            controller = self.job.Tools.Group[0]
            controller.HorizFeed = FreeCAD.Units.Quantity("400 mm/min")
            self.document.recompute()
            self.assertGreater(self.ops["Profile"].SimulatedCycleTime, 1.3 * before)  # half the feed
        finally:
            self.job.Tools.Group[0].HorizFeed = FreeCAD.Units.Quantity("800 mm/min")
            self.document.removeObject(analysis.Name)
            self.document.recompute()

    def test_an_operation_that_failed_or_waits_is_refused_by_name(self):
        op = self.ops["Adaptive"]
        op.touch()
        with self.assertRaisesRegex(ValueError, "Adaptive has changed since its path was computed: recompute it"):
            feedrate.simulate_object(op)
        rows, total = cycle_time.job_rows(self.job, feedsim.DEFAULT_MACHINE)
        self.assertIn("recompute it", [row for row in rows if row["name"] == op.Name][0]["error"])
        self.assertIn("Adaptive cannot be", total["error"])
        self.document.recompute()
        self.assertEqual(cycle_time.operation_row(op, feedsim.DEFAULT_MACHINE)["error"], "")


class CamDressups(unittest.TestCase):
    """CAM's dressups (holding tags on a profile, dogbones in a pocket) are read whole and timed in the Job in
    place of the operations they dress."""

    def test_dressed_operations_are_read_and_timed(self):
        document = FreeCAD.newDocument("CycleTimeDressups")
        try:
            operations = [o for o in cam_jobs.OPERATIONS if o[1] in ("Profile", "PocketShape")]
            _, job, ops = cam_jobs.cam_job(document, operations)
            plain = {name: cycle_time.operation_row(op, feedsim.DEFAULT_MACHINE)["simulated_s"]
                     for name, op in ops.items()}
            dressed = cam_jobs.dress(document, ops)
            for module, dressup in dressed.items():
                with self.subTest(dressup=module):
                    self.assertTrue(dressup.isValid(), dressup.getStatusString())
                    feedsim.simulate(feedrate.program_commands(dressup), feedsim.DEFAULT_MACHINE,
                                     refuse_unknown_words=True)
            rows, total = cycle_time.job_rows(job, feedsim.DEFAULT_MACHINE)
            # the Job's program as CAM's post writes it: its active operations in order, dressups included
            self.assertEqual([r["name"] for r in rows], [o.Name for o in job.Operations.Group if getattr(o, "Active", True)])
            for dressup in dressed.values():
                self.assertIn(dressup.Name, [r["name"] for r in rows])
            self.assertEqual(total["error"], "")
            tags = rows[0]["simulated_s"]
            self.assertGreater(tags, plain["Profile"], "the tags lift the tool over each of them")
        finally:
            FreeCAD.closeDocument(document.Name)


class CamEstimate(unittest.TestCase):
    def test_cam_s_clock_text_is_read_and_errors_are_none(self):
        class Op:
            CycleTime = "01:02:03"

        self.assertEqual(cycle_time.cam_estimate_s(Op()), 3723.0)
        Op.CycleTime = "Tool Feedrate Error"
        self.assertIsNone(cycle_time.cam_estimate_s(Op()))
        self.assertEqual(cycle_time.clock(3723.4), "1:02:03")
        self.assertEqual(cycle_time.clock(59.6), "1:00")
        self.assertEqual(cycle_time.clock(None), "")

    def test_what_is_not_a_job_is_refused(self):
        with self.assertRaisesRegex(ValueError, "is not a CAM Job"):
            cycle_time.job_rows(None)
        with self.assertRaisesRegex(ValueError, "is not a CAM Job"):
            cycle_time_object.create("a job")
