"""The Volume roughing operation in a real Path Job: a torus ToolBit, a Roughing volume, the path, and the
posts (840D TRAORI, LinuxCNC xyzac-trt) read back by the simulator."""
import os
import re
import unittest

import FreeCAD
import numpy as np

import hsmplanner
from hsmplanner import roughing
from hsmplanner.app.roughing import volume as roughing_object, operation as roughing_op, parts as roughing_parts
from hsmplanner.app.compat import create_job, post_module
from hsmplanner.app.roughing.commands import sweep_commands
from hsmplanner.app.posts import linuxcnc5x_post, siemens840d_post
from helpers import check_clearance_start_and_end, check_golden, motions, slot_roughing_job, temporary_directory


class VolumeRoughing(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.document, _, _, cls.job, cls.controller, cls.op = slot_roughing_job("VolumeRoughing", "S3", SlotWidth=30.0,
                                                                                Length=100.0)
        cls.volume = cls.op.Volume
        # the post a user posting this 5-axis program chooses (a new Job's default differs: 1.1 none, 1.0 the
        # first of its list, a 3-axis post that gets the program a warning)
        cls.job.PostProcessor = "hsm_siemens840d"
        cls.op.touch()
        cls.document.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def test_the_path_tilts_the_table_and_keeps_the_allowance(self):
        op = self.op
        self.assertTrue(op.isValid(), op.State)
        self.assertGreater(op.Passes, 0)
        self.assertGreater(op.CuttingLength.Value, 100.0)
        self.assertGreaterEqual(op.ClosestApproach.Value, op.Allowance.Value - 0.01)
        commands = op.Path.Commands
        angles = [c.Parameters["A"] for c in commands if "A" in c.Parameters]
        self.assertTrue(angles and all(abs(a) > 1.0 for a in angles), "S3 tilts the A axis off zero")

    def test_it_starts_and_ends_above_the_stock_as_cams_own_operations(self):
        """A roughing operation has no height properties: it goes up to the highest point of its own links, at
        least 5 mm above the stock, across, and down to its first point on the links' sphere."""
        height = max(c.Parameters["Z"] for c in self.op.Path.Commands if "Z" in c.Parameters)
        stock_top = self.op.Volume.Proxy.inputs(self.op.Volume)[1].optimalBoundingBox(False, False).ZMax
        self.assertGreaterEqual(height, stock_top + 5.0 - 1e-6)
        check_clearance_start_and_end(self, self.op, height)
        across = motions(self.op)[1]
        self.assertIn("A", across.Parameters, "the table turns at the clearance height, before going down")

    def test_the_computation_reports_its_progress_and_stops_when_told(self):
        """What the GUI's progress dialog reads (and where it lets Qt draw and take Cancel): shares from 0 to 1,
        never back, often; a False from the callable stops the computation with hsmplanner.Cancelled."""
        seen = []
        roughing_op.volume_roughing_program(self.op, lambda done: seen.append(done) or True)
        self.assertGreater(len(seen), 5)
        self.assertEqual(seen, sorted(seen), "the share done never goes back")
        self.assertTrue(0.0 <= seen[0] and seen[-1] <= 1.0 + 1e-9 and seen[-1] > 0.99, (seen[0], seen[-1]))
        asked = []
        with self.assertRaises(hsmplanner.Cancelled):
            roughing_op.volume_roughing_program(self.op, lambda done: asked.append(done) or done < 0.5)
        self.assertEqual(sum(done >= 0.5 for done in asked), 1, "stopped at the first False (the user's Cancel)")

    def test_posts_are_read_back_on_their_machines(self):
        folder = temporary_directory(self)
        mpf = os.path.join(folder, "roughing.mpf")
        siemens840d_post.export([self.job, self.controller, self.op], mpf, "--machine=mikron-ucp710-ac-840d")
        result = hsmplanner.simulate(mpf, "mikron-ucp710-ac-840d", refuse_unknown_words=True, blocks=True)
        self.assertGreater(result.summary.cutting_blocks, 50)
        self.assertGreater(result.summary.total_time, result.summary.naive_time * 0.99)
        self.op.Machine = "linuxcnc-2.9-xyzac-trt"
        self.document.recompute()
        try:
            text = linuxcnc5x_post.export([self.job, self.controller, self.op], "-", "")
            self.assertGreater(hsmplanner.simulate(text, "linuxcnc-2.9-xyzac-trt").summary.cutting_blocks, 50)
        finally:
            self.op.Machine = roughing_op.DEFAULT_MACHINE
            self.document.recompute()

    def test_a_five_axis_path_with_a_three_axis_post_says_so_in_the_program(self):
        """FreeCAD's linuxcnc post writes X Y Z A C as they are: without tool-centre-point control the tool leaves
        the path. Chosen as the Job's post, the operation warns in its program (and the Report view); with our
        TCP posts, or no post chosen yet, it does not."""
        saved = self.job.PostProcessor
        try:
            cases = [("linuxcnc", True), ("hsm_siemens840d", False)]
            if "" in self.job.getEnumerationsOfProperty("PostProcessor"):  # 1.1: no post chosen yet (1.0 has no '')
                cases.append(("", False))
            for post, warned in cases:
                self.job.PostProcessor = post
                self.op.touch()
                self.document.recompute()
                comments = [c.Name for c in self.op.Path.Commands[:6] if c.Name.startswith("(")]
                self.assertEqual(any("WARNING" in c and "tool-centre-point" in c and "'%s'" % post in c
                                     for c in comments), warned, (post, comments))
            self.job.PostProcessor = "linuxcnc"
            self.op.touch()
            self.document.recompute()
            path = os.path.join(temporary_directory(self), "tcp.ngc")
            post_module("linuxcnc").export([self.job, self.op], path, "--no-show-editor")
            with open(path) as stream:
                self.assertIn("WARNING: this program turns rotary axes", stream.read())
        finally:
            self.job.PostProcessor = saved
            self.op.touch()
            self.document.recompute()

    def test_s3_on_a_three_axis_machine_is_3_plus_2_through_freecads_post(self):
        # On a 3-axis Machine the setup planes are written 3+2: X Y Z in the work plane turned so that the setup
        # direction is Z, with comments saying how to set the part up; FreeCAD's own LinuxCNC post writes it.
        self.op.Machine = "mikron-ucp710-840d"
        self.document.recompute()
        try:
            self.assertTrue(self.op.isValid(), self.op.State)
            commands = self.op.Path.Commands
            self.assertFalse(any(k in c.Parameters for c in commands for k in "ABC"))
            self.assertTrue(any(c.Name.startswith("(3+2 work plane") for c in commands[:5]), commands[:5])
            folder = temporary_directory(self)
            ngc = os.path.join(folder, "roughing_3plus2.ngc")
            post_module("linuxcnc").export([self.job, self.op], ngc, "--no-show-editor")
            with open(ngc) as stream:
                text = stream.read()
            self.assertIn("3+2 work plane", text)
            self.assertGreater(hsmplanner.simulate(ngc, "linuxcnc-2.9").summary.cutting_blocks, 50)
            # Turned back, the path's tips are the 5-axis program's: the same toolpath, another frame.
            volume, part, stock, partitions = self.volume.Proxy.computed(self.volume)
            paths = roughing.sweep(partitions[0][1], volume.solids[0], part, stock,
                                   tool=roughing_op.cutter_of(self.controller.Tool))
            rotation, tilt, _ = roughing.work_plane(paths)
            self.assertGreater(tilt, 5.0)
            # (the first X is the move across at the clearance height, before the sweep's own)
            tips = np.array([[c.Parameters[k] for k in "XYZ"] for c in commands if "X" in c.Parameters][1:])
            np.testing.assert_allclose(tips @ rotation, paths.moves["tip"], atol=1e-6)
            np.testing.assert_allclose(paths.moves["axis"][0] @ rotation.T, [0, 0, 1], atol=1e-12)
        finally:
            self.op.Machine = roughing_op.DEFAULT_MACHINE
            self.document.recompute()
        self.assertTrue(self.op.isValid(), self.op.State)

    def test_a_path_whose_axis_turns_is_refused_on_a_three_axis_machine(self):
        moves = {"tip": np.array([[0.0, 0, 10], [5.0, 0, 10]]), "kind": np.array([0, 3]),
                 "axis": np.array([[0.0, 0, 1], [np.sin(0.2), 0, np.cos(0.2)]])}
        three_axis = hsmplanner.feedsim.load_machine("mikron-ucp710-840d")
        with self.assertRaisesRegex(ValueError, "move 1 turns the tool axis .* a 3-axis machine and its post run one "
                                                "tool axis only"):
            sweep_commands(moves, three_axis, 2000.0)

    def test_tool_axis_ticks_follow_the_machines_angles(self):
        from hsmplanner.app.roughing.commands import tool_axis_ticks
        machine = hsmplanner.feedsim.load_machine(self.op.Machine)
        ticks = tool_axis_ticks(self.op.Path.Commands, machine, every_mm=5.0, length_mm=4.0)
        self.assertGreater(len(ticks), self.op.CuttingLength.Value / 5.0 * 0.9)
        np.testing.assert_allclose(np.linalg.norm(ticks[:, 1] - ticks[:, 0], axis=1), 4.0, atol=1e-9)
        # S3 on the slot: every tick along the setup direction (the A/C angles turned back into the axis).
        volume, part, stock, partitions = self.volume.Proxy.computed(self.volume)
        setup = np.asarray(partitions[0][1].setup_direction)
        np.testing.assert_allclose((ticks[:, 1] - ticks[:, 0]) @ setup, 4.0, atol=1e-6)
        with self.assertRaisesRegex(ValueError, "tick spacing 0 mm"):
            tool_axis_ticks(self.op.Path.Commands, machine, every_mm=0.0)

    # The slot's S3 path posted for the A/C trunnion 840D (TRAORI, angles) and LinuxCNC's xyzac-trt, against
    # golden files: any change of the sweep or of the posts shows here, line by line.
    def test_posted_840d_program_against_its_golden_file(self):
        mpf = siemens840d_post.export([self.job, self.controller, self.op], "-", "--machine=mikron-ucp710-ac-840d")
        self.assertIn("TRAORI", mpf)
        self.assertGreater(hsmplanner.simulate(mpf, "mikron-ucp710-ac-840d", refuse_unknown_words=True)
                           .summary.cutting_blocks, 50)
        check_golden(self, mpf, "roughing_slot_s3_840d.mpf")

    def test_posted_linuxcnc_program_against_its_golden_file(self):
        self.op.Machine = "linuxcnc-2.9-xyzac-trt"
        self.document.recompute()
        try:
            ngc = linuxcnc5x_post.export([self.job, self.controller, self.op], "-", "")
        finally:
            self.op.Machine = roughing_op.DEFAULT_MACHINE
            self.document.recompute()
        self.assertGreater(hsmplanner.simulate(ngc, "linuxcnc-2.9-xyzac-trt", refuse_unknown_words=True)
                           .summary.cutting_blocks, 50)
        check_golden(self, ngc, "roughing_slot_s3_linuxcnc_trt.ngc")

    def test_a_post_refuses_a_machine_the_operation_was_not_computed_for(self):
        # The op's A C are the Mikron trunnion's angles: another machine's post would put the axis elsewhere.
        self.assertEqual(self.op.Machine, "mikron-ucp710-ac-840d")
        with self.assertRaisesRegex(ValueError, "LinuxCNC 5-axis post: Roughing was computed for machine "
                                                "'mikron-ucp710-ac-840d', not 'linuxcnc-2.9-xyzac-trt'"):
            linuxcnc5x_post.export([self.job, self.controller, self.op], "-", "--machine=linuxcnc-2.9-xyzac-trt")
        with self.assertRaisesRegex(ValueError, "840D post: Roughing was computed for machine 'mikron-ucp710-ac-840d', "
                                                "not 'linuxcnc-2.9-xyzac-trt'.*--machine=mikron-ucp710-ac-840d"):
            siemens840d_post.export([self.job, self.controller, self.op], "-", "--machine=linuxcnc-2.9-xyzac-trt")
        # Without --machine both take the operation's: the 840D post writes for it, the LinuxCNC post says why not.
        self.assertIn("TRAORI", siemens840d_post.export([self.job, self.controller, self.op], "-", ""))
        with self.assertRaisesRegex(ValueError, "machine 'mikron-ucp710-ac-840d' \\(the operations' Machine\\) is not a "
                                                "LinuxCNC machine"):
            linuxcnc5x_post.export([self.job, self.controller, self.op], "-", "")

    def test_the_840d_changes_the_tool_before_it_switches_traori_on(self):
        # As in Siemens' examples: T D M6 (and the length compensation D1 brings) first, then TRAORI; TRAFOOF
        # before the program ends.
        lines = [line.split(" ", 1)[-1] for line in
                 siemens840d_post.export([self.job, self.controller, self.op], "-", "").splitlines()]
        tool, on, off = lines.index("T3 D1 M6"), lines.index("TRAORI"), lines.index("TRAFOOF")
        moves = [i for i, line in enumerate(lines) if re.match(r"(G[01] |[XYZAC]-?[0-9.])", line)]
        self.assertLess(tool, on)
        self.assertLess(on, moves[0])
        self.assertLess(moves[-1], off)
        self.assertEqual(lines[-1], "M30")

    def test_a_new_job_s_default_tool_controller_gets_the_paper_s_torus(self):
        # FreeCAD's default controller (a Ø5 flat end mill at feed 0) would cut at F0: the op takes the torus.
        document = FreeCAD.newDocument("DefaultController")
        try:
            part, stock = roughing_parts.create_slanted_slot_block(document)
            document.recompute()
            volume = roughing_object.create(part, stock, Strategy="S1")
            job = create_job([part])
            self.assertTrue(all(c.HorizFeed.Value == 0 for c in job.Tools.Group), "FreeCAD's default has no feed")
            op = roughing_op.CreateVolumeRoughing("Roughing", parentJob=job)
            op.Volume = volume
            document.recompute()
            self.assertGreater(op.ToolController.HorizFeed.getValueAs("mm/min").Value, 0)
            self.assertEqual(roughing_op.cutter_of(op.ToolController.Tool).kind.name, "torus")
            self.assertGreater(op.Passes, 0)
            # A controller set to feed 0 afterwards: no path, no exception (one Report-view line).
            op.ToolController.HorizFeed = 0
            document.recompute()
            self.assertFalse(any(c.Name in ("G0", "G1") for c in op.Path.Commands), "no moves at F0")
        finally:
            FreeCAD.closeDocument(document.Name)

    def test_a_feed_rate_analysis_of_the_op_takes_its_machine(self):
        # Its A/C are the Mikron trunnion's: the analysis starts there, not on the 3-axis default.
        from hsmplanner.app import feedrate_object
        analysis = feedrate_object.create(self.op)
        try:
            self.assertEqual(analysis.Machine, self.op.Machine)
            self.assertGreater(analysis.TotalTime, 0.0)
            self.assertEqual(feedrate_object.create(self.job, document=self.document).Machine, self.op.Machine)
        finally:
            for obj in [o for o in self.document.Objects if o.TypeId == analysis.TypeId and o.Name.startswith(
                    "FeedRateAnalysis")]:
                self.document.removeObject(obj.Name)

    def test_the_cutter_comes_from_the_tool(self):
        cutter = roughing_op.cutter_of(self.controller.Tool)
        self.assertEqual(cutter.kind.name, "torus")
        self.assertAlmostEqual(cutter.diameter, 8.0)
        self.assertAlmostEqual(cutter.corner_radius, 1.0)


if __name__ == "__main__":
    unittest.main()
