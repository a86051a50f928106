"""Machining direction: the API on the paper's two cases and on the master feature, bad inputs, the
validation by simulation, and the "Machining direction" document object in a real document with a Job."""
import math
import os
import shutil
import unittest

import FreeCAD
import numpy as np
import Part

import hsmplanner
from hsmplanner import direction
from hsmplanner.app import direction_object, finishing, finishing_ops, master_feature_object, surfaces
from hsmplanner.app.direction_object import FEED_FROM
from hsmplanner.app.compat import create_job
from hsmplanner.app.master_feature import make_master_bottom_feature
from helpers import temporary_directory

CASE1 = dict(tool_diameter=10.0, scallop=0.01, spindle_rpm=18000.0, teeth=4, acceleration_m_s2=3.0, machine=None,
             grid=21)
SWITCH_MM_MIN = math.sqrt((10.0 + 5.0) * 3000.0) * 60.0  # √((R + Ro)·a): the transverse direction loses no feed


class CaseOne(unittest.TestCase):
    """The top of a cylinder R10 about Y, Ø10 ball, Sz 0.01 mm, a_max 3 m/s²."""

    face = surfaces.cylinder_top()

    def test_transverse_below_the_switching_feed(self):
        for feed in (3000.0, 0.98 * SWITCH_MM_MIN):
            result = hsmplanner.optimal_direction(self.face, feed_mm_min=feed, **CASE1)
            self.assertEqual(result.angle_deg, 0.0, feed)
            self.assertAlmostEqual(result.alpha, 1.0, places=9)
            self.assertIn(0.0, list(result.acceptable))
            self.assertNotIn(90.0, list(result.acceptable))

    def test_towards_the_axis_above_it(self):
        previous = 0.0
        for feed in (1.1 * SWITCH_MM_MIN, 20000.0, 30000.0):
            result = hsmplanner.optimal_direction(self.face, feed_mm_min=feed, **CASE1)
            self.assertGreater(result.angle_deg, previous, feed)
            self.assertLessEqual(result.angle_deg, 90.0)
            previous = result.angle_deg
        self.assertIn(90.0, list(result.acceptable))  # at 30 m/min the beams hold the axis, not the transverse
        self.assertNotIn(0.0, list(result.acceptable))

    def test_feed_scan_rows(self):
        rows = direction.directions_over_feeds(self.face, [4000.0, 30000.0], **CASE1)
        self.assertEqual([row[0] for row in rows], [4000.0, 30000.0])
        self.assertEqual(rows[0][1], 0.0)
        self.assertGreater(rows[1][1], 45.0)


