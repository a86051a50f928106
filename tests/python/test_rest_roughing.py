"""Rest roughing: the stock a first roughing leaves, as points, cut by a second operation with a smaller tool
(the API on the slanted slot, and the Volume roughing operation's RestFrom in a real Path Job)."""
import unittest

import FreeCAD
import numpy as np

from hsmplanner import roughing
from hsmplanner.app.roughing import volume as roughing_object, operation as roughing_op, study as roughing_study
from helpers import slot_roughing_job

SMALL = dict(diameter=4.0, corner_radius=0.5, flute_length=15.0, stick_out=30.0)


class RestRoughingApi(unittest.TestCase):
    """Z-level (S1) leaves the slot's overhanging wedge; a Ø4 rest roughing along the setup direction searched on
    what is left takes it out."""

    @classmethod
    def setUpClass(cls):
        cls.shapes = roughing.slanted_slot_block()
        cls.volume = roughing.volume_to_remove(cls.shapes.stock_brep, cls.shapes.part_brep)
        cls.solid = cls.volume.solids[0]
        first = roughing.partition(cls.solid, cls.shapes.part_brep, "S1")
        cls.first = roughing.sweep(first, cls.solid, cls.shapes.part_brep, cls.shapes.stock_brep)
        cls.left = roughing.simulate_removal(cls.first, cls.shapes.stock_brep, cls.shapes.part_brep, resolution=0.4,
                                             rest_spacing=0.4)

    def test_the_stock_left_as_points_beyond_the_allowance(self):
        rest = self.left.rest
        self.assertAlmostEqual(rest.spacing, 0.4)
        points = rest.points
        self.assertEqual(points.shape, (len(rest), 3))
        # The points stand for what S1 left beyond the allowance layer: about the beyond-allowance volume.
        self.assertGreater(rest.volume, 0.5 * self.left.beyond_allowance_volume)
        self.assertLess(rest.volume, 1.5 * self.left.beyond_allowance_volume + 0.1 * self.volume.volume)
        self.assertEqual(len(roughing.simulate_removal(self.first, self.shapes.stock_brep, self.shapes.part_brep,
                                                       resolution=0.4).rest), 0, "no points unless asked")

    def test_a_smaller_tool_takes_out_what_the_first_left(self):
        small = roughing.cutter(**SMALL)
        rest = self.left.rest
        partition = roughing.partition(self.solid, self.shapes.part_brep, "S3", step=4.0, rest=rest)
        second = roughing.sweep(partition, self.solid, self.shapes.part_brep, self.shapes.stock_brep, tool=small,
                                rest=rest)
        self.assertGreater(len(second.passes), 0)
        everywhere = roughing.sweep(partition, self.solid, self.shapes.part_brep, self.shapes.stock_brep, tool=small)
        self.assertLess(second.cutting_length, everywhere.cutting_length, "it cuts only where stock is left")
        moves, fed = roughing.keep_rapids_out_of_stock(second, self.shapes.stock_brep, self.shapes.part_brep, tool=small,
                                                       resolution=0.4, after=[(self.first, None)])
        both = roughing.simulate_removal(self.first, self.shapes.stock_brep, self.shapes.part_brep, resolution=0.4,
                                         then=[(moves, small)])
        self.assertLess(both.beyond_allowance_share, 0.5 * self.left.beyond_allowance_share,
                        "%.1f %% after the rest roughing, %.1f %% before" % (both.beyond_allowance_share,
                                                                            self.left.beyond_allowance_share))
        self.assertEqual(both.gouge_volume, 0.0)
        self.assertEqual(len(both.rapid_faults), 0, both.rapid_faults)
        self.assertGreaterEqual(roughing.check_clearance(second, self.shapes.part_brep, tool=small).minimum, 0.49)
        # The moves count on through both operations.
        self.assertEqual(len(both.rapid_faults), 0)
        self.assertGreater(both.path_length, self.left.path_length)

    def test_what_z_level_leaves_split_by_cause(self):
        partition = roughing.partition(self.solid, self.shapes.part_brep, "S1")
        split = roughing.split_what_is_left(partition, self.solid, self.shapes.part_brep, self.first, resolution=0.5)
        self.assertAlmostEqual(split.volume, self.volume.volume, delta=0.02 * self.volume.volume)
        # Along Z the overhanging wall hides a wedge of the slot: no tool reaches it, whatever the path.
        self.assertGreater(split.unreachable, 0.28 * self.volume.volume)
        self.assertLess(split.unreachable + split.between_levels, self.left.remaining_volume * 1.05)
        with self.assertRaisesRegex(ValueError, "resolution 0.01 mm is outside"):
            roughing.split_what_is_left(partition, self.solid, self.shapes.part_brep, self.first, resolution=0.01)

    def test_a_study_rest_passes_its_sweep_settings_on(self):
        fine = roughing_study.Rest(sweep_settings=dict(step_up_scallop=0.1, step_up_minimum=0.5))
        self.assertEqual(fine.label, "step-up + rest S3 Ø4 (step_up_minimum 0.5, step_up_scallop 0.1)")
        self.assertEqual(roughing_study.Rest().label, "step-up + rest S3 Ø4")
        self.assertEqual(roughing_study.Rest(sweep_settings=dict(push_out=None)).label, "step-up + rest S3 Ø4")
        for keyword in ("tool", "stepover"):
            with self.subTest(keyword=keyword), self.assertRaisesRegex(
                    ValueError, "rest roughing: %s is not a sweep setting a rest may set: use .*mesh_deflection" % keyword):
                roughing_study.Rest(sweep_settings={keyword: 1.0})
        for wrong in ([1, 2], "fine", 0):
            with self.subTest(wrong=wrong), self.assertRaisesRegex(TypeError, "sweep_settings must be a dict"):
                roughing_study.Rest(sweep_settings=wrong)
        small, rest = roughing.cutter(**SMALL), self.left.rest

        def closest(**settings):
            regions = roughing_study.sweep_regions("S3", self.shapes.part_brep, self.shapes.stock_brep, [self.solid],
                                                   small, dict(step=4.0), True, rest, sweep_settings=settings)
            return roughing.check_clearance(regions[0], self.shapes.part_brep, tool=small, limit=0.0).minimum

        self.assertLess(closest(), 0.9)  # the default allowance, 0.5 mm
        self.assertGreaterEqual(closest(allowance=1.0), 0.99)
        with self.assertRaisesRegex(ValueError, "mesh deflection = 0.001 is outside \\[0.005, 1\\]"):
            closest(mesh_deflection=0.001)
        odd = roughing_study.Rest(sweep_settings=dict(mesh_deflection="fine"))  # the sweep names it, not the label
        self.assertEqual(odd.label, "step-up + rest S3 Ø4 (mesh_deflection fine)")
        with self.assertRaisesRegex(TypeError, r"SweepSettings.mesh_deflection cannot be 'fine' \(str\): give a float"):
            closest(mesh_deflection="fine")

    def test_bad_inputs_are_named(self):
        with self.assertRaisesRegex(ValueError, "rest spacing 0.1 mm is outside \\[0.4"):
            roughing.simulate_removal(self.first, self.shapes.stock_brep, self.shapes.part_brep, resolution=0.4,
                                      rest_spacing=0.1)
        with self.assertRaisesRegex(ValueError, "rest stock points must be an \\(N, 3\\) array"):
            roughing._core.roughing.RestStock(np.zeros((4, 2)), 0.4)
        bad = roughing._core.roughing.RestStock(np.array([[np.nan, 0.0, 0.0]]), 0.4)
        partition = roughing.partition(self.solid, self.shapes.part_brep, "S1")
        with self.assertRaisesRegex(ValueError, "rest stock: a point is not finite"):
            roughing.sweep(partition, self.solid, self.shapes.part_brep, self.shapes.stock_brep, rest=bad)
        with self.assertRaisesRegex(ValueError, "rest stock spacing = 0 is outside"):
            roughing.sweep(partition, self.solid, self.shapes.part_brep, self.shapes.stock_brep,
                           rest=roughing._core.roughing.RestStock(np.zeros((1, 3)), 0.0))
        with self.assertRaisesRegex(ValueError, "each run is \\(moves, cutter\\)"):
            roughing._core.roughing.simulate_removal_runs([(1, 2, 3)], self.shapes.stock_brep, self.shapes.part_brep,
                                                          roughing._core.roughing.RemovalSettings())


