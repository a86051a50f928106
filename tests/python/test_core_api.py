"""The core API (hsmplanner, no FreeCAD needed) and its use from freecadcmd with real Part shapes."""
import math
import os
import sys
import unittest

import FreeCAD
import Part

import hsmplanner
from helpers import REPO, SYSTEM_PYTHON, run


class ImportWithoutFreeCAD(unittest.TestCase):
    def test_plain_python_imports_the_package_without_freecad(self):
        code = ("import sys, hsmplanner; print(hsmplanner.__version__); "
                "print('FreeCAD' in sys.modules or 'Part' in sys.modules)")
        result = run([SYSTEM_PYTHON, "-c", code], cwd=REPO, env=dict(os.environ, PYTHONPATH="python"))
        self.assertEqual(result.returncode, 0, result.stderr)
        version, freecad_loaded = result.stdout.split()
        self.assertEqual(version, hsmplanner.__version__)
        self.assertEqual(freecad_loaded, "False")

    def test_freecadcmd_finds_the_package_through_the_linked_workbench(self):
        mod_link = os.path.join(FreeCAD.getUserAppDataDir(), "Mod", "HSMPlanner")
        self.assertTrue(os.path.islink(mod_link), "workbench not linked into %s" % mod_link)
        self.assertEqual(os.path.realpath(mod_link), os.path.realpath(REPO))
        self.assertTrue(os.path.realpath(hsmplanner.__file__).startswith(os.path.realpath(REPO)))
        self.assertIn(os.path.join(mod_link, "python"), [os.path.normpath(p) for p in sys.path])


class OneVersion(unittest.TestCase):
    def test_package_xml_cmake_and_the_python_package_give_one_version(self):
        # package.xml is the source: CMake reads it into the core, whose __version__ hsmplanner re-exports
        metadata = FreeCAD.Metadata(os.path.join(REPO, "package.xml"))
        self.assertRegex(metadata.Version, r"^\d+\.\d+\.\d+$")
        self.assertEqual(hsmplanner.__version__, metadata.Version)
        self.assertEqual(hsmplanner._core.__version__, metadata.Version)


class ShapeSummaryOfPartShapes(unittest.TestCase):
    def test_summary_agrees_with_freecad_measures(self):
        part = Part.makeBox(30, 20, 10).cut(Part.makeCylinder(4, 10, FreeCAD.Vector(15, 10, 0)))
        summary = hsmplanner.shape_summary(part)
        self.assertEqual((summary.solids, summary.faces), (1, len(part.Faces)))
        self.assertEqual(summary.edges, len(part.Edges))
        self.assertAlmostEqual(summary.volume, part.Volume, places=6)
        self.assertAlmostEqual(summary.area, part.Area, places=6)
        self.assertAlmostEqual(summary.length, sum(e.Length for e in part.Edges), places=6)
        self.assertTrue(summary.valid)
        xmin, ymin, zmin, xmax, ymax, zmax = summary.bounds
        self.assertAlmostEqual(xmax - xmin, 30.0, places=6)

    def test_summary_accepts_brep_text(self):
        brep = Part.makeSphere(5).exportBrepToString()
        self.assertAlmostEqual(hsmplanner.shape_summary(brep).volume, 4 / 3 * math.pi * 125, places=3)


class CurveSampling(unittest.TestCase):
    def test_points_of_a_circle_edge(self):
        edge = Part.makeCircle(12.0, FreeCAD.Vector(5, 0, 2))
        points = hsmplanner.sample_curve(edge, 73)
        self.assertEqual(points.shape, (73, 3))
        radii = ((points[:, 0] - 5) ** 2 + points[:, 1] ** 2) ** 0.5
        self.assertLess(abs(radii - 12.0).max(), 1e-9)
        self.assertLess(abs(points[:, 2] - 2).max(), 1e-12)

    def test_points_of_a_wire_follow_its_edges_in_order(self):
        wire = Part.makePolygon([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(10, 0, 0), FreeCAD.Vector(10, 10, 0)])
        points = hsmplanner.sample_curve(wire, 5)
        self.assertEqual([tuple(p) for p in points.round(9)],
                         [(0, 0, 0), (5, 0, 0), (10, 0, 0), (10, 5, 0), (10, 10, 0)])


class BadInputGetsAClearError(unittest.TestCase):
    def test_empty_brep_names_the_fix(self):
        with self.assertRaisesRegex(ValueError, "BREP text is empty.*exportBrepToString"):
            hsmplanner.shape_summary("")

    def test_too_few_points(self):
        with self.assertRaisesRegex(ValueError, "sample count is 1"):
            hsmplanner.sample_curve(Part.makeCircle(3), 1)

    def test_not_a_shape(self):
        with self.assertRaisesRegex(TypeError, "expected a FreeCAD Part shape"):
            hsmplanner.sample_curve(42, 10)

    def test_null_shape(self):
        with self.assertRaisesRegex(ValueError, "null"):
            hsmplanner.shape_summary(Part.Shape())

    def test_face_has_no_chain_of_one_edge(self):
        with self.assertRaisesRegex(ValueError, "do not form one connected chain|pieces"):
            disjoint = Part.makeCompound([Part.makeLine((0, 0, 0), (1, 0, 0)), Part.makeLine((5, 0, 0), (6, 0, 0))])
            hsmplanner.sample_curve(disjoint, 10)


if __name__ == "__main__":
    unittest.main()