class Api(unittest.TestCase):
    def test_master_bottom_face(self):
        feature = make_master_bottom_feature()
        face = feature.shape.getElement(feature.bottom_face)
        result = hsmplanner.optimal_direction(face, tool_diameter=4.0, scallop=0.01, feed_mm_min=4000.0)
        self.assertTrue(0.0 <= result.angle_deg < 180.0)
        self.assertTrue(0.0 < result.alpha <= 1.0)
        self.assertGreater(len(result.points), 1000)
        self.assertEqual(len(result.best_angle_deg), len(result.points))
        times = np.asarray(result.predicted_time_s)
        self.assertEqual(len(times), 180)
        self.assertAlmostEqual(times.min(), times[int(result.fastest_angle_deg)], places=9)
        self.assertGreater(times.max(), 1.05 * times.min())  # the direction matters on this face

    def test_feed_per_tooth_is_fz_z_n(self):
        face = surfaces.valleys(grid=21)
        by_tooth = hsmplanner.optimal_direction(face, feed_per_tooth=0.2, spindle_rpm=15000.0, teeth=2, grid=20)
        by_feed = hsmplanner.optimal_direction(face, feed_mm_min=6000.0, spindle_rpm=15000.0, teeth=2, grid=20)
        self.assertEqual(list(by_tooth.rate), list(by_feed.rate))

    def test_flat_face_ties(self):
        result = hsmplanner.optimal_direction(Part.makePlane(50, 50), feed_mm_min=6000.0, grid=10)
        self.assertTrue(result.all_tie)
        self.assertEqual(len(result.acceptable), 180)
        self.assertTrue(any("flat face" in w for w in result.warnings))

    def test_bad_inputs_name_themselves(self):
        wall = Part.makePlane(50, 20, FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 1, 0))
        with self.assertRaisesRegex(ValueError, "vertical or undercut"):
            hsmplanner.optimal_direction(wall, feed_mm_min=6000.0)
        flat = Part.makePlane(50, 50)
        with self.assertRaisesRegex(ValueError, "too small"):
            hsmplanner.optimal_direction(flat, scallop=0.0001, feed_mm_min=6000.0)
        with self.assertRaisesRegex(ValueError, "feed"):
            hsmplanner.optimal_direction(flat)
        with self.assertRaisesRegex(ValueError, "1° or finer"):
            hsmplanner.optimal_direction(flat, feed_mm_min=6000.0, angle_step=2.0)
        with self.assertRaisesRegex(ValueError, "machine"):
            hsmplanner.optimal_direction(flat, feed_mm_min=6000.0, machine="no-such-machine")
        with self.assertRaisesRegex(ValueError, "acceleration"):
            hsmplanner.optimal_direction(flat, feed_mm_min=6000.0, machine=None)

    def test_ranges_read_through_zero(self):
        self.assertEqual(direction.angle_ranges(list(range(0, 28)) + list(range(153, 180))), [(153.0, 27.0)])
        self.assertEqual(direction.format_ranges([10, 11, 12, 50]), "10°–12°, 50°")
        self.assertEqual(direction.format_ranges([]), "")


class Validation(unittest.TestCase):
    def test_simulated_planes(self):
        face = surfaces.valleys(size=40.0, height=6.0, grid=21)
        rows = hsmplanner.simulated_directions(face, "Face1", [0, 90], tool_diameter=10.0, feed_mm_min=6000.0)
        self.assertEqual([row["angle_deg"] for row in rows], [0.0, 90.0])
        for row in rows:
            self.assertGreater(row["passes"], 40)
            self.assertGreater(row["simulated_s"], row["length_over_feed_s"])  # the machine never beats F
        self.assertIs(direction.fastest(rows), min(rows, key=lambda r: r["simulated_s"]))


