"""The strategy study in a document (hsmplanner.app.strategy_study): the ranges as users type them, refused by
field name and bounded; the inputs from a selection or a Guide curve net; a row made into an operation of a Job
that computes."""
import re
import unittest

import FreeCAD

from hsmplanner.app import finishing, guide_curve_net_object, master_feature_object, strategy_study
from hsmplanner.app.compat import create_job


class Ranges(unittest.TestCase):
    def test_lists_and_ranges(self):
        parse = strategy_study.parse_numbers
        self.assertEqual(parse("0:180:15", "Plane angles"), [15.0 * i for i in range(12)])  # 180° is 0° again
        self.assertEqual(parse(" 0, 45,90 ,", "Plane angles"), [0.0, 45.0, 90.0])
        self.assertEqual(parse("0.25:0.8:0.25", "K"), [0.25, 0.5, 0.75])
        self.assertEqual(parse("0:0.3:0.1", "K"), [0.0, 0.1, 0.2])  # not 4 values from 0.30000000000000004
        self.assertEqual(parse("", "P"), [])
        self.assertEqual(parse("7", "P"), [7.0])

    def test_bad_ranges_name_their_field(self):
        parse = strategy_study.parse_numbers
        for text, field, words in (("abc", "K", "K: 'abc' is not a number"),
                                   ("1,,x", "P", "P: 'x' is not a number"),
                                   ("nan", "Feeds", "Feeds: 'nan' is not a finite number"),
                                   ("0:10", "Plane angles", "Plane angles: '0:10': write start:stop:step"),
                                   ("0:10:0", "Plane angles", "Plane angles: the step of '0:10:0' must be positive"),
                                   ("10:0:1", "K", "K: '10:0:1' gives no value"),
                                   ("0:180:0.000001", "Plane angles", "Plane angles: 180000000 values (more than "
                                                                      "10000)"),
                                   (",".join(["1"] * 10001), "Feeds", "Feeds: 10001 values (more than 10000)"),
                                   ("0:1:1e-320", "Plane angles", "Plane angles: '0:1:1e-320' gives more than 10000"),
                                   ("-1e308:1e308:1e304", "P", "P: '-1e308:1e308:1e304' gives more than 10000")):
            with self.subTest(text=text[:20]), self.assertRaisesRegex(ValueError, "^" + re.escape(words)):
                parse(text, field)

    def test_the_grid_from_the_panels_texts(self):
        grid = strategy_study.study_grid(planes="0,90", k="0.5", p="20", median="with the median", feeds="4000")
        self.assertEqual([(v["strategy"], v.get("angle_deg"), v.get("k"), v.get("p"), v.get("median")) for v in grid],
                         [("planes", 0.0, None, None, None), ("planes", 90.0, None, None, None),
                          ("guide", None, 0.5, 20.0, True)])
        self.assertEqual(len(strategy_study.study_grid(planes="0", k="0.5", p="10,20", four_step=True)), 1 + 4 + 1)
        three = strategy_study.study_grid(k="0.5", p="20", median="the paper's three")
        self.assertEqual([v["mode"] for v in three], ["b1_to_b2", "median_to_boundaries", "boundaries_to_median"])
        for kwargs, words in ((dict(k="1.5", p="20"), "K = 1.5 is outside ]0, 1["),
                              (dict(planes="0", feeds="-1"), "feed -1.0 mm/min must be positive"),
                              (dict(), "the grid is empty"),
                              (dict(planes="0", median="maybe"), "median 'maybe'")):
            with self.subTest(kwargs=kwargs), self.assertRaisesRegex(ValueError, re.escape(words)):
                strategy_study.study_grid(**kwargs)


class InDocument(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("StrategyStudyApp")
        cls.part = master_feature_object.create(cls.document)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def selection(self):
        p = self.part
        return [(p, [p.BottomFace, p.Boundary1, p.Boundary2])]

    def test_inputs_from_the_selection_or_a_net(self):
        p = self.part
        inputs = strategy_study.inputs_from_selection(self.selection())
        self.assertEqual((inputs.face, inputs.boundary_1[1], inputs.boundary_2[1]), ("Face4", ["Edge13"], ["Edge14"]))
        shape, face, b1, b2 = inputs.shapes()
        self.assertTrue(b1.isSame(p.Shape.getElement("Edge13")) and face == "Face4")
        net = guide_curve_net_object.create(self.document, (p, p.Boundary1), (p, p.Boundary2), (p, p.BottomFace))
        self.addCleanup(self.document.removeObject, net.Name)
        from_net = strategy_study.inputs_from_selection([(net, [])])
        self.assertEqual((from_net.part, from_net.face, from_net.boundary_2), (p, "Face4", (p, ["Edge14"])))
        with self.assertRaisesRegex(ValueError, r"Select the bottom face .*\(selected: 1 face, 1 edge\)"):
            strategy_study.inputs_from_selection([(p, ["Face4", "Edge13"])])
        # a studied object deleted since it was picked: said by name of the fix, not a ReferenceError
        box = self.document.addObject("Part::Box", "Gone")
        self.document.recompute()
        gone = strategy_study.StudyInputs(box, "Face1", (box, ["Edge1"]), (box, ["Edge2"]))
        self.assertIs(gone.document(), self.document)
        self.document.removeObject("Gone")
        for call in (gone.document, gone.shapes, gone.describe):
            with self.assertRaisesRegex(ValueError, "no longer in its document"):
                call()

    def test_rows_become_operations_that_compute(self):
        """A planes row and a guide row of a study, applied: the Job's ball end of the study's diameter at the
        row's feed, the angle, a net of the row's K, P and mode, and paths computed."""
        settings = dict(strategy_study.QUICK_FINISHING)
        grid = strategy_study.study_grid(planes="90", k="0.5", p="20", median="with the median", four_step=True,
                                         feeds="3000")
        job = create_job([self.part])
        # headless FreeCAD 0.20 cannot choose among several controllers: the study's one only
        controller = finishing.ball_end_controller(job, settings["tool_diameter"], 3000.0)
        self.assertIs(strategy_study.study_controller(job, settings["tool_diameter"], 3000.0), controller)
        inputs = strategy_study.inputs_from_selection(self.selection())
        planes, _ = strategy_study.create_operation(grid[0], inputs, job, controller, settings)
        guide, net = strategy_study.create_operation(grid[1], inputs, job, controller, settings)
        four_step, four_step_net = strategy_study.create_operation(grid[2], inputs, job, controller, settings)
        self.document.recompute()
        self.assertAlmostEqual(planes.Angle.Value, 90.0)
        self.assertEqual((net.Mode, net.K, net.Step.Value), ("Boundaries to median", 0.5, 20.0))
        self.assertEqual(four_step_net.Mode, strategy_study.FOUR_STEP)
        for op in (planes, guide, four_step):
            self.assertTrue(op.isValid(), op.getStatusString())
            self.assertIs(op.ToolController, controller)
            self.assertAlmostEqual(op.CuspHeight.Value, settings["cusp_height"])
            self.assertGreater(len(op.Path.Commands), 100, op.Label)
        self.assertIn(planes, job.Operations.Group)
        self.assertEqual(net.ChosenDirection.Length > 0, True)
        other = strategy_study.study_controller(job, 6.0, 3000.0)  # another diameter: a new controller
        self.assertIsNot(other, controller)
        self.assertAlmostEqual(other.Tool.Diameter.Value, 6.0)


if __name__ == "__main__":
    unittest.main()
