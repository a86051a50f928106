"""What the plots of every subject share: figures made without pyplot, the tight layout of panel plots, labels
beside points that do not print over each other, and the colour map of feeds (the same in PNG maps, panels and
the 3D view).

Figures are made with matplotlib.figure.Figure and an Agg canvas, never with pyplot, so importing the plots
never changes the matplotlib backend of the FreeCAD session they run in.
"""
import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

FEED_COLORMAP = "RdYlGn"  # red where the machine slows down, green at the programmed feed


def new_figure(width, height, dpi=110):
    """A Figure with an Agg canvas, ready for savefig."""
    figure = Figure(figsize=(width, height), dpi=dpi)
    FigureCanvasAgg(figure)
    return figure


def subplots(rows, columns, width, height, dpi=110):
    figure = new_figure(width, height, dpi)
    axes = np.array([[figure.add_subplot(rows, columns, r * columns + c + 1) for c in range(columns)]
                     for r in range(rows)])
    return figure, axes


def label_offsets(points, labels, plot_size, font=6.0, limits=None):
    """Offsets in points (x, y) of the labels of `points` so that none prints over another: each label takes the
    first place, above its point, below, then farther above and below, whose box (about 0.55 font sizes a
    character wide, a font size high) meets no label placed before. `plot_size`: the plot's width and height in
    points, and `limits` ((x0, x1), (y0, y1)) the data they show (the points' own span when None), to put the
    data and the labels in one measure."""
    if len(points) != len(labels):
        raise ValueError("label_offsets: %d points but %d labels: give one label per point" % (len(points), len(labels)))
    if any(len(p) != 2 for p in points):
        raise ValueError("label_offsets: each point is (x, y), not %r" % (next(p for p in points if len(p) != 2),))
    if not points:
        return []
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    (x0, x1), (y0, y1) = limits or ((min(xs), max(xs)), (min(ys), max(ys)))
    xspan, yspan = (x1 - x0) or 1.0, (y1 - y0) or 1.0
    boxes, offsets = [], []
    for (x, y), label in zip(points, labels):
        px, py = (x - x0) / xspan * plot_size[0], (y - y0) / yspan * plot_size[1]
        width = 0.55 * font * len(label)
        places = [((px + 3, py + dy, px + 3 + width, py + dy + font), (3, dy)) for dy in (3, -9, 11, -17, 19, -25)]
        box, offset = next((place for place in places if not any(overlap(place[0], b) for b in boxes)), places[0])
        boxes.append(box)
        offsets.append(offset)
    return offsets


def overlap(a, b):
    """Whether boxes (x0, y0, x1, y1) a and b overlap."""
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def annotate_apart(axes, points, labels, fontsize=6):
    """Each of `labels` written beside its point of `points` (data coordinates), none over another
    (label_offsets, with the axes' size in points and the data they show as the figure lays them out now)."""
    box = axes.get_position()
    width, height = axes.figure.get_size_inches()
    plot_size = (box.width * width * 72.0, box.height * height * 72.0)
    axes.autoscale_view()
    limits = (axes.get_xlim(), axes.get_ylim())
    for point, label, offset in zip(points, labels, label_offsets(points, labels, plot_size, fontsize, limits)):
        axes.annotate(label, point, fontsize=fontsize, xytext=offset, textcoords="offset points")


def relayout_at_each_draw(figure, **pads):
    """Tight layout computed again whenever the figure is drawn: a panel's canvas is resized after the plots
    are drawn (a layout computed once was made for another size, and cut the labels off at the edges)."""
    figure.set_layout_engine("tight", **{k: v for k, v in pads.items() if v is not None})


def feed_colors(ratios):
    """RGB per value of reached / programmed feed (0..1), the same in PNG maps and in the 3D view."""
    cmap = matplotlib.colormaps[FEED_COLORMAP]
    return cmap(np.clip(np.asarray(ratios, dtype=float), 0.0, 1.0))[:, :3]
