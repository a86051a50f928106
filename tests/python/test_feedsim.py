"""Feed-rate simulation from Python, the CLI and FreeCAD: consistency, reports, bad input, fuzzing."""
import json
import os
import random
import subprocess
import unittest

import FreeCAD
import numpy as np
import Path

import hsmplanner
from hsmplanner import feedsim
from hsmplanner.app import feedrate, feedrate_object, master_feature_object, probe_paths
from hsmplanner.app.compat import post_module
from hsmplanner.scripting import build_program
from helpers import REPO, run, temporary_directory

FEEDSIM = build_program(REPO, "hsm-feedsim")
PROGRAM = "G21 G90\nG0 X0 Y0 Z5\nG1 Z0 F3000\nG1 X40\nG2 X40 Y20 I0 J10\nG1 X0\nG3 X0 Y40 I0 J10 F6000\nG0 Z5\n"


class PythonApi(unittest.TestCase):
    def test_text_file_and_path_commands_agree(self):
        folder = temporary_directory(self)
        path = os.path.join(folder, "p.ngc")
        with open(path, "w") as stream:
            stream.write(PROGRAM)
        from_text = hsmplanner.simulate(PROGRAM).summary.total_time
        from_file = hsmplanner.simulate(path).summary.total_time
        commands = [Path.Command(line.split()[0], {w[0]: float(w[1:]) / (60.0 if w[0] == "F" else 1.0)
                                                    for w in line.split()[1:]})
                    for line in PROGRAM.splitlines()[1:]]
        from_commands = hsmplanner.simulate(commands).summary.total_time
        self.assertAlmostEqual(from_text, from_file, places=12)
        self.assertAlmostEqual(from_text, from_commands, places=9)
        self.assertGreater(from_text, hsmplanner.simulate(PROGRAM).summary.naive_time)

    def test_moves_simulated_without_gcode_text(self):
        """A toolpath's moves give the time of the same moves written as G-code (to its 4 decimals)."""
        from hsmplanner.toolpaths import moves_to_gcode

        angle = np.linspace(0.0, 2.0 * np.pi, 400)
        moves = np.column_stack([30 * np.cos(angle), 20 * np.sin(angle), 0.01 * angle, np.zeros_like(angle)])
        moves = np.vstack([[30.0, 0.0, 5.0, 1.0], moves])
        direct = hsmplanner.feedsim.simulate_moves(moves, 4000.0, blocks=True)
        text = hsmplanner.simulate(moves_to_gcode(moves, 4000.0)).summary
        self.assertEqual(direct.summary.block_count, text.block_count)
        self.assertAlmostEqual(direct.summary.total_time, text.total_time, delta=1e-4 * text.total_time)
        self.assertAlmostEqual(direct.summary.time_over_naive, direct.summary.total_time / direct.summary.naive_time)
        self.assertEqual(len(direct.blocks["line"]), direct.summary.block_count)
        with self.assertRaisesRegex(ValueError, "must be positive"):
            hsmplanner.feedsim.simulate_moves(moves, 0.0)
        with self.assertRaisesRegex(ValueError, r"\(N, 4\) array"):
            hsmplanner.feedsim.simulate_moves(moves[:, :3], 4000.0)

    def test_blocks_and_trace(self):
        result = hsmplanner.simulate(PROGRAM, "linuxcnc-2.9", blocks=True, trace_period=0.002)
        blocks = result.blocks
        self.assertEqual(len(blocks["line"]), result.summary.block_count)
        self.assertAlmostEqual(float(np.sum(blocks["time"])), result.summary.total_time, places=9)
        self.assertEqual(list(blocks["motion"][:4]), [0, 1, 1, 2])  # G0 Z5, G1 Z0, G1 X40, G2
        self.assertAlmostEqual(blocks["sweep"][3], -np.pi, places=9)  # the G2 half circle
        self.assertEqual(result.trace.shape[1], 5)
        self.assertLessEqual(result.trace[:, 4].max(), 6000 / 60 + 1e-9)

    def test_machines_by_name_file_and_dict(self):
        folder = temporary_directory(self)
        mikron = hsmplanner.load_machine("mikron-ucp710-840d")
        data = json.loads(mikron.to_json())
        data["name"] = "slower"
        data["axes"]["X"]["max_acceleration_m_s2"] = 0.5
        path = os.path.join(folder, "slower.json")
        with open(path, "w") as stream:
            json.dump(data, stream)
        slow_file = hsmplanner.simulate(PROGRAM, path).summary.total_time
        slow_dict = hsmplanner.simulate(PROGRAM, data).summary.total_time
        fast = hsmplanner.simulate(PROGRAM, mikron).summary.total_time
        self.assertAlmostEqual(slow_file, slow_dict, places=12)
        self.assertGreater(slow_file, fast)

    def test_report_files(self):
        folder = temporary_directory(self)
        paths = feedsim.write_report(hsmplanner.simulate(PROGRAM, blocks=True), folder, "r", "demo")
        with open(paths[0]) as stream:
            summary = json.load(stream)
        for key in ("total_time_s", "cutting_time_s", "rapid_time_s", "naive_time_s", "block_count", "feed_classes"):
            self.assertIn(key, summary)
        with open(paths[1]) as stream:
            self.assertEqual(len(stream.readlines()), summary["block_count"] + 1)
        for png in paths[2:]:
            with open(png, "rb") as stream:
                self.assertEqual(stream.read(4), b"\x89PNG")
        with self.assertRaisesRegex(ValueError, "blocks=True"):
            feedsim.write_blocks_csv(hsmplanner.simulate(PROGRAM), os.path.join(folder, "x.csv"))


