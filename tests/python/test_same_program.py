"""The same document gives the same program, whether its part was displayed (triangulated by FreeCAD's 3D
view) or not (freecadcmd): retract heights come from exact bounds; the operation's head comments are valid
G-code whatever its label holds."""
import unittest

import FreeCAD

from hsmplanner.app import finishing, finishing_ops, guide_curve_net_object, master_feature_object
from hsmplanner.app.compat import create_job


def display_like_the_3d_view(document):
    """Triangulates every shape of `document` as FreeCAD's 3D view does when it shows them (coarse)."""
    for obj in document.Objects:
        shape = getattr(obj, "Shape", None)
        if shape is not None and not shape.isNull() and shape.Faces:
            shape.tessellate(0.5)


class SameDocumentSameProgram(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("SameProgram")
        part = master_feature_object.create(cls.document)
        cls.part = part
        net = guide_curve_net_object.create(cls.document, (part, part.Boundary1), (part, part.Boundary2),
                                            (part, part.BottomFace))
        cls.job = create_job([part])
        finishing.ball_end_controller(cls.job, 10.0, 4000.0)
        cls.op = finishing_ops.CreateGuideCurveFinishing("Guide", parentJob=cls.job)
        cls.op.Net = net
        cls.op.CuspHeight = 0.1
        cls.op.Label = "guide K0.5 P20 (study)"
        cls.document.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def recomputed(self):
        for obj in (self.job.Stock, self.op):
            obj.touch()
        self.document.recompute()
        self.assertTrue(self.op.isValid(), self.op.getStatusString())
        return [c.toGCode() for c in self.op.Path.Commands]

    def test_a_displayed_part_gives_the_same_commands(self):
        model = self.job.Model.Group[0]
        loose = model.Shape.BoundBox  # never triangulated: from the B-spline faces' control points
        headless = self.recomputed()
        display_like_the_3d_view(self.document)
        # the case guarded against: FreeCAD's own box of the part moves with the triangulation (10 mm in z)
        self.assertGreater(loose.ZMax - model.Shape.BoundBox.ZMax, 1.0, "the part was triangulated before")
        displayed = self.recomputed()
        self.assertGreater(len(headless), 100)
        self.assertEqual(displayed, headless)
        retracts = {round(c.Parameters["Z"], 6) for c in self.op.Path.Commands if c.Name == "G0" and "Z" in c.Parameters}
        self.assertTrue(retracts, "no retract in the program")

    def test_the_head_comment_stays_valid_g_code_at_each_recompute(self):
        first = [c.toGCode() for c in self.op.Path.Commands[:1]]
        self.assertEqual(first, ["(guide K0.5 P20 [study])"])
        again = self.recomputed()
        self.assertEqual(again[:1], first)
        for line in again:
            if line.startswith("("):
                self.assertEqual(line.count("("), 1, line)
                self.assertEqual(line.count(")"), 1, line)
