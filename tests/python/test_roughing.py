"""5-axis roughing part 1 through the Python API (hsmplanner.roughing): the slanted slot's closed-form volume and
face classes, the slicings and their tool axes, S3's setup direction, results as plain attributes and BREP that
FreeCAD reads back as valid solids, progress and cancellation, and bad inputs."""
import math
import os
import unittest

import numpy as np
import Part

import hsmplanner
from hsmplanner import roughing
from helpers import temporary_directory


def shape_of(brep):
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    return shape


def surfaces_of_class(solid, name):
    """The paper's faces (surfaces: B-rep faces of one surface count once) of a class."""
    return len({group for group, c in zip(solid.face_groups, solid.face_classes) if c.name == name})


class SlantedSlot(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.shapes = roughing.slanted_slot_block()
        cls.part = shape_of(cls.shapes.part_brep)
        cls.stock = shape_of(cls.shapes.stock_brep)
        cls.volume = roughing.volume_to_remove(cls.stock, cls.part)  # FreeCAD shapes are taken as they are
        cls.solid = cls.volume.solids[0]

    def test_volume_is_the_closed_form_and_freecad_reads_it_back(self):
        expected = roughing.slanted_slot_volume()
        self.assertEqual(expected, 16.0 * 24.0 * 40.0)
        self.assertAlmostEqual(self.volume.volume, expected, delta=1e-6 * expected)
        self.assertAlmostEqual(self.volume.stock_volume - self.volume.part_volume, expected, delta=1e-6 * expected)
        self.assertFalse(self.volume.fuzzy_retry)
        shape = shape_of(self.volume.brep)
        self.assertTrue(shape.isValid())
        self.assertEqual(len(shape.Solids), 1)
        self.assertAlmostEqual(shape.Volume, expected, delta=1e-6 * expected)
        # The volume and the part fill the stock: their union is the stock's volume.
        self.assertAlmostEqual(shape.fuse(self.part).Volume, self.stock.Volume, delta=1e-6 * self.stock.Volume)

    def test_face_classes_by_surface(self):
        self.assertEqual(len(self.solid.face_classes), len(shape_of(self.solid.brep).Faces))
        self.assertEqual(surfaces_of_class(self.solid, "crossable"), 3)
        self.assertEqual(surfaces_of_class(self.solid, "facing_crossable"), 1)
        self.assertEqual(surfaces_of_class(self.solid, "not_crossable"), 2)
        # The floor faces the mouth: its face is normal to the slot's axis, 30° from Z.
        floor = shape_of(self.solid.brep).Faces[list(self.solid.face_classes).index(roughing.FaceClass.facing_crossable)]
        normal = floor.normalAt(*floor.Surface.parameter(floor.CenterOfMass))
        self.assertAlmostEqual(abs(normal.z), math.cos(math.radians(30.0)), places=6)

    def test_planes_from_the_mouth(self):
        result = roughing.partition(self.solid, self.part, "S1", step=8.0)
        self.assertEqual(result.strategy, roughing.Strategy.S1)
        self.assertEqual(len(result.sub_volumes), 4)  # ceil(24.78 / 8)
        self.assertAlmostEqual(sum(s.volume for s in result.sub_volumes), self.solid.volume, delta=1e-6 * self.solid.volume)
        for k, sub in enumerate(result.sub_volumes):
            self.assertEqual(sub.slice, k)
            shape = shape_of(sub.brep)
            self.assertTrue(shape.isValid())
            self.assertAlmostEqual(shape.Volume, sub.volume, delta=1e-6 * sub.volume)
            # A slab k lies between 30 − 8k and 30 − 8(k + 1) in Z.
            self.assertLessEqual(shape.BoundBox.ZMax, 30.0 - 8.0 * k + 1e-6)
            self.assertGreaterEqual(shape.BoundBox.ZMin, 30.0 - 8.0 * (k + 1) - 1e-6)
            self.assertTrue(all(abs(d[2] - 1.0) < 1e-9 for d in sub.axis_directions))

    def test_floor_offsets_follow_the_axis(self):
        result = roughing.partition(self.volume, self.part, roughing.Strategy.S5, step=4.0)
        self.assertEqual(len(result.sub_volumes), 8)  # ceil((24 + 8·tan 30°) / 4)
        axis = (math.sin(math.radians(30.0)), 0.0, math.cos(math.radians(30.0)))
        for sub in result.sub_volumes:
            for d in sub.axis_directions:
                self.assertAlmostEqual(sum(a * b for a, b in zip(d, axis)), 1.0, places=6)

    def test_the_setup_direction_is_the_slots_axis(self):
        direction, reach = roughing.setup_direction(self.solid, self.part, grid=1.5)
        self.assertGreater(direction[0] * 0.5 + direction[2] * math.cos(math.radians(30.0)), math.cos(math.radians(6.0)))
        self.assertGreater(reach, 0.97)
        self.assertLess(roughing.reachable_share(self.solid, self.part, (0, 0, 1), grid=1.5), 0.75)
        result = roughing.partition(self.solid, self.part, "S3", step=8.0, setup_grid=1.5)
        self.assertAlmostEqual(sum(s.volume for s in result.sub_volumes), self.solid.volume, delta=1e-6 * self.solid.volume)
        self.assertEqual(result.reference_face, 0)
        self.assertGreater(result.setup_reach, 0.97)

    def test_progress_and_cancel(self):
        seen = []
        roughing.partition(self.solid, self.part, "S1", step=2.0, progress=lambda done: seen.append(done))
        self.assertEqual(seen[-1], 1.0)
        self.assertEqual(seen, sorted(seen))
        with self.assertRaises(hsmplanner.Cancelled):
            roughing.partition(self.solid, self.part, "S1", step=2.0, progress=lambda done: False)
        with self.assertRaises(hsmplanner.Cancelled):
            roughing.volume_to_remove(self.stock, self.part, progress=lambda done: False)

    def test_s4_on_a_planar_skin_says_it_is_s1(self):
        # The slot's stock skin is its top plane: S4's offsets of it are S1's planes, and the partition says so.
        s4, s1 = (roughing.partition(self.solid, self.part, name) for name in ("S4", "S1"))
        self.assertTrue(any("the stock skin here is a plane" in w and "S1's" in w for w in s4.warnings), s4.warnings)
        self.assertFalse(any("stock skin" in w for w in s1.warnings))
        np.testing.assert_allclose([v.volume for v in s4.sub_volumes], [v.volume for v in s1.sub_volumes], rtol=1e-9)

    def test_no_rapid_of_any_strategy_cuts_the_stock_left(self):
        # Each strategy's program with its rapids kept out of the stock (at 0.2 mm), checked on another model
        # (0.25 mm): no rapid takes anything out; and a rapid down into the stock is found and mended.
        for name in ("S1", "S3", "S4", "S5"):
            with self.subTest(strategy=name):
                paths = roughing.sweep(roughing.partition(self.solid, self.part, name), self.solid, self.part,
                                       self.stock)
                moves, fed = roughing.keep_rapids_out_of_stock(roughing.join_paths([paths], self.stock), self.stock,
                                                               self.part)
                check = roughing.simulate_removal(moves, self.stock, self.part, resolution=0.25)
                self.assertEqual(list(check.rapid_faults), [], "rapids cut the stock left")
                self.assertEqual(check.rapid_volume, 0.0)
        top = self.stock.BoundBox.ZMax
        inside = shape_of(self.solid.brep).Solids[0].CenterOfMass
        rapid = roughing.MOVE_KINDS.index("rapid")
        down = {"tip": np.array([[inside.x, inside.y, top + 10.0], [inside.x, inside.y, inside.z]]),
                "axis": np.array([[0.0, 0.0, 1.0]] * 2), "kind": np.array([rapid, rapid])}
        faults = roughing.simulate_removal(down, self.stock, self.part).rapid_faults
        self.assertEqual([f.move for f in faults], [1])
        self.assertGreater(faults[0].volume, 10.0)
        moves, fed = roughing.keep_rapids_out_of_stock(down, self.stock, self.part, margin=1.0)
        self.assertEqual([roughing.MOVE_KINDS[k] for k in moves["kind"]], ["rapid", "rapid", "plunge"])
        self.assertGreaterEqual(moves["tip"][1][2], faults[0].at[2] + 1.0 - 1e-9)  # stops a margin above the stock
        self.assertEqual(list(roughing.simulate_removal(moves, self.stock, self.part).rapid_faults), [])
        self.assertIn("1 rapid would have cut stock left", roughing.rapid_note(fed))

    def test_bad_inputs_name_the_input_and_the_fix(self):
        cases = [
            (lambda: roughing.partition(self.solid, self.part, "S2"), ValueError, "needs a cylindrical crossable face"),
            (lambda: roughing.partition(self.solid, self.part, "S1", step=0), ValueError, "step 0 mm must be positive"),
            (lambda: roughing.partition(self.solid, self.part, "S1", step=-1), ValueError, "must be positive"),
            (lambda: roughing.partition(self.solid, self.part, "S1", step=100), ValueError, "use a step up to"),
            (lambda: roughing.partition(self.solid, self.part, "S1", step=1e-3), ValueError, "use a step of at least"),
            (lambda: roughing.partition(self.solid, self.part, "S7"), ValueError, "use one of S1, S2, S3, S4, S5"),
            (lambda: roughing.partition(self.solid, self.part, "S3", setup_grid=0), ValueError, "setup grid 0 mm"),
            (lambda: roughing.partition(self.solid, self.part, "S3", setup_grid=1e-3), ValueError, "coarser grid"),
            (lambda: roughing.partition(self.solid, self.part, "S3", setup_resolution_deg=0.01), ValueError,
             "resolution 0.01°"),
            (lambda: roughing.volume_to_remove(self.part, self.part), ValueError, "nothing to remove"),
            (lambda: roughing.volume_to_remove(self.part, self.stock), ValueError, "does not contain the part"),
            (lambda: roughing.volume_to_remove(self.stock, self.part.Faces[0]), ValueError, "part"),
            (lambda: roughing.volume_to_remove(self.stock, Part.Shape()), ValueError, "shape is null"),
            (lambda: roughing.volume_to_remove(self.stock, "not a brep"), ValueError, "BREP"),
            (lambda: roughing.reachable_share(self.solid, self.part, (0, 0, 0)), ValueError, "non-zero"),
            (lambda: roughing.slanted_slot_block(slot_depth=40), ValueError, "does not fit in the block"),
            (lambda: roughing.impeller(blades=1), ValueError, "give 2 to 24 blades"),
            (lambda: roughing.impeller(channel_height=50), ValueError, "channel height"),
        ]
        for call, error, words in cases:
            with self.assertRaises(error) as caught:
                call()
            self.assertIn(words, str(caught.exception))

    def test_a_stock_beside_the_part_and_an_open_shell(self):
        beside = self.stock.copy()
        beside.translate(FreeCAD_vector(200.0, 0.0, 0.0))
        with self.assertRaises(ValueError) as caught:
            roughing.volume_to_remove(beside, self.part)
        self.assertIn("does not contain the part", str(caught.exception))
        shell = Part.Shell(self.part.Faces[:-1])  # one face missing: not closed
        with self.assertRaises(ValueError) as caught:
            roughing.volume_to_remove(self.stock, shell)
        self.assertIn("part", str(caught.exception))


def FreeCAD_vector(x, y, z):
    import FreeCAD

    return FreeCAD.Vector(x, y, z)


class Impeller(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.wheel = roughing.impeller()
        cls.volume = roughing.volume_to_remove(cls.wheel.stock_brep, cls.wheel.part_brep)

    def test_one_channel_per_blade_with_the_papers_six_faces(self):
        self.assertEqual(len(self.volume.solids), 7)
        for channel in self.volume.solids:
            self.assertEqual(channel.group_count, 6)
            self.assertEqual([surfaces_of_class(channel, name) for name in ("crossable", "facing_crossable", "not_crossable")],
                             [3, 1, 2])

    def test_s2_cylinders_about_the_outlet_and_their_radial_axes(self):
        channel = self.volume.solids[0]
        result = roughing.partition(channel, self.wheel.part_brep, "S2", step=8.0)
        self.assertAlmostEqual(result.volume, channel.volume, delta=1e-6 * channel.volume)
        outlet_radius = 50.0
        for sub in result.sub_volumes:
            self.assertEqual(sub.surface.kind, roughing.SurfaceKind.cylinder)
            self.assertAlmostEqual(sub.surface.radius, outlet_radius - 8.0 * sub.slice, places=6)
            for point, axis in zip(sub.axis_points, sub.axis_directions):
                radial = (point[0], point[1])
                norm = math.hypot(*radial)
                # The tool axis is radial, pointing out through the outlet.
                self.assertAlmostEqual((axis[0] * radial[0] + axis[1] * radial[1]) / norm, 1.0, places=6)
                self.assertAlmostEqual(axis[2], 0.0, places=9)


class Sweep(unittest.TestCase):
    """Part 2 from Python: the slanted slot swept by S1 and S3, checked independently."""

    @classmethod
    def setUpClass(cls):
        cls.shapes = roughing.slanted_slot_block(slot_width=30.0, length=100.0)
        cls.volume = roughing.volume_to_remove(cls.shapes.stock_brep, cls.shapes.part_brep)

    def swept(self, name, **settings):
        result = roughing.partition(self.volume, self.shapes.part_brep, name)
        return result, roughing.sweep(result, self.volume, self.shapes.part_brep, self.shapes.stock_brep, **settings)

    def test_s1_one_axis_and_clear_of_the_part(self):
        _, paths = self.swept("S1")
        axes = paths.moves["axis"]
        self.assertGreater(len(axes), 20)
        np.testing.assert_allclose(axes, np.tile(axes[0], (len(axes), 1)), atol=1e-12)
        kinds = [roughing.MOVE_KINDS[k] for k in paths.moves["kind"]]
        self.assertIn("cut", kinds)
        self.assertIn("ramp", kinds)
        report = roughing.check_clearance(paths, self.shapes.part_brep)
        self.assertEqual(report.too_close, 0)
        self.assertGreaterEqual(report.minimum, 0.49)
        self.assertGreater(paths.cutting_length, 100.0)

    def test_s3_along_the_setup_and_a_flat_cutter(self):
        result, paths = self.swept("S3", tool=roughing.cutter("flat", diameter=6.0), allowance=0.3)
        np.testing.assert_allclose(paths.moves["axis"][0], result.setup_direction, atol=1e-9)
        report = roughing.check_clearance(paths, self.shapes.part_brep, roughing.cutter("flat", diameter=6.0), 0.29)
        self.assertEqual(report.too_close, 0)

    def test_the_push_out_cuts_nearer_the_leaning_walls_and_no_nearer_than_the_allowance(self):
        # S1's levels are horizontal, the slot's walls lean: the keep-out holds the outer passes farther from
        # them than the allowance (the widest the tool is over each band of heights); pushed out to the exact
        # clearance they cut more and leave less, and the independent check still finds nothing too close.
        left = {}
        for push in (0.0, 1.5):
            _, paths = self.swept("S1", push_out=push)
            report = roughing.check_clearance(paths, self.shapes.part_brep)
            self.assertEqual(report.too_close, 0, "push-out %g" % push)
            self.assertGreaterEqual(report.minimum, 0.49)
            removal = roughing.simulate_removal(paths, self.shapes.stock_brep, self.shapes.part_brep, resolution=0.5)
            self.assertEqual(removal.gouge_volume, 0.0)
            left[push] = removal.beyond_allowance_share
        self.assertLess(left[1.5], left[0.0] - 0.3)

    def test_s5_stands_on_the_floor_and_leaves_the_allowance(self):
        # S5 follows the slot's floor (30° from the horizontal): the tool axis is the floor's normal, away from it,
        # and the lowest level's tip stays the allowance above the floor.
        result, paths = self.swept("S5")
        normal = np.array([np.sin(np.radians(30.0)), 0.0, np.cos(np.radians(30.0))])
        axes = paths.moves["axis"]
        self.assertGreater(len(axes), 20)
        np.testing.assert_allclose(axes @ normal, np.ones(len(axes)), atol=1e-9)
        cuts = paths.moves["tip"][paths.moves["kind"] == roughing.MOVE_KINDS.index("cut")]
        floor_point = np.asarray(result.sub_volumes[0].surface.origin)
        lowest = (cuts - floor_point) @ normal
        self.assertAlmostEqual(lowest.min(), 0.5, delta=0.06)
        report = roughing.check_clearance(paths, self.shapes.part_brep)
        self.assertEqual(report.too_close, 0)

    def test_material_removal_of_the_setup_planes(self):
        # S3 removes most of the slot's volume without touching the part; what it leaves on the part is at least
        # the allowance on average, and a holder 40 mm up clears everything.
        _, paths = self.swept("S3")
        result = roughing.simulate_removal(paths, self.shapes.stock_brep, self.shapes.part_brep, resolution=0.5)
        self.assertEqual(result.resolution, 0.5)
        self.assertLess(result.remaining_share, 60.0)
        self.assertEqual(result.gouge_move, -1)
        self.assertLess(result.gouge_volume, 1e-9)
        self.assertGreater(result.in_material_share, 20.0)
        # Of the whole path (rapids and links too) a smaller share cuts.
        self.assertAlmostEqual(result.in_material_path_share, 100.0 * result.in_material_length / result.path_length,
                               places=9)
        self.assertLess(result.in_material_path_share, result.in_material_share)
        self.assertGreater(result.path_length, result.feed_length)
        self.assertGreater(result.stick_out, 5.0)
        self.assertLess(result.stick_out, 40.0)
        self.assertGreaterEqual(result.thickness_mean, 0.4)
        self.assertEqual(len(result.thickness), len(result.surface_points))
        self.assertAlmostEqual(float(np.average(result.thickness, weights=result.weight)), result.thickness_mean, places=9)
        with self.assertRaisesRegex(ValueError, "resolution 0 mm is outside \\[0.005, 50\\] mm"):
            roughing.simulate_removal(paths, self.shapes.stock_brep, self.shapes.part_brep, resolution=0.0)
        # The stock left as blocks (one ray in 2 × 2: the volume within 1 %), saved as STL and read back by
        # FreeCAD's Mesh: closed and facing out (its signed volume is the stock's; the blocks' sides meet their
        # neighbours' edges part-way, so it is not a manifold in FreeCAD's sense).
        import Mesh
        blocks = roughing.simulate_removal(paths, self.shapes.stock_brep, self.shapes.part_brep, resolution=0.5,
                                           stock_mesh_stride=2)
        folder = temporary_directory(self)
        stl = roughing.save_stl(blocks.stock_mesh, os.path.join(folder, "stock_left.stl"))
        mesh = Mesh.Mesh(stl)
        self.assertEqual(mesh.CountFacets, len(blocks.stock_mesh[1]))
        self.assertAlmostEqual(mesh.Volume, blocks.remaining_volume, delta=0.01 * blocks.remaining_volume)
        # Two copies of the path joined keep one tool axis (a plane link), and remove nothing more.
        joined = roughing.join_paths([paths, paths], self.shapes.stock_brep)
        np.testing.assert_allclose(joined["axis"] @ paths.moves["axis"][0], 1.0, atol=1e-12)
        again = roughing.simulate_removal(joined, self.shapes.stock_brep, self.shapes.part_brep, resolution=0.5)
        self.assertAlmostEqual(again.remaining_share, result.remaining_share, places=9)

    def test_machine_axes_give_the_tool_axes_back(self):
        from hsmplanner import _core, feedsim
        _, paths = self.swept("S3")
        trunnion = feedsim.load_machine("mikron-ucp710-ac-840d")
        tips, angles, names = roughing.machine_axes(paths, trunnion)
        self.assertEqual(names, ["A", "C"])
        for angle, axis in zip(angles[::25], paths.moves["axis"][::25]):
            np.testing.assert_allclose(_core.forward_kinematics(trunnion, [0, 0, 0], list(angle))[1], axis, atol=1e-9)
        # On a 3-axis machine the same path is 3+2: the tips in the work plane turned so that the axis is Z.
        turned, _, names = roughing.machine_axes(paths, feedsim.load_machine("mikron-ucp710-840d"))
        rotation, tilt, about = roughing.work_plane(paths)
        self.assertEqual(names, [])
        np.testing.assert_allclose(turned, paths.moves["tip"] @ rotation.T, atol=1e-12)
        np.testing.assert_allclose(rotation @ paths.moves["axis"][0], [0, 0, 1], atol=1e-12)
        self.assertAlmostEqual(tilt, np.degrees(np.arccos(paths.moves["axis"][0][2])), places=9)
        self.assertAlmostEqual(float(about @ paths.moves["axis"][0]), 0.0, places=12)
        _, flat = self.swept("S1")
        tips, angles, names = roughing.machine_axes(flat, feedsim.load_machine("mikron-ucp710-840d"))
        self.assertEqual(names, [])
        np.testing.assert_allclose(tips, flat.moves["tip"])

    def test_bad_settings_name_the_input(self):
        result = roughing.partition(self.volume, self.shapes.part_brep, "S1")
        for settings, message in ((dict(radial_engagement=1.5), "radial engagement = 1.5 must be in \\[0.01, 1\\]"),
                                  (dict(allowance=-0.5), "allowance = -0.5 is outside"),
                                  (dict(push_out=20.0), "push-out = 20"),
                                  (dict(mesh_deflection=0.001), "mesh deflection = 0.001 is outside \\[0.005, 1\\]"),
                                  (dict(tool=roughing.cutter(diameter=500.0)), "cutter diameter = 500 mm")):
            with self.subTest(message=message), self.assertRaisesRegex(ValueError, message):
                roughing.sweep(result, self.volume, self.shapes.part_brep, self.shapes.stock_brep, **settings)
        with self.assertRaisesRegex(TypeError, r"SweepSettings.push_out_most cannot be 'far' \(str\): give a float"):
            roughing.sweep(result, self.volume, self.shapes.part_brep, self.shapes.stock_brep, push_out="far")
        with self.assertRaisesRegex(ValueError, "cutter kind 'drill' is unknown"):
            roughing.cutter("drill")