class BadInput(unittest.TestCase):
    def test_messages_name_the_input(self):
        cases = [
            (lambda: hsmplanner.simulate("G1 X1 F100\nG2 X5 Y0 I1\n"), ValueError, "line 2: arc end point"),
            (lambda: hsmplanner.simulate("G1 X1\n"), ValueError, "line 1: no feed rate"),
            (lambda: hsmplanner.simulate("nofile.ngc"), ValueError, "neither an existing file"),
            (lambda: hsmplanner.simulate(PROGRAM, "haas"), ValueError, "machine 'haas'"),
            (lambda: hsmplanner.simulate(PROGRAM, {"name": "x"}), ValueError, "missing \"controller\""),
            (lambda: hsmplanner.simulate(PROGRAM, 3), TypeError, "machine must be"),
            (lambda: hsmplanner.simulate(42), TypeError, "program must be"),
            (lambda: hsmplanner.simulate(PROGRAM, trace_period=-1), ValueError, "trace_period"),
            (lambda: hsmplanner.simulate("G1 X1 F100 Q7 U3\n", refuse_unknown_words=True), ValueError, "'U3'"),
        ]
        for call, error, message in cases:
            with self.subTest(message=message), self.assertRaisesRegex(error, message):
                call()

    def test_fuzzed_programs_never_crash(self):
        rng = random.Random(3)
        alphabet = "GXYZIJKFRP0123456789.-+ ()\n;=%"
        outcomes = {"ok": 0, "refused": 0}
        for _ in range(3000):
            text = list(PROGRAM)
            for _ in range(rng.randint(1, 6)):
                text.insert(rng.randrange(len(text) + 1), rng.choice(alphabet))
            try:
                summary = hsmplanner.simulate("".join(text), rng.choice(hsmplanner.machine_names())).summary
                self.assertTrue(np.isfinite(summary.total_time) and summary.total_time >= 0)
                outcomes["ok"] += 1
            except ValueError:
                outcomes["refused"] += 1
        self.assertGreater(outcomes["ok"], 100)
        self.assertGreater(outcomes["refused"], 100)


