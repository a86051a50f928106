"""Finishing: the toolpath API, the two operations in a real Job, the posts against golden files, and the
evaluation figures."""
import os
import unittest

import FreeCAD
import numpy as np
import Part

import hsmplanner
from hsmplanner import evaluation
from hsmplanner.app import finishing, finishing_ops, guide_curve_net_object, master_feature_object
from hsmplanner.app.compat import cam_module, create_job, post_module
from hsmplanner.app.master_feature import make_master_bottom_feature
from hsmplanner.app.posts import siemens840d_post
from helpers import REPO, check_clearance_start_and_end, check_golden, temporary_directory

FEATURE = make_master_bottom_feature()


class ToolpathApi(unittest.TestCase):
    def test_parallel_planes_on_the_part(self):
        moves, stats = hsmplanner.parallel_finishing(FEATURE.shape, FEATURE.bottom_face, angle_deg=90.0)
        self.assertGreater(stats["passes"], 100)
        self.assertEqual(moves.shape[1], 4)
        feeds = moves[moves[:, 3] == 0]
        self.assertLess(np.ptp(feeds[:, 1]), 70)  # within the cavity's width
        self.assertGreater(hsmplanner.toolpaths.path_length(moves), 10000)
        self.assertEqual(len(stats["pass_lengths"]), stats["passes"])

    def test_guide_finishing_from_a_net(self):
        b1, b2 = FEATURE.shape.getElement(FEATURE.boundary_1), FEATURE.shape.getElement(FEATURE.boundary_2)
        bottom = FEATURE.shape.getElement(FEATURE.bottom_face)
        net, _ = hsmplanner.guidance_curves(b1, b2, face=bottom)
        moves, stats = hsmplanner.guide_finishing(FEATURE.shape, FEATURE.bottom_face, net, zigzag=False)
        self.assertGreater(stats["passes"], 100)
        rapids = int(np.sum(np.diff(moves[:, 3]) > 0))
        self.assertGreaterEqual(rapids, stats["passes"] - 1)  # one-way: a retract between passes

    def test_bad_inputs_name_themselves(self):
        cases = [(dict(sweep="sideways"), "sweep 'sideways'"), (dict(tool_diameter=0), "tool diameter 0"),
                 (dict(cusp_height=5.0), "cusp height"), (dict(tolerance=0), "machining tolerance")]
        for kwargs, message in cases:
            with self.subTest(kwargs=kwargs), self.assertRaisesRegex(ValueError, message):
                hsmplanner.parallel_finishing(FEATURE.shape, FEATURE.bottom_face, **kwargs)
        with self.assertRaisesRegex(ValueError, "not a face name"):
            hsmplanner.parallel_finishing(FEATURE.shape, "Edge3")
        with self.assertRaisesRegex(ValueError, "bottom face Face99 does not exist: the part has 10 faces"):
            hsmplanner.parallel_finishing(FEATURE.shape, 99)
        with self.assertRaisesRegex(ValueError, "no area"):
            hsmplanner.guide_finishing(FEATURE.shape, FEATURE.bottom_face, [])


class NetCurves(unittest.TestCase):
    """Finishing takes a net's curves from its CurveShapes, B1 to B2, not from the order of its Shape's edges."""

    def setUp(self):
        self.document = FreeCAD.newDocument("NetCurves")
        self.addCleanup(FreeCAD.closeDocument, self.document.Name)
        self.part = master_feature_object.create(self.document)
        p = self.part
        self.net = guide_curve_net_object.create(self.document, (p, p.Boundary1), (p, p.Boundary2),
                                                 (p, p.BottomFace))

    @staticmethod
    def points(curves):
        return [np.asarray(hsmplanner.as_curve(c).sample(40)) for c in curves]

    def test_a_net_whose_shape_is_reordered_gives_the_same_curves(self):
        expected = self.points(guide_curve_net_object.net_curve_edges(self.net))
        self.assertEqual(len(expected), 5)
        curves, faces = guide_curve_net_object.net_curve_edges(self.net), self.net.Shape.Faces
        self.net.Shape = Part.Compound(list(reversed(curves)) + faces)  # the curves first, B2 to B1
        self.assertFalse(np.allclose(self.points(self.net.Shape.Edges[-1:])[0], expected[-1]))
        got = self.points(finishing.net_curves(self.net))
        self.assertEqual(len(got), len(expected))
        for a, b in zip(got, expected):
            np.testing.assert_allclose(a, b, atol=1e-9)
        boundary_1 = self.part.Shape.getElement(self.part.Boundary1)
        ends = sorted(tuple(v.Point) for v in boundary_1.Vertexes)
        np.testing.assert_allclose(sorted([tuple(got[0][0]), tuple(got[0][-1])]), ends, atol=1e-6)
        pairs = finishing.net_areas(self.net)
        self.assertEqual(len(pairs), 4)
        np.testing.assert_allclose(self.points([pairs[-1][1]])[0], expected[-1], atol=1e-9)  # ends at B2

    def test_a_net_without_curves_says_to_recompute_it(self):
        empty = guide_curve_net_object.create(self.document, name="Empty")
        with self.assertRaisesRegex(ValueError, "Empty has no curves: recompute it"):
            finishing.net_curves(empty)