class DocumentObject(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("Direction")
        cls.part = master_feature_object.create(cls.document)
        cls.job = create_job([cls.part])
        finishing.ball_end_controller(cls.job, 4.0, 4000.0)
        cls.planes = finishing_ops.CreateParallelPlaneFinishing("Planes", parentJob=cls.job)
        cls.planes.Face = (cls.part, cls.part.BottomFace)
        cls.analysis = direction_object.create((cls.part, cls.part.BottomFace), ToolDiameter=4.0, Feed=4000.0,
                                               Grid=30)
        cls.document.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def test_computes(self):
        a = self.analysis
        self.assertTrue(a.isValid(), a.State)
        self.assertEqual(a.ChosenAngle.Value, a.OptimalAngle.Value)  # Choice: directional beams
        self.assertGreater(a.PointCount, 500)
        self.assertIn(a.OptimalAngle.Value, list(a.AcceptableAngles))
        self.assertTrue(a.AcceptableRanges)
        self.assertGreater(a.PredictedTime, 0.0)

    def test_apply_to_parallel_plane_finishing(self):
        angle = direction_object.apply_to_operation(self.analysis, self.planes)
        self.assertEqual(angle, self.analysis.ChosenAngle.Value)
        self.assertAlmostEqual(self.planes.Angle.Value, self.analysis.ChosenAngle.Value)
        self.assertTrue(self.planes.isValid(), self.planes.State)
        self.assertGreater(self.planes.Passes, 50)
        with self.assertRaisesRegex(ValueError, "not a Parallel plane finishing"):
            direction_object.apply_to_operation(self.analysis, self.part)

    def test_choices(self):
        a = direction_object.create((self.part, self.part.BottomFace), ToolDiameter=4.0, Feed=4000.0, Grid=20,
                                    Choice="Least predicted time")
        self.addCleanup(self.document.removeObject, a.Name)
        self.assertEqual(a.ChosenAngle.Value, a.LeastTimeAngle.Value)
        a.Choice, a.ValidationStep = "Fastest simulated", 90.0
        self.document.recompute()
        self.assertTrue(a.isValid(), a.State)
        self.assertEqual(list(a.ValidationAngles), [0.0, 90.0, 180.0])
        fastest = min(zip(a.ValidationTimes, a.ValidationAngles))[1]
        self.assertEqual(a.ChosenAngle.Value, fastest)

    def test_bad_inputs_leave_it_invalid_with_a_message(self):
        a = direction_object.create(document=self.document, ToolDiameter=4.0)
        self.addCleanup(self.document.removeObject, a.Name)
        a.Teeth, a.Feed, a.Grid = 0, 0.0, 100000  # outside the panel's ranges: clamped at the door
        self.assertEqual((a.Teeth, a.Feed, a.Grid), (1, 1.0, 500))
        a.Teeth, a.Feed, a.Grid = 2, 4000.0, 50
        cases = [({}, "no face"),
                 (dict(Face=(self.part, self.part.BottomFace), FeedFrom=FEED_FROM[1], FeedPerTooth=5.0),
                  "too small for fz"),
                 (dict(FeedFrom=FEED_FROM[0], Machine=direction_object.ACCELERATION_ONLY, Choice="Fastest simulated"),
                  "choose a Machine"),
                 (dict(Machine="mikron-ucp710-840d", Choice="Directional beams", ScanFrom=5000.0, ScanTo=1000.0),
                  "ScanFrom < ScanTo")]
        for properties, message in cases:
            for key, value in properties.items():
                setattr(a, key, value)
            with self.assertRaisesRegex(ValueError, message):
                a.Proxy.run(a)
            self.document.recompute()  # reported on one line, as FreeCAD's CAM operations do: no traceback
            self.assertRegex(a.Proxy.error, message)
            self.assertEqual((a.PointCount, a.Proxy.ensure_result(a)), (0, None), message)
        with self.assertRaisesRegex(ValueError, "no property"):
            direction_object.create(document=self.document, Diameter=4.0)

    def test_saved_and_restored(self):
        folder = temporary_directory(self)
        path = os.path.join(folder, "direction.FCStd")
        self.document.saveAs(path)
        shutil.copy(path, os.path.join(folder, "copy.FCStd"))  # the saved file itself is this open document
        copy = FreeCAD.openDocument(os.path.join(folder, "copy.FCStd"))
        self.addCleanup(FreeCAD.closeDocument, copy.Name)
        restored = copy.getObject(self.analysis.Name)
        self.assertEqual(type(restored.Proxy).__name__, "MachiningDirection")
        self.assertEqual(restored.OptimalAngle.Value, self.analysis.OptimalAngle.Value)
        self.assertIsNone(restored.Proxy.result)  # not saved: rebuilt on demand
        result = restored.Proxy.ensure_result(restored)
        self.assertEqual(result.angle_deg, self.analysis.OptimalAngle.Value)


if __name__ == "__main__":
    unittest.main()


class DefaultsFromTheJob(unittest.TestCase):
    def test_the_analysis_takes_the_jobs_ball_end_tool_and_feeds(self):
        from hsmplanner.app.compat import create_job

        document = FreeCAD.newDocument("DirectionDefaults")
        self.addCleanup(FreeCAD.closeDocument, document.Name)
        part = master_feature_object.create(document)
        job = create_job([part])
        finishing.ball_end_controller(job, 4.0, 4000.0, spindle_rpm=18000)
        analysis = direction_object.create(document=document)
        self.assertAlmostEqual(analysis.ToolDiameter.Value, 4.0)
        self.assertAlmostEqual(analysis.Feed, 4000.0)
        self.assertAlmostEqual(analysis.SpindleSpeed, 18000.0)
        given = direction_object.create(document=document, ToolDiameter=6.0)
        self.assertAlmostEqual(given.ToolDiameter.Value, 6.0)  # what the user gives wins
