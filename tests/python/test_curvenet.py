"""Curve nets from Python and freecadcmd: the API on real FreeCAD edges, the document object, bad input."""
import math
import os
import unittest

import FreeCAD
import numpy as np
import Part

import hsmplanner
from hsmplanner.app import guide_curve_net_object, master_feature_object
from hsmplanner.app.guide_curve_net import MODES, NetParameters, build_guide_curve_net
from hsmplanner.app.master_feature import make_master_bottom_feature
from helpers import temporary_directory

FEATURE = make_master_bottom_feature()
B1 = FEATURE.shape.getElement(FEATURE.boundary_1)
B2 = FEATURE.shape.getElement(FEATURE.boundary_2)
BOTTOM = FEATURE.shape.getElement(FEATURE.bottom_face)


def edge_ends(edges):
    """Start (3), end (3) and length of each edge, one row each: what tells the curves of a net apart, and
    their order."""
    return np.array([tuple(e.valueAt(e.FirstParameter)) + tuple(e.valueAt(e.LastParameter)) + (e.Length,)
                     for e in edges])


def same_ends(edge, other, tolerance=1e-6):
    """The two edges join the same two points (either way round)."""
    a = [edge.valueAt(edge.FirstParameter), edge.valueAt(edge.LastParameter)]
    b = [other.valueAt(other.FirstParameter), other.valueAt(other.LastParameter)]
    return ((a[0] - b[0]).Length < tolerance and (a[1] - b[1]).Length < tolerance) or \
        ((a[0] - b[1]).Length < tolerance and (a[1] - b[0]).Length < tolerance)


def line_points(y, z=0.0, length=100.0, n=11):
    x = np.linspace(0.0, length, n)
    return np.column_stack([x, np.full_like(x, y), np.full_like(x, z)])


class IntermediateCurveApi(unittest.TestCase):
    def test_point_arrays_and_edges_give_the_same_curve(self):
        from_points = hsmplanner.intermediate_curve(line_points(0), line_points(20), 0.25, 5.0)
        edges = [Part.makeLine((0, y, 0), (100, y, 0)) for y in (0, 20)]
        from_edges = hsmplanner.intermediate_curve(edges[0], edges[1], 0.25, 5.0)
        np.testing.assert_allclose(from_points.points, from_edges.points, atol=1e-9)
        np.testing.assert_allclose(from_points.sample(5)[:, 1], 5.0, atol=1e-6)

    def test_curve_comes_back_as_a_freecad_edge(self):
        curve = hsmplanner.intermediate_curve(B1, B2, 0.5, 5.0, face=BOTTOM)
        shape = Part.Shape()
        shape.importBrepFromString(curve.to_brep())
        edge = shape.Edges[0]
        self.assertEqual(curve.degree, 5)
        self.assertIsInstance(edge.Curve, Part.BSplineCurve)
        self.assertEqual(edge.Curve.Degree, 5)
        # On the bottom face: every sample is within the fit tolerance of it.
        distances = [BOTTOM.distToShape(Part.Vertex(*p))[0] for p in curve.sample(40)]
        self.assertLess(max(distances), 0.011)

    def test_direction_accepts_freecad_vectors(self):
        curve = hsmplanner.intermediate_curve(line_points(0), line_points(20), 0.5, 10.0,
                                              direction=FreeCAD.Vector(1, 0, 0))
        self.assertEqual(len(curve.points), 11)


class CurveNetApi(unittest.TestCase):
    def test_tables_1_and_2_on_the_master_feature(self):
        counts = {(mode, k): len(hsmplanner.curve_net(B1, B2, k, 5.0, mode=mode, face=BOTTOM).curves) - 2
                  for mode, k in [("b1_to_b2", 0.25), ("b1_to_b2", 0.75), ("b2_to_b1", 0.25),
                                  ("boundaries_to_median", 0.25), ("boundaries_to_median", 0.5),
                                  ("boundaries_to_median", 0.75)]}
        self.assertEqual(counts, {("b1_to_b2", 0.25): 9, ("b1_to_b2", 0.75): 1, ("b2_to_b1", 0.25): 9,
                                  ("boundaries_to_median", 0.25): 13, ("boundaries_to_median", 0.5): 5,
                                  ("boundaries_to_median", 0.75): 3})

    def test_composed_areas_grow_by_one_curve_per_net(self):
        net = hsmplanner.curve_net(B1, B2, 0.5, 5.0, mode="median_to_boundaries")
        sizes = [len(ma) for ma in net.composed_areas()]
        self.assertEqual(sizes, [2, 4, 6])
        self.assertEqual([c.label for c in net.curves], ["B1", "C1.2", "C1.1", "Cmed", "C2.1", "C2.2", "B2"])

    def test_guidance_curves_report(self):
        net, report = hsmplanner.guidance_curves(B1, B2, face=BOTTOM)
        self.assertEqual([c.label for c in net.curves], ["B1", "C1", "Cmed", "C2", "B2"])
        self.assertEqual((report.half1.start, report.half2.start), ("Cmed", "B2"))
        regions = hsmplanner.area_regions(net, BOTTOM)
        self.assertAlmostEqual(sum(r[3] for r in regions), BOTTOM.Area, delta=1e-3 * BOTTOM.Area)


