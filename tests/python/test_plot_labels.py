"""The Pareto plot's labels: points close together get labels that do not print over each other."""
import unittest

from hsmplanner.plots.common import label_offsets, overlap


def boxes(points, labels, offsets, plot_size=(430.0, 265.0), font=6.0):
    """The labels' boxes in the plot's points, as label_offsets measures them."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    xspan, yspan = (max(xs) - min(xs)) or 1.0, (max(ys) - min(ys)) or 1.0
    result = []
    for (x, y), label, (dx, dy) in zip(points, labels, offsets):
        px, py = (x - min(xs)) / xspan * plot_size[0], (y - min(ys)) / yspan * plot_size[1]
        result.append((px + dx, py + dy, px + dx + 0.55 * font * len(label), py + dy + font))
    return result


class ParetoLabels(unittest.TestCase):
    def test_the_rest_rows_of_the_study_get_labels_apart(self):
        # the study's rows of 5 December: three rest rows within 230 s and 0.1 point of each other
        points = [(406, 41.9), (985, 19.5), (1981, 5.8), (2149, 6.2), (2264, 6.2), (2379, 6.2), (2933, 6.5)]
        labels = ["S1", "S1+su", "S1+su+r", "S5+su+r", "S3+su+r", "S4+su+r", "S2+su+r"]
        offsets = label_offsets(points, labels, (430.0, 265.0))
        placed = boxes(points, labels, offsets)
        for i in range(len(placed)):
            for j in range(i):
                self.assertFalse(overlap(placed[i], placed[j]), "%s over %s" % (labels[i], labels[j]))
        self.assertEqual(offsets[0], (3, 3))  # a lone point keeps its label above right
        self.assertNotEqual(offsets[4][1], offsets[3][1])  # the crowded ones moved

    def test_no_points_and_one_point(self):
        self.assertEqual(label_offsets([], [], (430.0, 265.0)), [])
        self.assertEqual(label_offsets([(1.0, 1.0)], ["S1"], (430.0, 265.0)), [(3, 3)])


if __name__ == "__main__":
    unittest.main()
