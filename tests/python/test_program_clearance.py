"""Posted 5-axis roughing programs checked as their controller runs them: the tip straight between blocks and
the rotary axes interpolated linearly (LinuxCNC's TCP kinematics, the 840D's ORIAXES), not the tool axis on the
great circle between the blocks' axes; the program read back from the post's own text."""
import re
import unittest

import numpy as np
import Path

from hsmplanner import feedsim, roughing
from hsmplanner.app.posts import linuxcnc5x_post
from hsmplanner.app.roughing.commands import (ProgramSource, interpolated_program, posted_program,
                                              program_clearance, sweep_commands)

TRT = "linuxcnc-2.9-xyzac-trt"


def posted_text(moves, machine_name):
    """The LinuxCNC post's text of a sweep on `machine_name`."""
    machine = feedsim.load_machine(machine_name)
    source = ProgramSource("Roughing", sweep_commands(moves, machine, 2000.0))
    return linuxcnc5x_post.export([source], "-", "--machine=%s" % machine_name), machine


class InterpolatedProgram(unittest.TestCase):
    def setUp(self):
        self.machine = feedsim.load_machine(TRT)
        self.commands = [Path.Command("G1", {"X": 0.0, "Y": 0.0, "Z": 50.0, "A": 0.0, "C": 0.0, "F": 10.0}),
                         Path.Command("G1", {"X": 10.0, "Y": 0.0, "Z": 50.0, "A": 30.0, "C": 90.0, "F": 10.0})]

    def test_the_rotary_axes_turn_linearly_between_blocks(self):
        joint = interpolated_program(self.commands, self.machine, "angles", max_turn_deg=1.0)
        self.assertEqual(len(joint["tip"]), 1 + 90)  # C turns 90° in steps of 1°
        np.testing.assert_array_equal(joint["move"], [0] + [1] * 90)
        from hsmplanner import _core

        middle = np.asarray(_core.forward_kinematics(self.machine, [0.0, 0.0, 0.0], [15.0, 45.0])[1])
        np.testing.assert_allclose(joint["axis"][45], middle, atol=1e-12)
        np.testing.assert_allclose(joint["tip"][45], [5.0, 0.0, 50.0], atol=1e-12)
        # On the great circle the middle axis is the ends' mean, normalised: another direction.
        great = interpolated_program(self.commands, self.machine, "vectors")
        self.assertEqual(len(great["tip"]), 2)
        mean = great["axis"].sum(axis=0)
        mean /= np.linalg.norm(mean)
        self.assertGreater(np.degrees(np.arccos(np.clip(mean @ middle, -1.0, 1.0))), 1.0)

    def test_bad_settings_are_named(self):
        with self.assertRaisesRegex(ValueError, "orientation 'arcs' must be 'angles'"):
            interpolated_program(self.commands, self.machine, "arcs")
        with self.assertRaisesRegex(ValueError, r"max_turn_deg 0 must be within \[0.0001, 10\]"):
            interpolated_program(self.commands, self.machine, "angles", max_turn_deg=0.0)
        with self.assertRaisesRegex(ValueError, "use a larger max_turn_deg"):
            far = [self.commands[0], Path.Command("G1", {"X": 10.0, "C": 360.0 * 200, "F": 10.0})]
            interpolated_program(far, feedsim.load_machine(TRT), "angles", max_turn_deg=0.05)


class PostedPrograms(unittest.TestCase):
    """Every 5-axis strategy on both test parts, posted for LinuxCNC and read back: clear of the part by the
    allowance, everywhere the controller takes the tool."""

    def check(self, shapes, volume, strategy, step):
        allowance = roughing._core.roughing.SweepSettings().allowance
        partition = roughing.partition(volume, shapes.part_brep, strategy, step=step)
        paths = roughing.sweep(partition, volume, shapes.part_brep, shapes.stock_brep)
        moves, _ = roughing.keep_rapids_out_of_stock(roughing.join_paths([paths], shapes.stock_brep),
                                                     shapes.stock_brep, shapes.part_brep)
        text, machine = posted_text(moves, TRT)
        read_back = posted_program(text, machine, "vectors")
        self.assertEqual(len(read_back["tip"]), len(moves["tip"]), "every move of the sweep is in the posted text")
        np.testing.assert_allclose(read_back["tip"], moves["tip"], atol=1e-3)  # 4 decimals posted
        np.testing.assert_allclose(read_back["axis"], moves["axis"], atol=1e-5)
        joint, block = program_clearance(text, machine, shapes.part_brep, limit=allowance - 0.01)
        great, _ = program_clearance(text, machine, shapes.part_brep, limit=allowance - 0.01, orientation="vectors")
        label = "%s: closest %.4f mm at block %d (great circle %.4f mm)" % (strategy, joint.minimum, block, great.minimum)
        self.assertEqual(joint.too_close, 0, label)
        self.assertGreaterEqual(joint.minimum, allowance - 0.01, label)
        self.assertGreaterEqual(joint.positions, great.positions, label)
        self.assertIn("\n", text.split("\n", block)[-1] if block > 0 else "", label)  # a line of the text
        print("\n  %s, %d blocks, %d positions checked" % (label, len(moves["tip"]), joint.positions))
        return text, machine

    def test_a_program_sunk_into_the_part_is_caught(self):
        slot = roughing.slanted_slot_block(slot_width=30.0, length=100.0)
        volume = roughing.volume_to_remove(slot.stock_brep, slot.part_brep).solids[0]
        text, machine = self.check(slot, volume, "S5", 8.0)
        sunk = re.sub(r"Z(-?[0-9.]+)", lambda m: "Z%.4f" % (float(m.group(1)) - 5.0), text)
        report, line = program_clearance(sunk, machine, slot.part_brep, limit=0.49)
        self.assertGreater(report.too_close, 0)
        self.assertLess(report.minimum, 0.0)
        self.assertRegex(sunk.split("\n")[line - 1], r"^(G[01] )?.*Z")

    def test_the_impeller_s5(self):
        # S4 on the impeller is checked as swept and posted by RoughingPathsExample (too close 0, closest 0.49)
        wheel = roughing.impeller()
        channel = roughing.volume_to_remove(wheel.stock_brep, wheel.part_brep).solids[0]
        self.check(wheel, channel, "S5", 4.0)

    def test_the_slanted_slot_s4_and_s5(self):
        slot = roughing.slanted_slot_block(slot_width=30.0, length=100.0)
        volume = roughing.volume_to_remove(slot.stock_brep, slot.part_brep).solids[0]
        for strategy in ("S4", "S5"):
            self.check(slot, volume, strategy, 8.0)


if __name__ == "__main__":
    unittest.main()
