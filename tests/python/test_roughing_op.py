"""The Volume roughing operation in a real Path Job: a torus ToolBit, a Roughing volume, the path, and the
posts (840D TRAORI, LinuxCNC xyzac-trt) read back by the simulator."""
import os
import unittest

import FreeCAD
import numpy as np

import hsmplanner
from hsmplanner.app import roughing_object, roughing_op, roughing_parts
from hsmplanner.app.compat import create_job
from hsmplanner.app.posts import linuxcnc5x_post, siemens840d_post
from helpers import temporary_directory


class VolumeRoughing(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("VolumeRoughing")
        part, stock = roughing_parts.create_slanted_slot_block(cls.document)
        part.SlotWidth = 30.0
        part.Length = 100.0
        cls.document.recompute()
        cls.volume = roughing_object.create(part, stock, Strategy="S3")
        cls.job = create_job([part])
        cls.controller = roughing_op.torus_controller(cls.job)
        cls.op = roughing_op.CreateVolumeRoughing("Roughing", parentJob=cls.job)
        cls.op.Volume = cls.volume
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

    def test_a_tilted_strategy_on_a_three_axis_machine_is_refused(self):
        self.op.Machine = "mikron-ucp710-840d"
        self.document.recompute()
        try:
            self.assertFalse(self.op.isValid())
        finally:
            self.op.Machine = roughing_op.DEFAULT_MACHINE
            self.document.recompute()
        self.assertTrue(self.op.isValid(), self.op.State)

    def test_the_cutter_comes_from_the_tool(self):
        cutter = roughing_op.cutter_of(self.controller.Tool)
        self.assertEqual(cutter.kind.name, "torus")
        self.assertAlmostEqual(cutter.diameter, 8.0)
        self.assertAlmostEqual(cutter.corner_radius, 1.0)


if __name__ == "__main__":
    unittest.main()
