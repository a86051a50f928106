"""The moves of a Path as the tip path draws them (gui/tip_path.py without a 3D view): words modal, one edge per
move from the tip before it, the Tip path mode only for paths with rotary words."""
import unittest

import numpy as np
import Path

from hsmplanner.app.roughing.commands import program_moves
from hsmplanner.gui.tip_path import element_name, tip_edges, tip_path_node, turns_the_tool


def commands():
    return [Path.Command("(setup comment)"),
            Path.Command("G0", {"X": 10.0, "Y": 5.0, "Z": 30.0}),
            Path.Command("G0", {"A": -30.0, "C": 90.0}),
            Path.Command("G1", {"Z": 12.0, "F": 10.0}),
            Path.Command("G1", {"X": 40.0, "A": -35.0})]


class TipPath(unittest.TestCase):
    def test_moves_carry_their_words_on(self):
        index, tips, angles, feeds = program_moves(commands(), ["A", "C"])
        self.assertEqual(index.tolist(), [1, 2, 3, 4])  # the comment is no move
        np.testing.assert_allclose(tips, [[10, 5, 30], [10, 5, 30], [10, 5, 12], [40, 5, 12]])
        np.testing.assert_allclose(angles, [[0, 0], [-30, 90], [-30, 90], [-35, 90]])
        self.assertEqual(feeds.tolist(), [False, False, True, True])

    def test_one_edge_per_move_from_the_tip_before(self):
        _, tips, _, _ = program_moves(commands())
        edges = tip_edges(tips)
        self.assertEqual(edges.shape, (4, 2, 3))
        np.testing.assert_allclose(edges[0], [[10, 5, 30], [10, 5, 30]])  # not from an unstated start
        np.testing.assert_allclose(edges[3], [[10, 5, 12], [40, 5, 12]])
        self.assertEqual(tip_edges(np.zeros((0, 3))).shape, (0, 2, 3))

    def test_the_mode_only_for_rotary_words(self):
        self.assertTrue(turns_the_tool(commands()))
        self.assertFalse(turns_the_tool([c for c in commands() if not ({"A", "C"} & set(c.Parameters))]))

    def test_the_node_colours_each_move_and_names_it_as_freecad(self):
        _, tips, _, feeds = program_moves(commands())
        node = tip_path_node(tip_edges(tips), feeds, (0, 1, 0), (1, 0, 0), 2)
        colours = [tuple(c.getValue()) for c in node.getChild(0).diffuseColor.getValues()]
        self.assertEqual(colours, [(1, 0, 0), (1, 0, 0), (0, 1, 0), (0, 1, 0)])
        lines = node.getChild(4)
        self.assertEqual(list(lines.coordIndex.getValues()), [0, 1, -1, 2, 3, -1, 4, 5, -1, 6, 7, -1])
        self.assertTrue(element_name(3, commands()[3]).startswith("4 G1 F10,0"), element_name(3, commands()[3]))


if __name__ == "__main__":
    unittest.main()
