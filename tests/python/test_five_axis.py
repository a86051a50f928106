"""Five-axis machines from Python and the CLI: presets, kinematics, 5-axis programs simulated, reports."""
import json
import os
import re
import unittest

import FreeCAD
import numpy as np

import hsmplanner
from hsmplanner import _core, feedsim
from hsmplanner.app import finishing, master_feature_object
from hsmplanner.app import compat
from hsmplanner.app.compat import cam_module, create_job
from hsmplanner.app.posts import linuxcnc5x_post, siemens840d_post
from hsmplanner.scripting import build_program
from helpers import REPO, check_golden, run, temporary_directory


FEEDSIM = build_program(REPO, "hsm-feedsim")
TRUNNION = "mikron-ucp710-ac-840d"
# TRAORI: the tip goes 50 mm out, C turns a full turn about it, then the tip moves while A tilts 20°.
PROGRAM = "TRAORI\nG1 X50 Y0 Z0 F6000\nG1 C360 F100000\nG1 X0 Y20 A20 C400 F3000\n"


class Machines(unittest.TestCase):
    def test_five_axis_presets(self):
        kinds = {name: feedsim.load_machine(name).kinematics for name in feedsim.machine_names()}
        self.assertEqual(kinds["mikron-ucp710-ac-840d"], "table-table")
        self.assertEqual(kinds["swivel-head-bc-840d"], "head-table")
        self.assertEqual(kinds["linuxcnc-2.9-xyzac-trt"], "table-table")
        self.assertEqual(kinds["mikron-ucp710-840d"], "")  # every 3-axis file stays as it was
        trt = feedsim.load_machine("linuxcnc-2.9-xyzac-trt")
        self.assertEqual([a.name for a in trt.rotary_axes], ["A", "C"])
        self.assertAlmostEqual(trt.rotary_axes[0].max_velocity, 30.0)  # deg/s
        self.assertTrue(trt.tool_tip_programmed)

    def test_kinematics_round_trip(self):
        machine = feedsim.load_machine(TRUNNION)
        tip, axis = _core.forward_kinematics(machine, [10.0, -5.0, 3.0], [25.0, 70.0])
        self.assertAlmostEqual(np.linalg.norm(axis), 1.0, places=12)
        linear, angles, singular = _core.inverse_kinematics(machine, tip, axis, [20.0, 60.0])
        np.testing.assert_allclose(linear, [10.0, -5.0, 3.0], atol=1e-9)
        np.testing.assert_allclose(angles, [25.0, 70.0], atol=1e-9)
        self.assertFalse(singular)
        self.assertEqual(len(_core.orientation_solutions(machine, axis)), 2)
        with self.assertRaisesRegex(ValueError, r"outside the travel \(A \[-100, 120\] deg\)"):
            _core.inverse_kinematics(machine, [0, 0, 0], [0, 0, -1])


