"""The Path (0.20) / CAM (1.x) compatibility module picks the right names and modules."""
import sys
import types
import unittest
from unittest import mock

from hsmplanner.app import compat


class RunningFreeCAD(unittest.TestCase):
    def test_names_on_this_freecad(self):
        era_1x = compat.freecad_version() >= (1, 0)
        self.assertEqual(compat.cam_command_name("Job"), "CAM_Job" if era_1x else "Path_Job")
        self.assertEqual(compat.cam_workbench_name(), "CAMWorkbench" if era_1x else "PathWorkbench")

    def test_modules_resolve_to_real_path_classes(self):
        self.assertTrue(hasattr(compat.cam_module("op"), "ObjectOp"))
        self.assertTrue(hasattr(compat.cam_module("job"), "ObjectJob"))
        self.assertTrue(hasattr(compat.cam_module("tool_controller"), "Create"))
        self.assertTrue(hasattr(compat.post_module("linuxcnc"), "export"))

    def test_unknown_role_and_post_are_refused_by_name(self):
        with self.assertRaisesRegex(ValueError, "unknown Path/CAM module role 'nope'"):
            compat.cam_module("nope")
        with self.assertRaisesRegex(ImportError, "no post-processor named 'nope'"):
            compat.post_module("nope")


class FreeCAD1x(unittest.TestCase):
    """FreeCAD 1.x seen through fakes: version 1.0 and Path.Op.Base present."""

    def test_year_numbered_releases_are_later_than_1_1(self):
        """FreeCAD numbers its releases by year after 1.1 (26.3 is the next): every version check holds for it."""
        from hsmplanner.gui import colors

        for reported, expected in ((["26", "3", "0", ""], (26, 3)), (["26", "3dev", "", ""], (26, 3)),
                                   (["1", "1", "3", ""], (1, 1))):
            with mock.patch.object(compat.FreeCAD, "Version", return_value=reported):
                self.assertEqual(compat.freecad_version(), expected)
                self.assertGreaterEqual(compat.freecad_version(), (1, 1))
                self.assertTrue(compat.is_cam_era())
                self.assertAlmostEqual(colors.view_color((1, 0, 0), 0.3)[3], 0.7)  # alpha, as 1.1 reads it
        with mock.patch.object(compat.FreeCAD, "Version", return_value=["1", "0", "0", ""]):
            self.assertAlmostEqual(colors.view_color((1, 0, 0), 0.3)[3], 0.3)  # 1.0 reads the transparency
        with mock.patch.object(compat.FreeCAD, "Version", return_value=["weekly", "", "", ""]):
            with self.assertRaisesRegex(ValueError, "no number to read"):
                compat.freecad_version()

    def test_command_names_and_preferences(self):
        with mock.patch.object(compat.FreeCAD, "Version", return_value=["1", "0", "2", ""]):
            self.assertEqual(compat.cam_command_name("Job"), "CAM_Job")
            self.assertEqual(compat.cam_workbench_name(), "CAMWorkbench")
            self.assertTrue(compat.cam_preferences_path().endswith("Mod/CAM"))

    def test_new_module_layout_is_preferred(self):
        fake = types.ModuleType("Path.Op.Base")
        with mock.patch.dict(sys.modules, {"Path.Op.Base": fake}):
            self.assertIs(compat.cam_module("op"), fake)


if __name__ == "__main__":
    unittest.main()
