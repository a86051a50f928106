"""Pictures of the five-strategy roughing study (examples/roughing_study.py): the stock left on the part
by each strategy as a coloured map, and bars of the remaining volume and the machining time beside the paper's.

Inputs are plain arrays (points, thickness) and rows of numbers: no FreeCAD, no core."""
import numpy as np

from .common import annotate_apart, new_figure


def _scale_top(thickness):
    """The top of a colour scale for a map's thicknesses: the 99th percentile (a few deep spots would turn the
    rest dark), 0 for no points."""
    return float(np.percentile(thickness, 99)) if len(thickness) else 0.0


def _map_title(label, thickness, weight):
    mean = float(np.average(thickness, weights=weight)) if len(thickness) else 0.0
    return "%s: mean %.2f, max %.2f mm" % (label, mean, float(thickness.max()) if len(thickness) else 0.0)


def _colour_bar(figure, norm, colours, **where):
    """A colour bar of `norm` with a few numbers (mm); where: colorbar's placing (cax= or ax=)."""
    import matplotlib.cm as cm
    from matplotlib.ticker import MaxNLocator

    colour_bar = figure.colorbar(cm.ScalarMappable(norm=norm, cmap=colours), **where)
    colour_bar.ax.yaxis.set_major_locator(MaxNLocator(4))
    colour_bar.ax.tick_params(labelsize=6)
    return colour_bar


