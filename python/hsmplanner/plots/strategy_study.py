"""Pictures of the automatic strategy study: each variant as a point of simulated time against the
share of cutting time below half the feed, the Pareto front drawn through the variants no other beats on both,
and the feed-class shares of the best rows as stacked bars. Inputs are the study's rows (no FreeCAD); the front
and the names are the study's own (hsmplanner.study)."""
import numpy as np

from ..study import FEED_CLASS_NAMES, pareto_front, short_name
from .common import annotate_apart, new_figure

STRATEGY_STYLES = {"planes": ("tab:blue", "o", "parallel planes"), "guide": ("tab:orange", "s", "guide curves"),
                   "4-step": ("tab:red", "*", "the paper's 4-step method")}
FEED_CLASSES = list(zip(("time_share_" + name for name in FEED_CLASS_NAMES),
                        ("< 20 %", "20–40 %", "40–60 %", "60–80 %", "> 80 % of F")))


def draw_pareto(axes, rows, selected=(), label_front=True):
    """The scatter of time (s) against slowdown share (%) by strategy, the front as a step line, the rows
    named in `selected` ringed. Returns the front."""
    ran = [r for r in rows if not r.get("error")]
    for strategy, (colour, marker, label) in STRATEGY_STYLES.items():
        these = [r for r in ran if r["strategy"] == strategy]
        if these:
            axes.scatter([r["time_s"] for r in these], [100 * r["slowdown_share"] for r in these], c=colour,
                         marker=marker, s=60 if strategy == "4-step" else 22, label=label, zorder=3)
    front = pareto_front(ran)
    if front:
        axes.step([r["time_s"] for r in front], [100 * r["slowdown_share"] for r in front], where="post",
                  color="black", linewidth=1.0, label="Pareto front", zorder=2)
        if label_front:
            annotate_apart(axes, [(r["time_s"], 100 * r["slowdown_share"]) for r in front],
                           [short_name(r) for r in front], fontsize=6)
    chosen = [r for r in ran if r["name"] in set(selected)]
    if chosen:
        axes.scatter([r["time_s"] for r in chosen], [100 * r["slowdown_share"] for r in chosen], s=140,
                     facecolors="none", edgecolors="magenta", linewidths=1.5, label="selected", zorder=4)
    axes.set_xlabel("simulated machining time, s", fontsize=8)
    axes.set_ylabel("cutting time below half the feed, %", fontsize=8)
    axes.tick_params(labelsize=7)
    axes.grid(alpha=0.3)
    axes.legend(fontsize=7)
    return front


def draw_feed_classes(axes, rows):
    """Stacked bars of the time share in each of the paper's five feed classes, one bar per row."""
    bottom = np.zeros(len(rows))
    colours = ["#d7191c", "#fdae61", "#ffffbf", "#a6d96a", "#1a9641"]
    for (key, label), colour in zip(FEED_CLASSES, colours):
        share = np.array([100 * r[key] for r in rows])
        axes.barh(np.arange(len(rows)), share, left=bottom, color=colour, label=label, edgecolor="grey",
                  linewidth=0.3)
        bottom += share
    axes.set_yticks(np.arange(len(rows)), [short_name(r) for r in rows], fontsize=6)
    axes.invert_yaxis()
    axes.set_xlabel("share of the machining time in each feed class, %", fontsize=8)
    axes.tick_params(axis="x", labelsize=7)
    axes.legend(fontsize=6, ncol=5, loc="upper center", bbox_to_anchor=(0.5, -0.12))


def save_study_plot(rows, path, title, best=12):
    """The Pareto scatter and the feed classes of the `best` fastest rows, side by side, saved to `path`."""
    figure = new_figure(13.0, 5.5)
    left, right = figure.add_subplot(1, 2, 1), figure.add_subplot(1, 2, 2)
    draw_pareto(left, rows)
    ranked = sorted((r for r in rows if not r.get("error")), key=lambda r: r["time_s"])[:best]
    draw_feed_classes(right, ranked)
    right.set_title("the %d fastest variants" % len(ranked), fontsize=8)
    figure.suptitle(title, fontsize=9)
    figure.tight_layout()
    figure.savefig(path)
    return path


def draw_feed_maps(figure, maps, columns=2):
    """The feed-rate maps of several variants side by side on `figure`: [(row, blocks), …], each titled with its
    name, simulated time and slowdown share, one colour scale (reached / programmed feed) for all."""
    from .feedrate import draw_feed_map, feed_share_bar

    figure.clear()
    columns = min(columns, len(maps)) or 1
    rows = (len(maps) + columns - 1) // columns
    axes = [figure.add_subplot(rows, columns, k + 1) for k in range(len(maps))]
    for panel, (row, blocks) in zip(axes, maps):
        draw_feed_map(panel, blocks, linewidth=1.2)
        panel.set_title("%s: %.1f s, %.1f %% below F/2" % (short_name(row), row["time_s"],
                                                            100 * row["slowdown_share"]), fontsize=8)
        panel.tick_params(labelsize=6)
        panel.xaxis.label.set_size(7)
        panel.yaxis.label.set_size(7)
    if axes:
        feed_share_bar(figure, axes, shrink=0.6)
    return axes


def save_feed_maps(maps, path, title="", columns=2):
    """draw_feed_maps in a figure of its own, saved to `path`."""
    rows = (len(maps) + columns - 1) // columns
    figure = new_figure(6.0 * min(columns, len(maps)) + 1.2, 3.0 * rows + 0.4)  # the feature is 140 x 60 mm
    draw_feed_maps(figure, maps, columns)
    figure.suptitle(title, fontsize=9)
    figure.savefig(path, bbox_inches="tight")
    return path