class CommandLine(unittest.TestCase):
    def test_json_csv_and_summary(self):
        folder = temporary_directory(self)
        program = os.path.join(folder, "p.ngc")
        with open(program, "w") as stream:
            stream.write(PROGRAM)
        out_json, out_csv = os.path.join(folder, "s.json"), os.path.join(folder, "b.csv")
        result = run([FEEDSIM, program, "--machine", "grbl", "--json", out_json, "--csv", out_csv])
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("simulated time", result.stdout)
        with open(out_json) as stream:
            summary = json.load(stream)
        self.assertAlmostEqual(summary["total_time_s"], hsmplanner.simulate(PROGRAM, "grbl").summary.total_time,
                               places=9)
        with open(out_csv) as stream:
            self.assertEqual(len(stream.readlines()), summary["block_count"] + 1)

    def test_errors_exit_non_zero_with_a_message(self):
        folder = temporary_directory(self)
        program = os.path.join(folder, "bad.ngc")
        with open(program, "w") as stream:
            stream.write("G1 X1 F100\nG1 X1.2.3\n")
        result = run([FEEDSIM, program, "--machine", "grbl"])
        self.assertEqual(result.returncode, 1)
        self.assertIn("hsm-feedsim: error: line 2:", result.stderr)
        result = run([FEEDSIM, program, "--machine", "nope"])
        self.assertIn("machine 'nope'", result.stderr)
        self.assertEqual(run([FEEDSIM, "--list-machines"]).stdout.split(), hsmplanner.machine_names())


class FreeCadJob(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("FeedSimJob")
        cls.part = master_feature_object.create(cls.document)
        cls.job, cls.op = probe_paths.make_probe_job(cls.part, 4000.0, pass_spacing=6.0, point_spacing=1.0)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def test_job_operation_and_posted_file_agree(self):
        from_job = feedrate.simulate_object(self.job, blocks=False).summary
        from_op = feedrate.simulate_object(self.op, blocks=False).summary
        self.assertAlmostEqual(from_job.total_time, from_op.total_time, delta=1e-6)  # one operation
        program = os.path.join(temporary_directory(self), "job.ngc")
        post_module("linuxcnc").export([self.job] + self.job.Operations.Group, program, "--no-show-editor")
        posted = hsmplanner.simulate(program).summary
        self.assertEqual(posted.block_count, from_job.block_count)
        self.assertAlmostEqual(posted.total_time, from_job.total_time, delta=1e-3 * from_job.total_time)

    def test_analysis_object_recomputes_saves_and_restores(self):
        analysis = feedrate_object.create(self.job, "linuxcnc-2.9")
        self.assertTrue(analysis.isValid(), analysis.State)
        self.assertGreater(analysis.TotalTime, analysis.NaiveTime)
        self.assertAlmostEqual(sum(analysis.FeedClassesTime), 1.0, places=9)
        self.assertEqual(json.loads(analysis.Report)["machine"], "linuxcnc-2.9")
        import shutil

        folder = temporary_directory(self)
        path = os.path.join(folder, "analysis.FCStd")
        self.document.saveAs(path)
        shutil.copy(path, os.path.join(folder, "reopened.FCStd"))  # a second document from the same file
        restored_document = FreeCAD.openDocument(os.path.join(folder, "reopened.FCStd"))
        self.addCleanup(FreeCAD.closeDocument, restored_document.Name)
        restored = restored_document.getObject(analysis.Name)
        self.assertIsNone(restored.Proxy.result)
        result = restored.Proxy.ensure_result(restored)
        self.assertAlmostEqual(result.summary.total_time, analysis.TotalTime, places=9)
        self.document.removeObject(analysis.Name)

    def test_bad_source_and_machine(self):
        with self.assertRaisesRegex(ValueError, "not a Path/CAM Job or operation"):
            feedrate_object.create(self.part)
        analysis = feedrate_object.create(self.op)
        analysis.Machine = feedrate_object.CUSTOM_MACHINE
        self.document.recompute()  # reported on one line, as FreeCAD's CAM operations do: no traceback
        self.assertIn("MachineFile is empty", analysis.Proxy.error)
        self.assertEqual((analysis.TotalTime, analysis.Report, analysis.Proxy.ensure_result(analysis)), (0.0, "", None))
        self.document.removeObject(analysis.Name)


if __name__ == "__main__":
    unittest.main()