def draw_stock_maps(figure, maps, view=(28, -60), top_mm=None, columns=3, bar=True, own_scales=False,
                    coordinates=True):
    """One 3D panel per strategy on `figure`: [(label, points (N, 3), thickness (N,), weight (N,)), …], the
    points of the part's surface coloured by the stock left on them, mm; the titles give the area-weighted mean
    (the weights: each point's share of the surface).

    One scale for all panels with a shared colour bar (`bar`), or with `own_scales` a scale and a colour bar per
    panel: on one scale a strategy that leaves little reads as one colour beside one that leaves much.
    coordinates=False leaves out the axes' numbers (a small panel: only the colours are read there)."""
    import matplotlib.cm as cm
    from matplotlib.colors import Normalize

    figure.clear()
    if not maps:
        return False
    columns = min(columns, len(maps))
    rows = (len(maps) + columns - 1) // columns
    shared = top_mm or max(_scale_top(np.asarray(t)) for _, _, t, _ in maps) or 1.0
    colours = cm.get_cmap("viridis")
    for k, (label, points, thickness, weight) in enumerate(maps):
        axes = figure.add_subplot(rows, columns, k + 1, projection="3d")
        points, thickness = np.asarray(points).reshape(-1, 3), np.asarray(thickness)
        norm = Normalize(0.0, (top_mm or _scale_top(thickness) or 1.0) if own_scales else shared)
        step = max(1, len(points) // 20000)  # a readable cloud: at most 20,000 points a panel
        axes.scatter(*points[::step].T, c=colours(norm(thickness[::step])), s=2.0, linewidths=0)
        axes.view_init(*view)
        axes.set_title(_map_title(label, thickness, weight), fontsize=8)
        axes.tick_params(labelsize=6)
        if not coordinates:
            for axis in (axes.xaxis, axes.yaxis, axes.zaxis):
                axis.set_ticklabels([])
        if own_scales:
            _colour_bar(figure, norm, colours, ax=axes, shrink=0.7, pad=0.0, fraction=0.07)  # mm: in the title
    if bar and not own_scales:
        figure.subplots_adjust(left=0.0, right=0.9, top=0.9, bottom=0.03, wspace=0.02, hspace=0.1)
        _colour_bar(figure, Normalize(0.0, shared), colours, cax=figure.add_axes([0.92, 0.2, 0.015, 0.6])).set_label(
            "stock left on the part, mm (%g and more at the top of the scale)" % round(shared, 2), fontsize=8)
    return True


def save_stock_maps(maps, path, title, view=(28, -60), top_mm=None):
    """draw_stock_maps in a figure of its own, saved to `path`."""
    columns = min(3, len(maps))
    rows = (len(maps) + columns - 1) // columns
    figure = new_figure(4.2 * columns + 0.9, 4.0 * rows)
    draw_stock_maps(figure, maps, view, top_mm)
    figure.suptitle(title, fontsize=9)
    figure.savefig(path)
    return path


VARIANT_MARKS = {"paper": "", "step-up": "+su"}  # a rest row: "+su+r"


def short_label(row):
    """S1, S1+su (step-up), S1+su+r (step-up and rest roughing): a row's strategy and variant in a few letters."""
    variant = row.get("variant") or "paper"
    return row["strategy"] + VARIANT_MARKS.get(variant, "+su+r")


def save_study_bars(rows, path, title):
    """Bars per strategy: V_r (ours with and without the allowance layer, the paper's) and the simulated
    machining time against length/feed. `rows`: dicts with strategy, variant, paper_vr, vr,
    vr_beyond_allowance, time_s, length_over_feed_s (None where unknown)."""
    labels = [short_label(r) for r in rows]
    x = np.arange(len(rows))
    figure = new_figure(10.0, 4.0)
    left, right = figure.add_subplot(1, 2, 1), figure.add_subplot(1, 2, 2)
    value = lambda key: [np.nan if r.get(key) in (None, "") else float(r[key]) for r in rows]
    for offset, key, name in ((-0.27, "paper_vr", "paper (TopSolid)"), (0.0, "vr", "ours"),
                              (0.27, "vr_beyond_allowance", "ours, without the 0.5 mm allowance")):
        left.bar(x + offset, value(key), width=0.26, label=name)
    left.set_xticks(x, labels, fontsize=7, rotation=60)
    left.set_ylabel("V_r: volume left, % of the volume to remove", fontsize=8)
    left.set_ylim(0.0, 1.3 * np.nanmax(value("vr") + value("paper_vr")))  # room for the legend above the bars
    left.legend(fontsize=7, loc="upper center", ncol=2)
    right.bar(x - 0.2, value("length_over_feed_s"), width=0.38, label="length / feed")
    right.bar(x + 0.2, value("time_s"), width=0.38, label="simulated (840D A/C)")
    right.set_xticks(x, labels, fontsize=7, rotation=60)
    right.set_ylabel("machining time, s", fontsize=8)
    right.set_ylim(0.0, 1.2 * np.nanmax(value("time_s") + value("length_over_feed_s")))
    right.legend(fontsize=7, loc="upper center", ncol=2)
    for axes in (left, right):
        axes.tick_params(labelsize=7)
    figure.suptitle(title, fontsize=9)
    figure.tight_layout()
    figure.savefig(path)
    return path


def save_pareto(rows, path, title):
    """V_r beyond the allowance against the simulated time, one point per row (colour: strategy, mark: as the
    paper, step-up, step-up and rest roughing), the rows no other beats on both joined: the front a shop
    chooses on."""
    from hsmplanner.study import pareto_front

    figure = new_figure(7.0, 4.6)
    axes = figure.add_subplot(1, 1, 1)
    measured = [r for r in rows if r.get("time_s") not in (None, "")]
    strategies = sorted({r["strategy"] for r in measured})
    colours = dict(zip(strategies, ("C0", "C1", "C2", "C3", "C4", "C5")))
    marks = {"paper": "o", "step-up": "s"}
    points = [(row["time_s"], row["vr_beyond_allowance"]) for row in measured]
    for row, point in zip(measured, points):
        axes.scatter(*point, color=colours[row["strategy"]], marker=marks.get(row["variant"], "^"), s=36)
    annotate_apart(axes, points, [short_label(r) for r in measured], fontsize=6)
    front = pareto_front(measured, ("time_s", "vr_beyond_allowance"))
    axes.plot([r["time_s"] for r in front], [r["vr_beyond_allowance"] for r in front], "k--", lw=0.8,
              label="Pareto front")
    for variant, mark in (("as the paper", "o"), ("step-up", "s"), ("step-up + rest", "^")):
        axes.scatter([], [], color="0.4", marker=mark, label=variant)
    axes.set_xlabel("simulated machining time, s", fontsize=8)
    axes.set_ylabel("V_r beyond the allowance, % of the volume to remove", fontsize=8)
    axes.tick_params(labelsize=7)
    axes.legend(fontsize=7)
    figure.suptitle(title, fontsize=9)
    figure.tight_layout()
    figure.savefig(path)
    return path