class Simulation(unittest.TestCase):
    def test_c_limits_the_turn_and_the_report_says_so(self):
        result = hsmplanner.simulate(PROGRAM, machine=TRUNNION, blocks=True)
        shares = feedsim.speed_limit_shares(result.summary)
        self.assertEqual(next(iter(shares)), "C", shares)
        self.assertAlmostEqual(sum(shares.values()), 1.0, places=9)
        blocks = result.blocks
        self.assertEqual(feedsim.SPEED_LIMITS[blocks["limit"][1]], "C")
        self.assertTrue(blocks["rotary_only"][1])
        np.testing.assert_allclose(blocks["rotary_end"][1], [0.0, 360.0], atol=1e-9)
        np.testing.assert_allclose(blocks["rotary_end"][2], [20.0, 400.0], atol=1e-9)
        self.assertAlmostEqual(blocks["length"][1], 0.0, places=9)  # the tip stayed on the workpiece
        # The machine's X Y Z are not the tip's once the table has turned.
        self.assertGreater(np.linalg.norm(blocks["machine_end"][2] - blocks["end"][2]), 1.0)
        self.assertIn("speed held by, share of time:  C ", result.summary.to_text())
        report = json.loads(result.summary.to_json())["speed_limits"]
        self.assertEqual(report["names"], list(feedsim.SPEED_LIMITS))
        self.assertAlmostEqual(sum(report["share_of_time"]), 1.0, places=9)

    def test_report_draws_the_rotary_axes(self):
        folder = temporary_directory(self)
        result = hsmplanner.simulate(PROGRAM, machine=TRUNNION, blocks=True)
        paths = feedsim.write_report(result, folder, stem="five", program="p5", machine=TRUNNION)
        self.assertIn(os.path.join(folder, "five_rotary_axes.png"), paths)
        for path in paths:
            self.assertGreater(os.path.getsize(path), 10000 if path.endswith(".png") else 300, path)
        with open(os.path.join(folder, "five_blocks.csv")) as stream:
            header, first, turn = stream.readline(), stream.readline(), stream.readline()
        self.assertTrue(header.strip().endswith("limit,rotary1_start_deg,rotary2_start_deg,rotary1_end_deg,"
                                                "rotary2_end_deg"))
        self.assertEqual(turn.split(",")[17], "C")

    def test_the_cli_names_the_limiting_axis(self):
        folder = temporary_directory(self)
        path = os.path.join(folder, "p5.mpf")
        with open(path, "w") as stream:
            stream.write(PROGRAM)
        out = run([FEEDSIM, "-m", TRUNNION, path]).stdout
        self.assertRegex(out, r"speed held by, share of time:  C \d+\.\d%")
        refused = run([FEEDSIM, "-m", "mikron-ucp710-840d", path], check=False)
        self.assertNotEqual(refused.returncode, 0)
        self.assertIn("line 3: the program turns C but machine \"mikron-ucp710-840d\" has no such axis",
                      refused.stderr)

    def test_bad_five_axis_programs_name_their_line(self):
        cases = [
            ("G1 X1 A3=0 B3=0 C3=0 F100\n", "line 1: orientation vector A3 B3 C3 = (0, 0, 0) has no length"),
            ("G1 X1 A3= F100\n", "line 1: A3= needs a number"),
            ("G1 X1 A5 A6 F100\n", "line 1: rotary axis A given twice"),
            ("G1 X1 A5 A3=1 F100\n", "line 1: rotary axes and an orientation vector on one line"),
            ("G93\nG1 X1 A5\n", "line 2: G93 (inverse time) needs F on every feed move"),
            ("G1 X1 B5 F100\n", "line 1: the program turns B but machine"),
        ]
        for program, message in cases:
            with self.subTest(program=program), self.assertRaisesRegex(ValueError, re.escape(message)):
                hsmplanner.simulate(program, machine=TRUNNION)

    def test_fixed_orientation_keeps_the_three_axis_time(self):
        """A/C at zero with TCP is the 3-axis machine: the same lines take the same time. (Arcs are chords of 5°
        in a 5-axis program, each with its own axis projection: up to 3 % faster than the 3-axis arc model, which
        takes the weaker in-plane axis for the whole arc.)"""
        program = "G1 X20 Y0 Z0 F3000\nG1 X20 Y20\nG1 X0 Y25 Z-3\nG1 X0 Y0\nG1 X30 Y-4 Z0\n"
        three = hsmplanner.simulate(program, machine="mikron-ucp710-840d").summary.total_time
        five = hsmplanner.simulate("TRAORI\nG1 A0 C0 X0 F3000\n" + program, machine=TRUNNION).summary.total_time
        self.assertAlmostEqual(five, three, delta=0.01 * three)
        self.assertGreater(five, 0.0)