class BadInput(unittest.TestCase):
    def test_each_bad_input_names_itself(self):
        cases = [
            (dict(k=1.0), ValueError, r"K = 1 is outside \]0,1\["),
            (dict(k=0.0), ValueError, r"K = 0 is outside"),
            (dict(step=0.0), ValueError, "step P = 0 mm must be at least 0.01 mm"),
            (dict(step=500.0), ValueError, "longer than the common extent"),
            (dict(direction=(0, 0, 1)), ValueError, "along the tool axis"),
            (dict(direction=(1, 0)), ValueError, "3 components"),
            (dict(mode="diagonal"), ValueError, "mode 'diagonal' is unknown"),
        ]
        for overrides, error, message in cases:
            arguments = dict(k=0.5, step=5.0, mode="b1_to_b2")
            arguments.update(overrides)
            with self.subTest(overrides=overrides), self.assertRaisesRegex(error, message):
                hsmplanner.curve_net(B1, B2, **arguments)

    def test_degenerate_curves(self):
        with self.assertRaisesRegex(ValueError, "distinct point"):
            hsmplanner.curve_net(np.zeros((4, 3)), line_points(10), 0.5, 5.0)
        with self.assertRaisesRegex(ValueError, "cross near"):
            crossing = np.column_stack([np.linspace(0, 100, 11), np.linspace(-10, 30, 11), np.zeros(11)])
            hsmplanner.curve_net(line_points(10), crossing, 0.5, 5.0)
        with self.assertRaisesRegex(ValueError, "do not overlap"):
            far = line_points(10) + np.array([200.0, 0, 0])
            hsmplanner.curve_net(line_points(0), far, 0.5, 5.0)
        with self.assertRaisesRegex(TypeError, "b1 must be a FreeCAD edge"):
            hsmplanner.curve_net("not a curve".split(), line_points(0), 0.5, 5.0)
        with self.assertRaisesRegex(ValueError, "expected one face"):
            hsmplanner.curve_net(B1, B2, 0.5, 5.0, face=FEATURE.shape)
        with self.assertRaisesRegex(ValueError, "zero length|distinct end points|no usable edge"):
            hsmplanner.curve_net(Part.Edge(Part.LineSegment(FreeCAD.Vector(), FreeCAD.Vector(1e-9, 0, 0))),
                                 line_points(10), 0.5, 5.0)

    def test_fuzzed_parameters_never_crash(self):
        rng = np.random.default_rng(7)
        for _ in range(200):
            k = float(rng.choice([rng.uniform(-1, 2), 0.0, 1.0, float("nan"), float("inf")]))
            step = float(rng.choice([rng.uniform(-10, 300), 0.0, float("nan"), 1e-3]))
            gap = float(rng.uniform(-1, 20))
            try:
                net = hsmplanner.curve_net(line_points(0), line_points(rng.uniform(-30, 30)), k, step, min_gap=gap)
            except ValueError:
                continue
            self.assertTrue(0 < k < 1 and step > 0 and gap >= 0)
            self.assertGreaterEqual(len(net.curves), 2)