class Operations(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("FinishingOps")
        part = master_feature_object.create(cls.document)
        cls.part = part
        cls.net = guide_curve_net_object.create(cls.document, (part, part.Boundary1), (part, part.Boundary2),
                                                (part, part.BottomFace))
        cls.job = create_job([part])
        cls.controller = finishing.ball_end_controller(cls.job, 4.0, 4000.0)
        cls.guide = finishing_ops.CreateGuideCurveFinishing("Guide", parentJob=cls.job)
        cls.guide.Net = cls.net
        cls.planes = finishing_ops.CreateParallelPlaneFinishing("Planes", parentJob=cls.job)
        cls.planes.Face = (part, part.BottomFace)
        cls.planes.Angle = 0
        cls.document.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def test_both_operations_compute_in_the_job(self):
        for op in (self.guide, self.planes):
            self.assertTrue(op.isValid(), op.State)
            self.assertIs(op.ToolController, self.controller)
            self.assertGreater(op.Passes, 100)
            feeds = [c.Parameters["F"] for c in op.Path.Commands if c.Name == "G1" and "F" in c.Parameters]
            self.assertAlmostEqual(max(feeds), 4000.0 / 60.0, places=6)  # the tool controller's feed, mm/s

    def test_the_cusp_range_is_what_the_core_takes_with_the_ball(self):
        low, high = finishing_ops.cusp_limits(self.controller)
        self.assertEqual((low, high), (0.001, 2.0 - 0.001))  # the Ø4 ball
        self.assertEqual(finishing_ops.cusp_limits(None), finishing_ops.LIMITS["CuspHeight"])
        shape, face = finishing.net_part(self.net)
        for cusp, refused in ((high, False), (2.0, True)):
            with self.subTest(cusp=cusp):
                call = lambda: hsmplanner.parallel_finishing(shape, face, 0.0, tool_diameter=4.0, cusp_height=cusp)
                if refused:
                    self.assertRaisesRegex(ValueError, "cusp height", call)
                else:
                    self.assertGreater(len(call()[0]), 0)

    def test_each_starts_and_ends_at_the_clearance_height_as_cams_own(self):
        for op in (self.guide, self.planes):
            with self.subTest(op=op.Label):
                self.assertGreater(op.ClearanceHeight.Value, op.SafeHeight.Value)
                check_clearance_start_and_end(self, op, op.ClearanceHeight.Value)

    def test_simulated_through_both_posts(self):
        folder = temporary_directory(self)
        direct = hsmplanner.simulate(self.guide, "mikron-ucp710-840d").summary
        mpf, ngc = os.path.join(folder, "g.mpf"), os.path.join(folder, "g.ngc")
        siemens840d_post.export([self.job, self.controller, self.guide], mpf, "--tolerance=0.01")
        post_module("linuxcnc").export([self.job, self.guide], ngc, "--no-show-editor")
        for program in (mpf, ngc):
            posted = hsmplanner.simulate(program, "mikron-ucp710-840d", refuse_unknown_words=program == mpf).summary
            self.assertEqual(posted.cutting_blocks, direct.cutting_blocks, program)
            self.assertAlmostEqual(posted.cutting_length, direct.cutting_length, delta=0.01 * direct.cutting_length)

    def test_a_job_with_freecads_default_tool_gets_a_ball_end(self):
        """FreeCAD's new Job holds a Ø5 flat end mill at feeds of 0: the operation takes a Ø4 ball end at
        F4000 added to the Job instead of failing; one that is switched to the flat tool says what to set."""
        self.addCleanup(FreeCAD.setActiveDocument, self.document.Name)  # runs last: the other tests' document
        document = FreeCAD.newDocument("DefaultTool")
        self.addCleanup(FreeCAD.closeDocument, document.Name)
        part = master_feature_object.create(document)
        job = create_job([part])
        default = list(job.Tools.Group)
        self.assertFalse(finishing.is_usable(default[0]))
        op = finishing_ops.CreateParallelPlaneFinishing("Planes", parentJob=job)
        op.Face = (part, part.BottomFace)
        document.recompute()
        controller = op.ToolController
        self.assertNotIn(controller, default)
        self.assertIn(controller, job.Tools.Group)
        self.assertTrue(finishing.is_ball_end(controller.Tool))
        self.assertAlmostEqual(controller.Tool.Diameter.Value, 4.0)
        self.assertAlmostEqual(controller.HorizFeed.getValueAs("mm/min").Value, 4000.0, places=6)
        self.assertTrue(op.isValid(), op.State)
        self.assertGreater(op.Passes, 10)
        second = finishing_ops.CreateGuideCurveFinishing("Guide", parentJob=job)
        self.assertIs(second.ToolController, controller)  # the Job's usable controller, not another one
        self.assertEqual(len(job.Tools.Group), 2)
        op.ToolController = default[0]
        document.recompute()
        self.assertFalse(op.isValid())
        self.assertIn("ball-end finishing needs a ball end mill", op.getStatusString())

    def test_missing_net_is_reported(self):
        op = finishing_ops.CreateGuideCurveFinishing("NoNet", parentJob=self.job)
        self.document.recompute()
        self.assertNotEqual(op.State, ["Up-to-date"])
        self.assertEqual(len([c for c in op.Path.Commands if c.Name == "G1"]), 0)
        self.document.removeObject(op.Name)

    def test_saved_and_restored(self):
        import shutil

        folder = temporary_directory(self)
        path = os.path.join(folder, "ops.FCStd")
        self.document.saveAs(path)
        shutil.copy(path, os.path.join(folder, "copy.FCStd"))
        copy = FreeCAD.openDocument(os.path.join(folder, "copy.FCStd"))
        self.addCleanup(FreeCAD.closeDocument, copy.Name)
        guide = copy.getObject(self.guide.Name)
        self.assertEqual(type(guide.Proxy).__name__, "ObjectGuideCurveFinishing")
        guide.touch()
        copy.recompute()
        self.assertEqual(guide.Passes, self.guide.Passes)


class Posts(unittest.TestCase):
    """Both posts on a small fixed operation, against golden files (FreeCAD's time stamp line left out)."""

    LINES = ["(small fixed program)", "G0 X0 Y0 Z5", "G1 X0 Y0 Z-1 F10", "G1 X20 Y0 Z-1", "G2 X20 Y10 Z-1 I0 J5",
             "G1 X0.0004 Y10", "G3 X0 Y20 I0 J5 F20", "G0 Z5"]

    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("Posts")
        part = master_feature_object.create(cls.document)
        cls.job = create_job([part])
        cls.controller = finishing.ball_end_controller(cls.job, 4.0, 4000.0)
        cls.op = cam_module("custom_op").Create("Fixed", parentJob=cls.job)
        cls.op.Gcode = cls.LINES
        cls.document.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def check(self, text, golden):
        """Against the golden file, FreeCAD's time stamp line left out."""
        check_golden(self, "".join(line for line in text.splitlines(True) if "Output Time" not in line), golden)

    def test_siemens_840d(self):
        text = siemens840d_post.export([self.job, self.controller, self.op], "-", "--tolerance=0.005")
        self.assertIn("CYCLE832(0.005,1,1)", text)
        summary = hsmplanner.simulate(text, "mikron-ucp710-840d", refuse_unknown_words=True).summary
        self.assertEqual(summary.cutting_blocks, 5)
        self.check(text, "siemens840d_fixed.mpf")

    def test_linuxcnc(self):
        path = os.path.join(temporary_directory(self), "fixed.ngc")
        post_module("linuxcnc").export([self.job, self.op], path, "--no-show-editor")
        self.assertEqual(hsmplanner.simulate(path, "linuxcnc-2.9").summary.cutting_blocks, 5)
        with open(path) as stream:
            self.check(stream.read(), "linuxcnc_fixed.ngc")

    def test_bad_post_arguments(self):
        with self.assertRaisesRegex(ValueError, "--tolerance must be positive"):
            siemens840d_post.export([self.job, self.op], "-", "--tolerance=-1")
        with self.assertRaises(SystemExit):
            siemens840d_post.export([self.job, self.op], "-", "--unknown-option")


class Evaluation(unittest.TestCase):
    def test_sequences_entries_and_short_share(self):
        program = ("G0 X0 Y0 Z1\nG1 Z0 F1000\nG1 X50\nG0 Z1\nG0 X60\nG1 Z0\nG1 X65\nG0 Z1\n")
        figures = evaluation.evaluate(hsmplanner.simulate(program, blocks=True))
        self.assertEqual(figures["tool_entries"], 2)
        self.assertEqual(figures["short_sequences"], 1)  # 1 + 5 mm < 20 mm; 1 + 50 mm is not
        self.assertAlmostEqual(figures["short_sequence_share"], 0.5)
        self.assertAlmostEqual(figures["path_length_mm"], 57.0)
        self.assertAlmostEqual(evaluation.short_share([5, 30, 40, 10]), 0.5)
        with self.assertRaisesRegex(ValueError, "blocks=True"):
            evaluation.evaluate(hsmplanner.simulate(program))


if __name__ == "__main__":
    unittest.main()