class Posts(unittest.TestCase):
    """The 5-axis posts on a small fixed operation whose moves carry A and C, against golden files, and read
    back by the simulator on the machine they were posted for."""

    LINES = ["(5-axis fixed program)", "G0 X0 Y0 Z5 A0 C0", "G1 X0 Y0 Z-1 F10", "G1 X20 Y0 Z-1 A10 C15",
             "G1 X20 Y10 A20 C30", "G2 X20 Y20 Z-1 I0 J5 C40", "G1 X0 Y20 A-15 C60 F20", "G0 Z5 A0 C0"]

    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("FiveAxisPosts")
        cls.job = create_job([master_feature_object.create(cls.document)])
        cls.controller = finishing.ball_end_controller(cls.job, 4.0, 4000.0)
        cls.op = cam_module("custom_op").Create("Fixed5", parentJob=cls.job)
        cls.op.Gcode = cls.LINES
        cls.document.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def simulated(self, text, machine):
        result = hsmplanner.simulate(text, machine, blocks=True, refuse_unknown_words=True)
        self.assertEqual(result.summary.cutting_blocks, 5)
        return result

    def test_840d_angles(self):
        text = siemens840d_post.export([self.job, self.controller, self.op], "-", "--machine=mikron-ucp710-ac-840d")
        self.assertIn("TRAORI", text)
        self.assertIn("A10 C15", text)
        result = self.simulated(text, "mikron-ucp710-ac-840d")
        np.testing.assert_allclose(result.blocks["rotary_end"][-2], [-15.0, 60.0], atol=1e-9)
        check_golden(self, text, "siemens840d_5axis_angles.mpf")

    def test_840d_vectors_give_the_same_angles_back(self):
        text = siemens840d_post.export([self.job, self.controller, self.op], "-",
                                       "--machine=mikron-ucp710-ac-840d --orientation=vectors")
        self.assertIn("ORIWKS ORIVECT", text)
        self.assertNotRegex(text, r" [AC]-?[\d.]+(\s|$)")  # no angles: vectors only
        result = self.simulated(text, "mikron-ucp710-ac-840d")
        # Every block ends with the tool axis the operation's angles give. The angles themselves may differ: from
        # A20 C40 to A-15 C60 the great circle passes 2.6° from the pole, and the controller, following it, keeps
        # A positive and turns C half a turn (A15 C-120), as a real 840D in ORIVECT does.
        machine = feedsim.load_machine("mikron-ucp710-ac-840d")
        wanted = [(0, 0), (0, 0), (10, 15), (20, 30), (20, 40), (-15, 60), (0, 0)]
        for end, angles in zip(result.blocks["rotary_end"], wanted):
            np.testing.assert_allclose(_core.forward_kinematics(machine, [0, 0, 0], list(end))[1],
                                       _core.forward_kinematics(machine, [0, 0, 0], list(angles))[1], atol=1e-5)
        np.testing.assert_allclose(result.blocks["rotary_end"][-2], [15.0, -120.0], atol=1e-3)
        check_golden(self, text, "siemens840d_5axis_vectors.mpf")

    def test_linuxcnc_trt(self):
        text = linuxcnc5x_post.export([self.job, self.controller, self.op], "-", "")
        self.assertIn("G64 P0.01", text)
        result = self.simulated(text, "linuxcnc-2.9-xyzac-trt")
        np.testing.assert_allclose(result.blocks["rotary_end"][-2], [-15.0, 60.0], atol=1e-9)
        # LinuxCNC refuses a comment with a '(' inside; the header names the kinematics in brackets
        for line in text.splitlines():
            self.assertLessEqual(line.count("("), 1, line)
        self.assertIn("[table-table, tool tip programmed]", text.splitlines()[0])
        check_golden(self, text, "linuxcnc_5axis_trt.ngc")

    def test_cam_post_process_writes_the_golden_programs(self):
        """CAM's Post Process as its command runs it: the Job's post-processor chosen in its list, its arguments,
        and the factory's processor, which on FreeCAD 1.1 is our class-based post (Hsm_Siemens840D,
        Hsm_Linuxcnc5X) and on 1.0 CAM's wrapper of the script. Either way the golden files' programs."""
        import Path.Preferences
        from Path.Post.Processor import PostProcessorFactory

        available = Path.Preferences.allAvailablePostProcessors()
        cases = [("hsm_siemens840d", "Hsm_Siemens840D", "--machine=mikron-ucp710-ac-840d", "siemens840d_5axis_angles.mpf"),
                 ("hsm_siemens840d", "Hsm_Siemens840D", "--machine=mikron-ucp710-ac-840d --orientation=vectors",
                  "siemens840d_5axis_vectors.mpf"),
                 ("hsm_linuxcnc5x", "Hsm_Linuxcnc5X", "", "linuxcnc_5axis_trt.ngc")]
        class_based = compat.freecad_version() >= (1, 1)
        saved = self.job.PostProcessor, self.job.PostProcessorArgs
        try:
            for name, class_name, arguments, golden in cases:
                self.assertIn(name, available)
                self.job.PostProcessor = name
                self.job.PostProcessorArgs = arguments
                processor = PostProcessorFactory.get_post_processor(self.job, name)
                self.assertEqual(type(processor).__name__, class_name if class_based else "WrapperPost")
                sections = processor.export()
                self.assertEqual([section for section, _ in sections], ["allitems"])
                check_golden(self, sections[0][1], golden)
        finally:
            self.job.PostProcessor, self.job.PostProcessorArgs = saved

    def test_feed_rate_analysis_of_a_five_axis_operation(self):
        """The document's analysis reads the operation's A and C as the Job machine's, the tip programmed."""
        from hsmplanner.app import feedrate_object

        analysis = feedrate_object.create(self.op, "mikron-ucp710-ac-840d", self.document)
        self.document.recompute()
        try:
            result = analysis.Proxy.ensure_result(analysis)
            self.assertEqual(result.summary.cutting_blocks, 5)
            np.testing.assert_allclose(result.blocks["rotary_end"][-2], [-15.0, 60.0], atol=1e-9)
            np.testing.assert_allclose(result.blocks["end"][-2], [0.0, 20.0, -1.0], atol=1e-9)  # the tip
            self.assertIn("F", feedsim.speed_limit_shares(result.summary))
        finally:
            self.document.removeObject(analysis.Name)

    def test_bad_machines_are_refused_by_name(self):
        objects = [self.job, self.controller, self.op]
        with self.assertRaisesRegex(ValueError, "turn A but machine 'swivel-head-bc-840d' has rotary axes C, B"):
            siemens840d_post.export(objects, "-", "--machine=swivel-head-bc-840d")
        with self.assertRaisesRegex(ValueError, "orientation vectors need the machine"):
            siemens840d_post.export(objects, "-", "--orientation=vectors")
        with self.assertRaisesRegex(ValueError, "not a LinuxCNC machine with TCP kinematics"):
            linuxcnc5x_post.export(objects, "-", "--machine=linuxcnc-2.9")
        self.op.Gcode = self.LINES[:-1] + ["G1 X0 Y0 A-120 C0"]
        self.document.recompute()
        try:
            with self.assertRaisesRegex(ValueError, r"Fixed5, move \d+: A-120 is outside the travel of A on "
                                                    r"'linuxcnc-2.9-xyzac-trt' \[-100, 50\] deg"):
                linuxcnc5x_post.export(objects, "-", "")
        finally:
            self.op.Gcode = self.LINES
            self.document.recompute()


if __name__ == "__main__":
    unittest.main()
