"""Machining direction: the rate of the directional beams per direction, the optimum against the programmed
feed, the map of local best directions, and the simulated validation of parallel planes; for reports
(save_*) and the direction panel (draw_*, `compact`/`stacked` for its width)."""
import numpy as np

from .common import FEED_COLORMAP, new_figure, relayout_at_each_draw


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
