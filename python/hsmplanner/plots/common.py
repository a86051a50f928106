"""What the plots of every subject share: figures made without pyplot, the tight layout of panel plots, and
the colour map of feeds (the same in PNG maps, panels and the 3D view).

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


def relayout_at_each_draw(figure, **pads):
    """Tight layout computed again whenever the figure is drawn: a panel's canvas is resized after the plots
    are drawn (a layout computed once was made for another size, and cut the labels off at the edges)."""
    figure.set_layout_engine("tight", **{k: v for k, v in pads.items() if v is not None})


def feed_colors(ratios):
    """RGB per value of reached / programmed feed (0..1), the same in PNG maps and in the 3D view."""
    cmap = matplotlib.colormaps[FEED_COLORMAP]
    return cmap(np.clip(np.asarray(ratios, dtype=float), 0.0, 1.0))[:, :3]
