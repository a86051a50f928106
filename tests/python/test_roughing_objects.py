"""The FreeCAD layer of 5-axis roughing : the test parts and their stocks, and the Roughing
volume document object (volumes, face classes, partitions; it follows its inputs, switches its display and
survives saving without computing again; bad inputs are one line and the object stays valid)."""
import os
import unittest
from unittest import mock

import FreeCAD
import Part

from hsmplanner import roughing
from hsmplanner.app.roughing import volume as roughing_object, parts as roughing_parts
from hsmplanner.app.roughing.volume import CLASS_NAMES, FACE_CLASSES, SUB_VOLUMES, strategy_label
from helpers import temporary_directory

SLOT_VOLUME = 15360.0  # 16 × 24 × 40 mm, the slot's closed form
SLOT_COUNTS = "crossable 3, facing_crossable 1, not_crossable 2"
RELATIVE = 1e-6


def counting(test_case, name):
    """A mock wrapping hsmplanner.roughing.<name> (what the document object calls), counting its calls."""
    patcher = mock.patch.object(roughing, name, wraps=getattr(roughing, name))
    calls = patcher.start()
    test_case.addCleanup(patcher.stop)
    return calls


class SlotDocument(unittest.TestCase):
    def setUp(self):
        self.document = FreeCAD.newDocument("RoughingSlot")
        self.addCleanup(self.close)
        self.part, self.stock = roughing_parts.create_slanted_slot_block(self.document)

    def close(self):
        if self.document.Name in FreeCAD.listDocuments():
            FreeCAD.closeDocument(self.document.Name)

    def assertRelative(self, value, expected, message=None):
        self.assertAlmostEqual(value, expected, delta=RELATIVE * abs(expected), msg=message)

    def volume(self, **properties):
        obj = roughing_object.create(self.part, **properties)
        self.document.recompute()
        self.assertTrue(obj.isValid(), obj.State)
        self.assertIsNone(obj.Proxy.error)
        return obj


class TestParts(SlotDocument):
    def test_the_slot_block_and_its_stock(self):
        self.assertTrue(self.part.isValid() and self.stock.isValid(), (self.part.State, self.stock.State))
        self.assertEqual((type(self.part.Proxy).__name__, type(self.stock.Proxy).__name__),
                         ("SlantedSlotBlock", "TestPartStock"))
        self.assertIs(self.stock.Part, self.part)
        self.assertIs(roughing_parts.stock_of(self.part), self.stock)
        self.assertRelative(self.stock.Shape.Volume, 80.0 * 40.0 * 30.0)
        self.assertRelative(self.stock.Shape.Volume - self.part.Shape.Volume, SLOT_VOLUME)
        self.assertRelative(self.part.RemovalVolume, SLOT_VOLUME)
        self.assertEqual(self.part.Tilt.Value, 30.0)  # the core's defaults

    def test_the_stock_follows_the_part(self):
        self.part.SlotDepth = 20
        self.part.Placement = FreeCAD.Placement(FreeCAD.Vector(100, 0, 0), FreeCAD.Rotation())
        self.document.recompute()
        self.assertRelative(self.part.RemovalVolume, 16.0 * 20.0 * 40.0)
        self.assertRelative(self.stock.Shape.Volume - self.part.Shape.Volume, 16.0 * 20.0 * 40.0)
        self.assertAlmostEqual(self.stock.Shape.BoundBox.XMin, 100.0, places=9)
        self.assertAlmostEqual(self.part.Shape.BoundBox.XMin, 100.0, places=9)

    def test_bad_parameters_name_the_fix_and_the_document_lives(self):
        self.part.SlotDepth = 40
        self.document.recompute()
        self.assertFalse(self.part.isValid())
        self.assertIn("does not fit in the block", self.part.getStatusString())
        self.assertRelative(self.stock.Shape.Volume, 96000.0)  # the last good stock stays
        self.part.SlotDepth = 24
        self.document.recompute()
        self.assertTrue(self.part.isValid(), self.part.State)

    def test_parameters_are_clamped(self):
        self.part.Tilt = 75
        self.part.Length = -5
        self.assertEqual((self.part.Tilt.Value, self.part.Length.Value), (59.0, 1.0))
        # FreeCAD stores the -5 of a length as 0 before the proxy sees it: the warning says so
        from hsmplanner.app.property_limits import shown_value

        self.assertIn("negative length", shown_value(self.part, "Length", 0.0))
        self.assertEqual(shown_value(self.part, "Tilt", 75.0), "75")

    def test_create_without_a_document(self):
        with mock.patch.object(FreeCAD, "ActiveDocument", None):
            with self.assertRaisesRegex(ValueError, "no document"):
                roughing_parts.create_slanted_slot_block(None)