class RestFromOperation(unittest.TestCase):
    """Two Volume roughing operations in a Job: S1 with the paper's torus, then a Ø4 torus on an S3 volume with
    RestFrom the first."""

    @classmethod
    def setUpClass(cls):
        cls.document, part, stock, cls.job, _, cls.first = slot_roughing_job("RestRoughing", "S1")
        small = roughing_op.torus_controller(cls.job, diameter=4.0, corner_radius=0.5, number=4, replace=False)
        cls.rest = roughing_op.CreateVolumeRoughing("Rest", parentJob=cls.job)
        cls.rest.Volume = roughing_object.create(part, stock, Strategy="S3", Step=4.0)
        cls.rest.ToolController = small
        cls.rest.RestFrom = cls.first
        cls.document.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def test_the_rest_operation_cuts_only_what_the_first_left(self):
        self.assertGreater(self.first.Passes, 0)
        self.assertGreater(self.rest.Passes, 0)
        self.assertGreaterEqual(self.rest.ClosestApproach.Value, 0.49)
        alone = roughing_op.volume_roughing_program(self.rest)  # as computed
        self.rest.RestFrom = None
        self.document.recompute()
        try:
            self.assertGreater(self.rest.CuttingLength.Value, alone.cutting_length,
                               "without RestFrom it cuts the whole volume")
        finally:
            self.rest.RestFrom = self.first
            self.document.recompute()
        self.assertAlmostEqual(self.rest.CuttingLength.Value, alone.cutting_length, places=6)

    def test_step_up_and_rest_properties_with_their_defaults(self):
        self.assertAlmostEqual(self.first.StepUpMinimum.Value, 1.0)
        self.assertAlmostEqual(self.first.StepUpScallop.Value, 0.25)
        self.assertAlmostEqual(self.first.PushOut.Value, roughing_op._DEFAULTS.push_out_most)
        for name in ("StepUpMinimum", "StepUpScallop", "PushOut", "RestFrom"):
            self.assertIn(name, self.first.PropertiesList)

    def test_a_link_that_is_not_a_roughing_or_loops_is_said(self):
        self.assertRaisesRegex(ValueError, "is not a Volume roughing operation", roughing_op.operations_before,
                               type("Op", (), {"Name": "A", "Label": "A", "RestFrom": self.job})())
        a = type("Op", (), {"Name": "A", "Label": "A"})()
        b = type("Op", (), {"Name": "B", "Label": "B", "RestFrom": a})()
        a.RestFrom = b
        a.Proxy = b.Proxy = roughing_op.ObjectVolumeRoughing.__new__(roughing_op.ObjectVolumeRoughing)
        self.assertRaisesRegex(ValueError, "leads back to itself", roughing_op.operations_before, a)
