"""Pictures written by examples and reports, and drawn in the GUI's panels. No FreeCAD needed.

Figures are made without pyplot (matplotlib.figure.Figure with an Agg canvas), so importing this module
never changes the matplotlib backend of the FreeCAD session it runs in.
"""
import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.cm import ScalarMappable
from matplotlib.colors import Normalize
from matplotlib.figure import Figure
from mpl_toolkits.mplot3d.art3d import Poly3DCollection


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

_LIGHT = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])


def _shaded(vertices, triangles, rgb):
    """Per-triangle colours with a simple directional light, so curvature reads in a still picture."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
    light = 0.35 + 0.65 * np.abs(normals @ _LIGHT)
    return np.clip(np.outer(light, rgb), 0.0, 1.0)


def plot_part_with_curves(meshes, curves, path, title, plan_marks=()):
    """3D view and plan view of a part with highlighted curves, saved as PNG.

    meshes: list of (vertices (N,3), triangles (M,3), rgb); curves: list of (points (N,3), colour, label);
    plan_marks: list of (x, y, text) annotated on the plan view.
    """
    figure = new_figure(14, 6)
    view3d = figure.add_subplot(1, 2, 1, projection="3d")
    for vertices, triangles, rgb in meshes:
        polygons = Poly3DCollection(vertices[triangles], facecolors=_shaded(vertices, triangles, rgb),
                                    edgecolors="none")
        view3d.add_collection3d(polygons)
    all_points = np.vstack([m[0] for m in meshes])
    lo, hi = all_points.min(axis=0), all_points.max(axis=0)
    view3d.set_xlim(lo[0], hi[0])
    view3d.set_ylim(lo[1], hi[1])
    view3d.set_zlim(lo[2], hi[2])
    view3d.set_box_aspect(hi - lo)
    view3d.view_init(elev=58, azim=-70)
    view3d.set_xlabel("X (mm)")
    view3d.set_ylabel("Y (mm)")
    view3d.set_zlabel("Z (mm)")

    plan = figure.add_subplot(1, 2, 2)
    for points, colour, label in curves:
        view3d.plot(points[:, 0], points[:, 1], points[:, 2] + 0.3, color=colour, linewidth=2.5, zorder=10)
        plan.plot(points[:, 0], points[:, 1], color=colour, linewidth=2, label=label)
    for x, y, text in plan_marks:
        plan.plot([x], [y], "ko", markersize=4)
        plan.annotate(text, (x, y), textcoords="offset points", xytext=(4, 6), fontsize=8)
    plan.set_aspect("equal")
    plan.grid(True, alpha=0.3)
    plan.set_xlabel("X (mm)")
    plan.set_ylabel("Y (mm)")
    plan.set_title("plan view of the boundaries")
    plan.legend(loc="upper right", fontsize=8)
    figure.suptitle(title)
    figure.subplots_adjust(left=0.02, right=0.98, wspace=0.12)
    figure.savefig(path)
    return path


def _area_colour(index):
    palette = matplotlib.colormaps["tab20"]
    return palette((2 * index + index // 10) % 20)


def plot_net_plan(axes, curves, areas, title, labels=None):
    """Plan view of a curve net: areas filled between consecutive curves, curves by role.

    curves: list of (points (N,3) ordered along the net's direction, role); areas: (lower, upper) index pairs.
    """
    for index, (lower, upper) in enumerate(areas):
        a, b = curves[lower][0], curves[upper][0]
        outline = np.vstack([a[:, :2], b[::-1, :2]])
        axes.fill(outline[:, 0], outline[:, 1], color=_area_colour(index), alpha=0.75, linewidth=0)
    styles = {"boundary": ("black", 1.8), "median": ("#d00000", 1.6), "intermediate": ("#1a4dd9", 0.9)}
    for points, role in curves:
        colour, width = styles.get(role, ("grey", 1.0))
        axes.plot(points[:, 0], points[:, 1], color=colour, linewidth=width)
    axes.set_aspect("equal")
    axes.set_title(title, fontsize=9)
    axes.tick_params(labelsize=7)


def save_net_grid(panels, path, title, columns=3):
    """One plan view per net: panels is a list of (curves, areas, title) for plot_net_plan."""
    rows = (len(panels) + columns - 1) // columns
    figure, grid = subplots(rows, columns, 5.2 * columns, 2.9 * rows)
    for axes, panel in zip(grid.flat, panels):
        plot_net_plan(axes, *panel)
    for axes in list(grid.flat)[len(panels):]:
        axes.axis("off")
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(path)
    return path


# --- feed-rate reports ------------------------------------------------------------------------------------

FEED_COLORMAP = "RdYlGn"  # red where the machine slows down, green at the programmed feed
FEED_CLASS_LABELS = ("<0.3", "0.3-0.5", "0.5-0.7", "0.7-0.9", "≥0.9")


def feed_colors(ratios):
    """RGB per value of reached / programmed feed (0..1), the same in PNG maps and in the 3D view."""
    cmap = matplotlib.colormaps[FEED_COLORMAP]
    return cmap(np.clip(np.asarray(ratios, dtype=float), 0.0, 1.0))[:, :3]


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


def relayout_at_each_draw(figure, **pads):
    """Tight layout computed again whenever the figure is drawn: a panel's canvas is resized after the plots
    are drawn (a layout computed once was made for another size, and cut the labels off at the edges)."""
    figure.set_layout_engine("tight", **{k: v for k, v in pads.items() if v is not None})


def draw_feed_histograms(figure, summary, stacked=False):
    """Feed classes (share of blocks, length, time) and block-length classes of a summary dict (JSON keys),
    side by side, or one above the other (`stacked`, for a narrow task panel)."""
    figure.clear()
    rows, columns = (2, 1) if stacked else (1, 2)
    left, right = figure.add_subplot(rows, columns, 1), figure.add_subplot(rows, columns, 2)
    classes = summary["feed_classes"]
    x = np.arange(5)
    for offset, (key, label, colour) in zip((-0.27, 0, 0.27), (
            ("share_of_blocks", "blocks", "#8da0cb"), ("share_of_length", "length", "#66c2a5"),
            ("share_of_time", "time", "#fc8d62"))):
        left.bar(x + offset, 100 * np.asarray(classes[key]), width=0.26, label=label, color=colour)
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
    edges = summary["block_length_classes"]["edges_mm"]
    labels = ["<%g" % edges[0]] + ["%g-%g" % (a, b) for a, b in zip(edges, edges[1:])] + ["≥%g" % edges[-1]]
    right.bar(np.arange(len(labels)), summary["block_length_classes"]["cutting_blocks"], color="#8da0cb")
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
            summary["machine"], summary["total_time_s"], summary["naive_time_s"], summary["time_over_naive"]),
            fontsize=10)
    relayout_at_each_draw(figure)


def save_feed_histograms(summary, path):
    figure = new_figure(11, 4.2)
    draw_feed_histograms(figure, summary)
    figure.savefig(path)
    return path


def save_feed_map(blocks, path, title):
    """Plan view of the path, each cutting block coloured by its mean reached / programmed feed."""
    from matplotlib.collections import LineCollection

    figure = new_figure(11, 6.5)
    axes = figure.add_subplot(1, 1, 1)
    ratios = blocks["mean_feed"] / np.maximum(blocks["programmed_feed"], 1e-12)
    lines = block_polylines(blocks)
    cutting = blocks["motion"] != 0
    segments = [p[:, :2] for p, cut in zip(lines, cutting) if cut]
    collection = LineCollection(segments, colors=feed_colors(ratios[cutting]), linewidths=2.0)
    axes.add_collection(collection)
    rapids = [p[:, :2] for p, cut in zip(lines, cutting) if not cut]
    axes.add_collection(LineCollection(rapids, colors="#999999", linewidths=0.5, linestyles="dotted"))
    axes.autoscale()
    axes.set_aspect("equal")
    axes.set_xlabel("X (mm)")
    axes.set_ylabel("Y (mm)")
    scalar = ScalarMappable(cmap=FEED_COLORMAP, norm=Normalize(0, 100))
    figure.colorbar(scalar, ax=axes, label="mean reached feed, % of programmed", shrink=0.8)
    axes.set_title(title, fontsize=10)
    figure.tight_layout()
    figure.savefig(path)
    return path


def save_strategy_times(times, feeds, path):
    """Grouped bars: simulated machining time of each strategy at each programmed feed."""
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
    axes.set_title("Finishing the master bottom feature on the Mikron UCP 710 / 840D model")
    figure.tight_layout()
    figure.savefig(path)
    return path


# --- machining direction ------------------------------------------------------------------------------------

def draw_directions_over_feeds(axes, rows, compact=False):
    """The paper's Fig. 10 on `axes`: acceptable directions (squares) and the optimum (line) against the
    programmed feed. rows: (feed mm/min, optimal angle, acceptable angles)."""
    for feed, optimum, acceptable in rows:
        axes.plot(np.full(len(acceptable), feed / 1000.0), acceptable, "s", color="#9ecae1", markersize=3)
    axes.plot([r[0] / 1000.0 for r in rows], [r[1] for r in rows], "o-", color="#d62728", label="optimal direction")
    axes.plot([], [], "s", color="#9ecae1", label="acceptable directions")
    axes.set_xlabel("programmed feed (m/min)")
    axes.set_ylabel("direction θ from X (°)" if compact else "machining direction θ from X (°)")
    axes.set_ylim(-5, 185)
    axes.set_yticks(range(0, 181, 45 if compact else 30))
    axes.grid(True, alpha=0.3)
    _direction_legend(axes, compact, loc="center left")


def save_directions_over_feeds(rows, path, title):
    figure = new_figure(9, 5)
    axes = figure.add_subplot(1, 1, 1)
    draw_directions_over_feeds(axes, rows)
    axes.set_title(title, fontsize=10)
    figure.tight_layout()
    figure.savefig(path)
    return path


def _spread(plan_points, count):
    """Indices of about `count` of the points, one per cell of a square grid over their plan: evenly spread
    (every k-th point of a face's sample list lines up in streaks)."""
    side = max(1, int(np.sqrt(count)))
    low, span = plan_points.min(axis=0), np.maximum(np.ptp(plan_points, axis=0), 1e-9)
    cells = np.minimum((side * (plan_points - low) / span).astype(int), side - 1)
    return np.unique(cells[:, 0] * side + cells[:, 1], return_index=True)[1]


def draw_direction_map(axes, points, angles_deg, values, optimal_deg=None, arrows=600):
    """Strokes of the best local direction at (about `arrows` of) the sample points, coloured by G_pmax in the
    3D view's colours (red: the surface is slow to finish there), in plan."""
    points, angles, values = np.asarray(points), np.radians(np.asarray(angles_deg)), np.asarray(values)
    pick = _spread(points[:, :2], arrows)
    p, a, v = points[pick], angles[pick], values[pick]
    span = float(np.ptp(points[:, 0]) + np.ptp(points[:, 1])) / 2 or 1.0
    length = 0.6 * span / np.sqrt(len(p))
    quiver = axes.quiver(p[:, 0], p[:, 1], np.cos(a), np.sin(a), v, angles="xy", scale_units="xy",
                         scale=1.0 / length, pivot="middle", headwidth=0, headlength=0, headaxislength=0,
                         width=0.1 / np.sqrt(arrows), cmap=FEED_COLORMAP)  # as in the 3D view
    if optimal_deg is not None:
        c = points[:, :2].mean(axis=0)
        d = np.array([np.cos(np.radians(optimal_deg)), np.sin(np.radians(optimal_deg))]) * span * 0.45
        axes.annotate("", xy=c + d, xytext=c - d, arrowprops=dict(arrowstyle="<->", color="#d62728", lw=2.5))
    axes.set_aspect("equal")
    return quiver


# A task panel is about 230 px wide: there the plots take small type, fewer ticks and their legends below.
_COMPACT_FONT = 7


def _direction_legend(axes, compact, handles=None, labels=None, loc="best"):
    if handles is None:
        handles, labels = axes.get_legend_handles_labels()
    if compact:
        axes.legend(handles, labels, fontsize=_COMPACT_FONT, loc="upper left", bbox_to_anchor=(-0.25, -0.22),
                    frameon=False, borderaxespad=0.0, handlelength=1.5)
    else:
        axes.legend(handles, labels, fontsize=8, loc=loc)


def _compact_axes(*axes_list):
    for axes in axes_list:
        axes.tick_params(labelsize=_COMPACT_FONT)
        axes.xaxis.label.set_fontsize(_COMPACT_FONT + 1)
        axes.yaxis.label.set_fontsize(_COMPACT_FONT + 1)


# Why the predicted time dips: each plane keeps the smallest step along it, so planes that run along a feature
# (valleys) keep their own step each, and a few degrees off they cross it and take its worst.
PREDICTED_TIME_NOTE = "a plane keeps the smallest step along it: the time dips where planes run along a feature"


def draw_direction_rate(axes, result, compact=False):
    """The beams' intersection: min over the points of G_p/G_pmax per direction, the optimum marked, and the
    predicted time of planes per direction on a second scale."""
    axes.plot(result.angles_deg, result.rate, color="#1f77b4")
    axes.axvline(result.angle_deg, color="#d62728", label="beams: θ* %.0f°, α* %.3f" % (result.angle_deg, result.alpha))
    axes.axhline(result.reported_alpha, color="grey", linestyle=":", label="α = %.2f" % result.reported_alpha)
    axes.set_ylim(0, 1.05)
    axes.set_xlabel("direction θ from X (°)")
    axes.set_ylabel("min G_p / G_pmax" if compact else "min over the points of G_p / G_pmax")
    axes.set_xlim(0, 180)
    axes.set_xticks(range(0, 181, 45 if compact else 30))
    times = np.asarray(result.predicted_time_s, dtype=float)
    handles, labels = axes.get_legend_handles_labels()
    twin = None
    if np.isfinite(times).any():
        twin = axes.twinx()
        twin.plot(result.angles_deg, np.where(np.isfinite(times), times, np.nan), "--", color="#9467bd")
        twin.set_ylabel("predicted time (s)" if compact else "predicted cutting time (s)", color="#9467bd")
        if not compact:  # the panel says it in the plot's tool tip
            axes.annotate(PREDICTED_TIME_NOTE, xy=(0.5, 1.01), xycoords="axes fraction", ha="center", va="bottom",
                          fontsize=7, color="#9467bd")
        line = axes.axvline(result.fastest_angle_deg, color="#9467bd", linestyle="--")
        handles.append(line)
        labels.append("least predicted time: %.0f°" % result.fastest_angle_deg)
    if compact:
        _compact_axes(*[a for a in (axes, twin) if a is not None])
    _direction_legend(axes, compact, handles, labels, loc="lower left")


def draw_direction_report(figure, result, title, scan=None, validation=None, stacked=False):
    """Rate per direction, then the simulated validation, the feed scan or the map of local best directions:
    side by side, or one above the other in small type with legends below (`stacked`, for a task panel)."""
    figure.clear()
    rows, columns = (2, 1) if stacked else (1, 2)
    left, right = figure.add_subplot(rows, columns, 1), figure.add_subplot(rows, columns, 2)
    draw_direction_rate(left, result, compact=stacked)
    title_size = 8 if stacked else 9
    if validation:
        draw_direction_validation(right, validation, [("directional beams", result.angle_deg),
                                                      ("least predicted time", result.fastest_angle_deg)], stacked)
        right.set_title("parallel planes simulated on the machine", fontsize=title_size)
    elif scan:
        draw_directions_over_feeds(right, scan, stacked)
        right.set_title("directions against the programmed feed", fontsize=title_size)
    else:
        quiver = draw_direction_map(right, result.points, result.best_angle_deg, result.fitness_max, result.angle_deg,
                                    arrows=150 if stacked else 600)  # fewer, longer strokes in a small map
        # Plain ticks: matplotlib's offset notation read "1e-6+1.1999e-1" for a face of uniform G_pmax.
        bar = figure.colorbar(quiver, ax=right, label="G_pmax (mm²)", format="%.4g",
                              orientation="horizontal" if stacked else "vertical", pad=0.2 if stacked else 0.05)
        bar.ax.tick_params(labelsize=_COMPACT_FONT)
        right.set_title("best local direction\n(red arrow: the optimum)", fontsize=title_size)
    if stacked:
        _compact_axes(right)
    if title:
        figure.suptitle(title, fontsize=10)
    relayout_at_each_draw(figure, h_pad=1.0 if stacked else None)


def save_direction_report(result, path, title, scan=None, validation=None):
    figure = new_figure(13, 5)
    draw_direction_report(figure, result, title, scan, validation)
    figure.savefig(path)
    return path


def draw_direction_validation(axes, rows, marks=(), compact=False):
    """Simulated machining time of parallel planes against their angle (rows of simulated_directions), with
    length/feed, the fastest marked, and `marks`: (label, angle) of the criteria's choices."""
    angles = [row["angle_deg"] for row in rows]
    simulated = [row["simulated_s"] for row in rows]
    axes.plot(angles, simulated, "o-", label="simulated (feed-rate simulator)")
    axes.plot(angles, [row["length_over_feed_s"] for row in rows], "s--", color="grey", label="length / feed")
    colours = ["#d62728", "#9467bd", "#8c564b"]
    for (label, angle), colour in zip(marks, colours):
        axes.axvline(angle, color=colour, label="%s: %.0f°" % (label, angle))
    best = angles[int(np.argmin(simulated))]
    axes.axvline(best, color="#2ca02c", linestyle=":", lw=2, label="fastest simulated: %.0f° (%.1f s)"
                 % (best, min(simulated)))
    axes.set_xlabel("direction of the planes θ from X (°)")
    axes.set_ylabel("machining time (s)")
    axes.set_xticks(range(0, 181, 45 if compact else 30))
    _direction_legend(axes, compact)
    axes.grid(True, alpha=0.3)


def save_direction_validation(rows, marks, path, title):
    figure = new_figure(9, 5)
    axes = figure.add_subplot(1, 1, 1)
    draw_direction_validation(axes, rows, marks)
    axes.set_title(title, fontsize=10)
    figure.tight_layout()
    figure.savefig(path)
    return path