class RoughingVolumeOfTheSlot(SlotDocument):
    def test_volume_classes_and_s1_sub_volumes(self):
        obj = self.volume(Strategy="S1")
        self.assertIs(obj.Stock, self.stock)  # the test part's own stock by default
        self.assertRelative(obj.Volume, SLOT_VOLUME)
        self.assertRelative(obj.StockVolume - obj.PartVolume, SLOT_VOLUME)
        self.assertEqual((obj.RegionCount, list(obj.FaceClassCounts)), (1, [SLOT_COUNTS]))
        by_face = [CLASS_NAMES[i] for i in obj.VolumeFaceClasses]
        self.assertEqual(sorted(by_face), sorted(["crossable"] * 3 + ["facing_crossable"] + ["not_crossable"] * 2))
        self.assertEqual(obj.SubVolumeCount, 4)
        self.assertEqual(list(obj.SubVolumeSlices), [0, 1, 2, 3])
        self.assertEqual(list(obj.SubVolumeRegions), [1, 1, 1, 1])
        self.assertRelative(sum(obj.SubVolumes), obj.Volume)
        # Face classes: the Shape is the volume, FaceColorIndex its classes face by face
        self.assertEqual(obj.Display, FACE_CLASSES)
        self.assertEqual(len(obj.Shape.Solids), 1)
        self.assertRelative(obj.Shape.Volume, SLOT_VOLUME)
        self.assertEqual(list(obj.FaceColorIndex), list(obj.VolumeFaceClasses))
        self.assertEqual(len(obj.FaceColorIndex), len(obj.Shape.Faces))
        self.assertEqual(obj.SetupDirection, FreeCAD.Vector())

    def test_sub_volumes_display(self):
        obj = self.volume(Strategy="S1", Display=SUB_VOLUMES)
        self.assertEqual(len(obj.Shape.Solids), 4)
        self.assertRelative(obj.Shape.Volume, SLOT_VOLUME)
        self.assertEqual(len(obj.FaceColorIndex), len(obj.Shape.Faces))
        expected = [sub_slice for solid, sub_slice in zip(obj.Shape.Solids, obj.SubVolumeSlices)
                    for _ in solid.Faces]
        self.assertEqual(list(obj.FaceColorIndex), expected)
        for solid, volume in zip(obj.Shape.Solids, obj.SubVolumes):
            self.assertRelative(solid.Volume, volume)

    def test_follows_the_part_after_recompute(self):
        obj = self.volume(Strategy="S1")
        self.part.SlotDepth = 20
        self.document.recompute()
        self.assertTrue(obj.isValid(), obj.State)
        self.assertRelative(obj.Volume, 16.0 * 20.0 * 40.0)
        self.assertRelative(obj.Volume, self.part.RemovalVolume)
        self.assertRelative(sum(obj.SubVolumes), obj.Volume)
        self.assertRelative(obj.Shape.Volume, obj.Volume)

    def test_s3_finds_the_slot_axis_and_s5_follows_the_floor(self):
        obj = self.volume(Strategy="S3")
        direction = obj.SetupDirection
        self.assertAlmostEqual(direction.x, 0.5, delta=0.05)
        self.assertAlmostEqual(direction.z, 0.866, delta=0.05)
        self.assertGreater(obj.SetupReach, 0.95)
        self.assertRelative(sum(obj.SubVolumes), SLOT_VOLUME)
        obj.Strategy = strategy_label("S5")
        self.document.recompute()
        self.assertEqual(obj.SubVolumeCount, 4)
        self.assertRelative(sum(obj.SubVolumes), SLOT_VOLUME)
        self.assertEqual(obj.SetupDirection, FreeCAD.Vector())

    def test_display_touch_and_strategies_do_not_compute_the_volume_again(self):
        obj = self.volume(Strategy="S1")
        volumes, partitions = counting(self, "volume_to_remove"), counting(self, "partition")
        obj.Display = SUB_VOLUMES
        self.document.recompute()
        obj.touch()
        self.document.recompute()
        self.assertEqual((volumes.call_count, partitions.call_count), (0, 0))
        self.assertEqual(len(obj.Shape.Solids), 4)
        obj.Strategy = strategy_label("S5")
        self.document.recompute()
        obj.Strategy = strategy_label("S1")
        self.document.recompute()
        self.assertEqual((volumes.call_count, partitions.call_count), (0, 1))  # S1 was kept in memory

    def test_strategy_none_and_sub_volumes_shows_the_classes(self):
        obj = self.volume(Display=SUB_VOLUMES)
        self.assertEqual((obj.Strategy, obj.SubVolumeCount), (roughing_object.STRATEGY_NONE, 0))
        self.assertEqual(list(obj.FaceColorIndex), list(obj.VolumeFaceClasses))
        self.assertIn(roughing_object.DISPLAY_FALLBACK, obj.Warnings)

    def test_saved_and_reopened_without_computing(self):
        obj = self.volume(Strategy="S1", Display=SUB_VOLUMES)
        saved = {name: list(getattr(obj, name)) for name in ("FaceColorIndex", "VolumeFaceClasses", "SubVolumes",
                                                             "SubVolumeSlices", "FaceClassCounts", "RegionVolumes")}
        volume, name, part_name, stock_name = obj.Volume, obj.Name, self.part.Name, self.stock.Name
        path = os.path.join(temporary_directory(self), "roughing.FCStd")
        self.document.saveAs(path)
        FreeCAD.closeDocument(self.document.Name)
        self.document = FreeCAD.openDocument(path)
        restored = self.document.getObject(name)
        part = self.document.getObject(part_name)
        stock = self.document.getObject(stock_name)
        self.assertEqual([type(o.Proxy).__name__ for o in (restored, part, stock)],
                         ["RoughingVolume", "SlantedSlotBlock", "TestPartStock"])
        self.assertEqual((restored.Part, restored.Stock, restored.Display), (part, stock, SUB_VOLUMES))
        self.assertEqual({name: list(getattr(restored, name)) for name in saved}, saved)
        self.assertEqual(restored.Volume, volume)
        self.assertEqual(len(restored.Shape.Faces), len(restored.FaceColorIndex))  # what the view colours
        self.assertEqual(len(restored.Shape.Solids), 4)
        volumes, partitions = counting(self, "volume_to_remove"), counting(self, "partition")
        restored.touch()
        self.document.recompute()
        restored.Display = FACE_CLASSES
        self.document.recompute()
        self.assertEqual((volumes.call_count, partitions.call_count), (0, 0))
        self.assertEqual(list(restored.FaceColorIndex), saved["VolumeFaceClasses"])
        part.SlotDepth = 20
        self.document.recompute()
        self.assertEqual(volumes.call_count, 1)
        self.assertRelative(restored.Volume, 12800.0)

    def test_bad_inputs_are_one_line_and_the_object_stays_valid(self):
        obj = self.volume(Strategy="S1")
        box = self.document.addObject("Part::Feature", "SmallBox")
        box.Shape = Part.makeBox(10, 10, 10)
        sheet = self.document.addObject("Part::Feature", "Sheet")
        sheet.Shape = Part.makePlane(200, 200, FreeCAD.Vector(-50, -50, 10))
        # Bad links leave no result; a strategy, step or region this volume cannot take leaves the volume to
        # remove in the view (its faces by class), with no sub-volumes.
        cases = [(dict(Part=None), "Part is not set: link the part", False),
                 (dict(Part=self.part, Stock=self.part), "Part and Stock are both", False),
                 (dict(Stock=box), "the stock does not contain the part", False),
                 (dict(Stock=self.stock, Part=sheet), "holds no solid", False),
                 (dict(Part=self.part, Step=400.0), "larger than the volume's extent", True),
                 (dict(Step=8.0, Strategy=strategy_label("S2")), "S2 needs a cylindrical crossable face.*use S1, S3, "
                                                                 "S4 or S5", True),
                 (dict(Strategy=strategy_label("S1"), Region=2), "Region 2: the volume to remove has 1 region", True)]
        for properties, message, keeps_volume in cases:
            for key, value in properties.items():
                setattr(obj, key, value)
            self.document.recompute()
            self.assertTrue(obj.isValid(), "%s: %s" % (message, obj.State))
            self.assertRegex(obj.Proxy.error or "", message)
            self.assertEqual(obj.SubVolumeCount, 0, message)
            if keeps_volume:
                self.assertRelative(obj.Volume, SLOT_VOLUME)
                self.assertEqual(len(obj.Shape.Solids), 1, message)
                self.assertEqual(len(obj.FaceColorIndex), len(obj.Shape.Faces), message)
            else:
                self.assertEqual((obj.Volume, obj.Shape.isNull(), list(obj.FaceColorIndex)), (0.0, True, []), message)
        obj.Region = 1
        self.document.recompute()
        self.assertIsNone(obj.Proxy.error)
        self.assertRelative(obj.Volume, SLOT_VOLUME)

    def test_ranges_are_clamped(self):
        obj = roughing_object.create(self.part, recompute=False)
        obj.Step, obj.Region, obj.SetupResolution, obj.SetupGrid = 0.0, -1, 0.0, 1e6
        self.assertEqual((obj.Step.Value, obj.Region, obj.SetupResolution.Value, obj.SetupGrid.Value),
                         (0.5, 0, 0.5, 50.0))
        with self.assertRaisesRegex(ValueError, "no property 'Tool'"):
            roughing_object.create(self.part, Tool=3)

    def test_two_solids_in_any_order(self):
        self.assertEqual(roughing_object.part_and_stock(self.stock, self.part), (self.part, self.stock))
        box = self.document.addObject("Part::Feature", "Blank")
        box.Shape = Part.makeBox(100, 100, 100, FreeCAD.Vector(-10, -10, -10))
        self.assertEqual(roughing_object.part_and_stock(box, self.part), (self.part, box))


