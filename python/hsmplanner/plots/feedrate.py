"""Feed-rate reports: feed classes and block lengths of a simulation, its feed map, and the simulated times
of finishing strategies."""
import numpy as np
from matplotlib.cm import ScalarMappable
from matplotlib.colors import Normalize

from hsmplanner._core import LENGTH_CLASS_EDGES_MM, SPEED_LIMITS

from .common import FEED_COLORMAP, feed_colors, new_figure, relayout_at_each_draw

FEED_CLASS_LABELS = ("<0.3", "0.3-0.5", "0.5-0.7", "0.7-0.9", "≥0.9")


def block_polylines(blocks, arc_points=16):
    """One (k,3) polyline per block: lines as 2 points, arcs (and helices) sampled."""
    lines = []
    for i in range(len(blocks["line"])):
        start, end, sweep = blocks["start"][i], blocks["end"][i], blocks["sweep"][i]
        if sweep == 0.0:
            lines.append(np.vstack([start, end]))
            continue
        n, c = blocks["normal"][i], blocks["center"][i]
        radial = start - c
        rise = np.dot(end - start, n)
        f = np.linspace(0.0, 1.0, max(3, int(arc_points * abs(sweep) / np.pi) + 2))[:, None]
        angle = f * sweep
        cross = np.cross(n, radial)
        rotated = radial * np.cos(angle) + cross * np.sin(angle)
        lines.append(c + rotated + f * rise * n)
    return lines


def draw_feed_histograms(figure, summary, stacked=False):
    """Feed classes (share of blocks, length, time) and block-length classes of a SimulationSummary, side by
    side, or one above the other (`stacked`, for a narrow task panel)."""
    figure.clear()
    rows, columns = (2, 1) if stacked else (1, 2)
    left, right = figure.add_subplot(rows, columns, 1), figure.add_subplot(rows, columns, 2)
    x = np.arange(5)
    for offset, (shares, label, colour) in zip((-0.27, 0, 0.27), (
            (summary.feed_classes_blocks, "blocks", "#8da0cb"), (summary.feed_classes_length, "length", "#66c2a5"),
            (summary.feed_classes_time, "time", "#fc8d62"))):
        left.bar(x + offset, 100 * np.asarray(shares), width=0.26, label=label, color=colour)
    left.set_xticks(x)
    if stacked:  # upright and short: rotated labels still run into each other at a panel's width
        left.set_xticklabels([label.replace("0.", ".") for label in FEED_CLASS_LABELS], fontsize=7)
        left.set_xlabel("reached feed / F")
    else:
        left.set_xticklabels(FEED_CLASS_LABELS, rotation=30, fontsize=8)  # upright they run into each other
        left.set_xlabel("reached / programmed feed")
    left.set_ylabel("% of cutting")
    left.legend(fontsize=8)
    left.set_title("feed classes", fontsize=10)
    edges = LENGTH_CLASS_EDGES_MM
    labels = ["<%g" % edges[0]] + ["%g-%g" % (a, b) for a, b in zip(edges, edges[1:])] + ["≥%g" % edges[-1]]
    right.bar(np.arange(len(labels)), summary.length_classes, color="#8da0cb")
    if stacked:  # too narrow for a range under each bar: the class edges between the bars
        right.set_xticks(np.arange(len(edges)) + 0.5)
        right.set_xticklabels(["%g" % e for e in edges], fontsize=7, rotation=90)  # 12 px apart at 210 px
    else:
        right.set_xticks(np.arange(len(labels)))
        right.set_xticklabels(labels, rotation=35, fontsize=8)
    right.set_xlabel("block length (mm)")
    right.set_ylabel("cutting blocks")
    right.set_title("block lengths", fontsize=10)
    if not stacked:  # the panel says it in its table
        figure.suptitle("%s: %.1f s simulated, %.1f s by length/feed (x%.2f)" % (
            summary.machine, summary.total_time, summary.naive_time, summary.time_over_naive),
            fontsize=10)
    relayout_at_each_draw(figure)


def save_feed_histograms(summary, path):
    figure = new_figure(11, 4.2)
    draw_feed_histograms(figure, summary)
    figure.savefig(path)
    return path