class GuideCurveNetObject(unittest.TestCase):
    def setUp(self):
        self.document = FreeCAD.newDocument("GuideNetTest")
        self.addCleanup(lambda: [FreeCAD.closeDocument(n) for n in list(FreeCAD.listDocuments())])
        self.part = master_feature_object.create(self.document)

    def make(self, **values):
        p = self.part
        return guide_curve_net_object.create(self.document, (p, p.Boundary1), (p, p.Boundary2), (p, p.BottomFace),
                                             **values)

    def test_four_step_net_with_its_areas(self):
        net = self.make()
        self.assertTrue(net.isValid(), net.State)
        self.assertEqual(net.Curves, ["B1", "C1", "Cmed", "C2", "B2"])
        self.assertEqual(len(net.AreaSurfaces), 4)
        self.assertAlmostEqual(sum(net.AreaSurfaces), self.part.Shape.getElement(self.part.BottomFace).Area,
                               delta=1.0)
        self.assertEqual(len(net.Shape.Faces), len(net.FaceAreas))
        self.assertEqual(net.ComposedAreas[0], "MA1: B1|Cmed, Cmed|B2")
        self.assertIn("planes", net.PlaneSpacing)

    def test_follows_its_properties_and_the_part(self):
        net = self.make(Mode="Boundaries to median", K=0.25)
        self.assertEqual(len(net.Curves), 15)
        net.K = 0.75
        self.document.recompute()
        self.assertEqual(len(net.Curves), 5)
        self.part.Length = 120
        self.document.recompute()
        self.assertAlmostEqual(guide_curve_net_object.net_curve_edges(net)[-1].BoundBox.XMax, 120.0, delta=0.05)

    def test_values_outside_the_panel_ranges_are_clamped_at_the_door(self):
        net = self.make(Mode="Boundary 1 to boundary 2")
        for prop, bad, clamped in (("K", 1.5, 0.99), ("K", -2.0, 0.01), ("Step", 0.003, 0.5), ("MinGap", 0.0, 0.01),
                                   ("KMedian", float("nan"), 0.01), ("FitTolerance", 1e-9, 0.0001)):
            with self.subTest(prop=prop, value=bad):
                setattr(net, prop, bad)
                value = getattr(net, prop)
                self.assertAlmostEqual(getattr(value, "Value", value), clamped)
        net.K, net.Step = 0.5, 5.0
        self.document.recompute()
        self.assertTrue(net.isValid())

    def test_an_error_in_the_core_marks_the_object_and_keeps_the_document(self):
        net = self.make(Mode="Boundary 1 to boundary 2")
        net.Step = 40.0
        net.Direction = FreeCAD.Vector(0, 0, 1)  # along the tool axis: the core refuses it
        self.document.recompute()
        self.assertIn("Invalid", net.State)
        net.Direction = FreeCAD.Vector(0, 0, 0)
        self.document.recompute()
        self.assertTrue(net.isValid())

    def test_missing_boundary_is_reported(self):
        net = guide_curve_net_object.create(self.document)
        net.Boundary1 = (self.part, self.part.Boundary1)
        self.document.recompute()
        self.assertIn("Invalid", net.State)
        with self.assertRaisesRegex(ValueError, "Boundary2 is not set"):
            guide_curve_net_object.GuideCurveNet.inputs(net)

    def test_curves_are_their_own_property_from_b1_to_b2(self):
        net = self.make()
        edges = guide_curve_net_object.net_curve_edges(net)
        self.assertEqual(len(edges), len(net.Curves))
        self.assertEqual(net.getEditorMode("CurveShapes"), ["ReadOnly"])
        part = self.part.Shape
        self.assertTrue(same_ends(edges[0], part.getElement(self.part.Boundary1)))
        self.assertTrue(same_ends(edges[-1], part.getElement(self.part.Boundary2)))
        # the same edges as the displayed shape's curves, whatever their place in it
        shown = edge_ends(net.Shape.Edges)
        for row in edge_ends(edges):
            self.assertTrue(np.any(np.all(np.abs(shown - row) < 1e-9, axis=1)), row)

    def test_a_net_not_computed_has_no_curves_to_give(self):
        net = guide_curve_net_object.create(self.document)
        with self.assertRaisesRegex(ValueError, "has no curves: recompute it"):
            guide_curve_net_object.net_curve_edges(net)

    def test_saves_and_restores(self):
        net = self.make(K=0.7, Step=4)
        curves = edge_ends(guide_curve_net_object.net_curve_edges(net))
        path = os.path.join(temporary_directory(self), "net.FCStd")
        self.document.saveAs(path)
        FreeCAD.closeDocument(self.document.Name)
        document = FreeCAD.openDocument(path)
        restored = document.getObject(net.Name if False else "GuideCurveNet")
        self.assertEqual(type(restored.Proxy).__name__, "GuideCurveNet")
        self.assertAlmostEqual(restored.K, 0.7)
        # the curves come back as they were saved, B1 → B2, before any recompute
        np.testing.assert_allclose(edge_ends(guide_curve_net_object.net_curve_edges(restored)), curves, atol=1e-9)
        restored.touch()
        document.recompute()
        self.assertTrue(restored.isValid(), restored.State)
        self.assertEqual(restored.Curves, ["B1", "C1", "Cmed", "C2", "B2"])

    def test_a_document_saved_before_curve_shapes_gets_them_on_opening(self):
        net = self.make()
        curves = edge_ends(guide_curve_net_object.net_curve_edges(net))
        net.removeProperty("CurveShapes")  # as nets were saved before it existed
        path = os.path.join(temporary_directory(self), "old.FCStd")
        self.document.saveAs(path)
        FreeCAD.closeDocument(self.document.Name)
        restored = FreeCAD.openDocument(path).getObject("GuideCurveNet")
        self.assertIn("CurveShapes", restored.PropertiesList)
        np.testing.assert_allclose(edge_ends(guide_curve_net_object.net_curve_edges(restored)), curves, atol=1e-9)

    def test_unknown_property_is_refused(self):
        with self.assertRaisesRegex(ValueError, "no property 'Kay'"):
            self.make(Kay=0.3)


class PureFunction(unittest.TestCase):
    def test_every_mode_builds(self):
        for mode in MODES:
            with self.subTest(mode=mode):
                result = build_guide_curve_net(B1, B2, BOTTOM, NetParameters(mode=mode, k=0.5), with_regions=False)
                self.assertGreaterEqual(len(result.edges), 3)
                self.assertEqual(result.regions, [])
        with self.assertRaisesRegex(ValueError, "mode 'x' is unknown"):
            build_guide_curve_net(B1, B2, None, NetParameters(mode="x"))


if __name__ == "__main__":
    unittest.main()