class JobStock(SlotDocument):
    def test_the_stock_of_a_job(self):
        from hsmplanner.app.compat import create_job

        plain = self.document.addObject("Part::Feature", "Block")
        plain.Shape = self.part.Shape.copy()
        job = create_job([plain])
        self.document.recompute()
        self.assertIs(roughing_object.default_stock(plain), job.Stock)
        obj = roughing_object.create(plain)
        self.document.recompute()
        self.assertIs(obj.Stock, job.Stock)
        self.assertIsNone(obj.Proxy.error)
        self.assertRelative(obj.StockVolume, job.Stock.Shape.Volume)
        self.assertRelative(obj.Volume, job.Stock.Shape.Volume - plain.Shape.Volume)
        obj.Stock = job  # the Job itself stands for its stock
        self.document.recompute()
        self.assertIsNone(obj.Proxy.error)
        self.assertRelative(obj.StockVolume, job.Stock.Shape.Volume)


class ImpellerDocument(unittest.TestCase):
    """One impeller for the class (building it and its volume to remove take seconds)."""

    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("RoughingImpeller")
        cls.part, cls.stock = roughing_parts.create_impeller(cls.document)
        cls.obj = roughing_object.create(cls.part)
        cls.document.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def test_seven_channels_of_six_surfaces_3_1_2(self):
        obj = self.obj
        self.assertIsNone(obj.Proxy.error)
        self.assertEqual(type(self.part.Proxy).__name__, "Impeller")
        self.assertEqual(obj.RegionCount, 7)
        self.assertEqual(list(obj.FaceClassCounts), [SLOT_COUNTS] * 7)
        self.assertAlmostEqual(obj.Volume, obj.StockVolume - obj.PartVolume, delta=RELATIVE * obj.Volume)
        self.assertAlmostEqual(sum(obj.RegionVolumes), obj.Volume, delta=RELATIVE * obj.Volume)
        for volume in obj.RegionVolumes:
            self.assertAlmostEqual(volume, obj.Volume / 7.0, delta=0.01 * volume)
        self.assertEqual(len(obj.Shape.Solids), 7)
        self.assertEqual(len(obj.FaceColorIndex), len(obj.Shape.Faces))

    def test_s5_partition_of_the_largest_channel(self):
        volumes = counting(self, "volume_to_remove")
        self.obj.Strategy = strategy_label("S5")
        self.document.recompute()
        self.assertIsNone(self.obj.Proxy.error)
        self.assertEqual(volumes.call_count, 0)  # the volume is kept in memory
        self.assertGreaterEqual(self.obj.SubVolumeCount, 2)
        self.assertEqual(set(self.obj.SubVolumeRegions), {1})
        self.assertAlmostEqual(sum(self.obj.SubVolumes), self.obj.RegionVolumes[0],
                               delta=RELATIVE * self.obj.RegionVolumes[0])

    def test_impeller_parameters_are_clamped(self):
        self.part.Blades = 30
        self.assertEqual(self.part.Blades, 24)
        self.part.Blades = 7
        self.part.purgeTouched()


if __name__ == "__main__":
    unittest.main()