def draw_feed_map(axes, blocks, linewidth=2.0):
    """Plan view of the path on `axes`, each cutting block coloured by its mean reached / programmed feed,
    rapids dotted grey; X and Y in mm at one scale."""
    from matplotlib.collections import LineCollection

    ratios = blocks["mean_feed"] / np.maximum(blocks["programmed_feed"], 1e-12)
    lines = block_polylines(blocks)
    cutting = blocks["motion"] != 0
    segments = [p[:, :2] for p, cut in zip(lines, cutting) if cut]
    axes.add_collection(LineCollection(segments, colors=feed_colors(ratios[cutting]), linewidths=linewidth))
    rapids = [p[:, :2] for p, cut in zip(lines, cutting) if not cut]
    axes.add_collection(LineCollection(rapids, colors="#999999", linewidths=0.25 * linewidth, linestyles="dotted"))
    axes.autoscale()
    axes.set_aspect("equal")
    axes.set_xlabel("X (mm)")
    axes.set_ylabel("Y (mm)")


def feed_share_bar(figure, axes, label="mean reached feed, % of programmed", **kwargs):
    """The colour bar of draw_feed_map's colours, 0 to 100 % of the programmed feed."""
    scalar = ScalarMappable(cmap=FEED_COLORMAP, norm=Normalize(0, 100))
    return figure.colorbar(scalar, ax=axes, label=label, **kwargs)


def save_feed_map(blocks, path, title):
    """Plan view of the path, each cutting block coloured by its mean reached / programmed feed."""
    figure = new_figure(11, 6.5)
    axes = figure.add_subplot(1, 1, 1)
    draw_feed_map(axes, blocks)
    feed_share_bar(figure, axes, shrink=0.8)
    axes.set_title(title, fontsize=10)
    figure.tight_layout()
    figure.savefig(path)
    return path


def save_rotary_axes(blocks, summary, rotary_names, path, title):
    """The rotary axes over time (each block's start and end, deg) above the share of time each limit held the
    speed: where a 5-axis program is slow, and which axis makes it so."""
    figure = new_figure(11, 6.5)
    angles = figure.add_subplot(2, 1, 1)
    start, time = blocks["start_time"], blocks["time"]
    t = np.column_stack([start, start + time]).ravel()
    for k, name in enumerate(rotary_names):
        a = np.column_stack([blocks["rotary_start"][:, k], blocks["rotary_end"][:, k]]).ravel()
        angles.plot(t, a, linewidth=1.2, label=name)
    angles.set_xlabel("time (s)")
    angles.set_ylabel("angle (deg)")
    angles.legend(loc="upper right", fontsize=8)
    angles.set_title(title, fontsize=10)
    shares = figure.add_subplot(2, 1, 2)
    total = max(sum(summary.limit_time), 1e-12)
    values = [100.0 * x / total for x in summary.limit_time]
    bars = shares.barh(range(len(SPEED_LIMITS)), values, color="#4a7ebb")
    shares.set_yticks(range(len(SPEED_LIMITS)))
    shares.set_yticklabels(SPEED_LIMITS, fontsize=8)
    shares.invert_yaxis()
    shares.set_xlabel("share of the time the limit held the speed (%)")
    for bar, value in zip(bars, values):
        if value > 0.05:
            shares.text(bar.get_width() + 0.5, bar.get_y() + bar.get_height() / 2, "%.1f %%" % value, va="center",
                        fontsize=8)
    shares.set_xlim(0, 110)
    figure.tight_layout()
    figure.savefig(path)
    return path


def save_strategy_times(times, feeds, path, title):
    """Grouped bars: simulated machining time of each strategy at each programmed feed.

    times: {strategy: [seconds at each feed]}; feeds: programmed feeds, mm/min; title: the figure's title
    (what was machined, on which machine)."""
    figure = new_figure(11, 4.5)
    axes = figure.add_subplot(1, 1, 1)
    names = list(times)
    width = 0.8 / len(feeds)
    for k, feed in enumerate(feeds):
        values = [times[name][k] for name in names]
        bars = axes.bar(np.arange(len(names)) + (k - (len(feeds) - 1) / 2) * width, values, width,
                        label="F = %g m/min" % (feed / 1000))
        axes.bar_label(bars, fmt="%.0f", fontsize=7)
    axes.set_xticks(np.arange(len(names)))
    axes.set_xticklabels([n.replace("_", " ") for n in names])
    axes.set_ylabel("simulated machining time (s)")
    axes.legend()
    axes.set_title(title)
    figure.tight_layout()
    figure.savefig(path)
    return path
