"""Pictures of curve nets and of the part with its curves (examples and reports)."""
import matplotlib
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from .common import new_figure, subplots

_LIGHT = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])


def _shaded(vertices, triangles, rgb):
    """Per-triangle colours with a simple directional light, so curvature reads in a still picture."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
    light = 0.35 + 0.65 * np.abs(normals @ _LIGHT)
    return np.clip(np.outer(light, rgb), 0.0, 1.0)


def plot_part_with_curves(meshes, curves, path, title, plan_marks=(), plan_title="plan view of the curves"):
    """3D view and plan view of a part with highlighted curves, saved as PNG.

    meshes: list of (vertices (N,3), triangles (M,3), rgb); curves: list of (points (N,3), colour, label);
    plan_marks: list of (x, y, text) annotated on the plan view; plan_title: the plan view's title.
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
    plan.set_title(plan_title)
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
