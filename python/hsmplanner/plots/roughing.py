"""Pictures of 5-axis roughing part 1: the volume to remove with its faces coloured by class, the sub-volumes
of each strategy in alternating colours, and the volumes of the slices (how even the layers are).

Shapes come in as triangle meshes ((N, 3) points, (M, 3) vertex indices), so that these plots need neither
FreeCAD nor the core: the example tessellates with FreeCAD, the tests may pass any mesh."""
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from .common import new_figure
from .palette import FACE_CLASS_COLORS, SLICE_COLORS

FACE_CLASS_LABELS = {"crossable": "crossable (stock skin)", "facing_crossable": "facing crossable (hub, floor)",
                     "not_crossable": "not crossable (blade sides, walls)"}


def slice_color(index):
    return SLICE_COLORS[index % 2]


def _draw_meshes(axes, meshes, colors, alpha=0.85):
    """Triangle meshes (points, triangles) in their colours on 3D axes, with equal scales."""
    low, high = np.full(3, np.inf), np.full(3, -np.inf)
    for (points, triangles), color in zip(meshes, colors):
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        triangles = np.asarray(triangles, dtype=int).reshape(-1, 3)
        if not len(triangles):
            continue
        axes.add_collection3d(Poly3DCollection(points[triangles], facecolor=color, edgecolor=(0, 0, 0, 0.08),
                                               linewidth=0.2, alpha=alpha))
        low, high = np.minimum(low, points.min(axis=0)), np.maximum(high, points.max(axis=0))
    if np.all(np.isfinite(low)):
        centre, half = 0.5 * (low + high), 0.5 * float(np.max(high - low))
        for setter, c in zip((axes.set_xlim, axes.set_ylim, axes.set_zlim), centre):
            setter(c - half, c + half)
    axes.set_xlabel("X mm", fontsize=7)
    axes.set_ylabel("Y mm", fontsize=7)
    axes.set_zlabel("Z mm", fontsize=7)
    axes.tick_params(labelsize=6)


def save_face_classes(meshes, classes, path, title, view=(28, -60)):
    """The faces (one mesh each) coloured by class (names of FACE_CLASS_COLORS), with a legend."""
    figure = new_figure(6.4, 5.6)
    axes = figure.add_subplot(1, 1, 1, projection="3d")
    _draw_meshes(axes, meshes, [FACE_CLASS_COLORS[c] for c in classes])
    axes.view_init(*view)
    from matplotlib.patches import Patch

    present = [c for c in FACE_CLASS_COLORS if c in set(classes)]
    figure.legend(handles=[Patch(color=FACE_CLASS_COLORS[c], label=FACE_CLASS_LABELS[c]) for c in present],
                  loc="lower center", ncol=1, fontsize=8, frameon=False)
    figure.suptitle(title, fontsize=9)
    figure.subplots_adjust(left=0.0, right=1.0, top=0.92, bottom=0.16)
    figure.savefig(path)


def save_partitions(partitions, path, title, view=(28, -60)):
    """One 3D panel per strategy: {label: [(slice, mesh), …]}, slices in alternating colours."""
    labels = list(partitions)
    columns = min(3, len(labels))
    rows = (len(labels) + columns - 1) // columns
    figure = new_figure(4.2 * columns, 3.9 * rows)
    for k, label in enumerate(labels):
        axes = figure.add_subplot(rows, columns, k + 1, projection="3d")
        pieces = partitions[label]
        _draw_meshes(axes, [mesh for _, mesh in pieces], [slice_color(s) for s, _ in pieces])
        axes.view_init(*view)
        axes.set_title("%s: %d sub-volumes" % (label, len({s for s, _ in pieces})), fontsize=8)
    figure.suptitle(title, fontsize=9)
    figure.subplots_adjust(left=0.0, right=1.0, top=0.9, bottom=0.02, wspace=0.05, hspace=0.12)
    figure.savefig(path)


def save_slice_volumes(rows, path, title):
    """Bars of each slice's volume per strategy: rows of (label, [volume of slice 0, 1, …] in mm³)."""
    figure = new_figure(7.0, 0.6 + 1.25 * len(rows))
    for k, (label, volumes) in enumerate(rows):
        axes = figure.add_subplot(len(rows), 1, k + 1)
        volumes = np.asarray(volumes, dtype=float) / 1000.0
        axes.bar(np.arange(len(volumes)), volumes, color=[slice_color(i) for i in range(len(volumes))])
        axes.set_ylabel("cm³", fontsize=7)
        axes.set_title(label, fontsize=8, loc="left")
        axes.tick_params(labelsize=7)
        axes.set_xticks(np.arange(len(volumes)))
        axes.set_xlim(-0.6, max(len(r[1]) for r in rows) - 0.4)
    figure.axes[-1].set_xlabel("slice, from the reference surface inwards", fontsize=8)
    figure.suptitle(title, fontsize=9)
    figure.set_layout_engine("tight")
    figure.savefig(path)


def save_sweeps(sweeps, path, title, view=(28, -60), axis_every_mm=6.0, axis_length_mm=5.0):
    """One 3D panel per sweep: [(label, SweepResult), …]; cuts coloured by level, ramps and links grey, rapids
    dotted, and a tick of the tool axis every few millimetres of cutting (4- and 5-axis paths show it turn)."""
    from hsmplanner.roughing import MOVE_KINDS

    cut, ramp, link, rapid = (MOVE_KINDS.index(k) for k in ("cut", "ramp", "link", "rapid"))
    columns = min(3, len(sweeps))
    rows = (len(sweeps) + columns - 1) // columns
    figure = new_figure(4.6 * columns, 4.2 * rows)
    for k, (label, paths) in enumerate(sweeps):
        axes = figure.add_subplot(rows, columns, k + 1, projection="3d")
        moves = paths.moves
        tips, kinds, levels = moves["tip"], moves["kind"], moves["sub_volume"]
        travelled = 0.0
        for i in range(1, len(tips)):
            a, b = tips[i - 1], tips[i]
            segment = np.vstack([a, b])
            if kinds[i] == cut:
                axes.plot(*segment.T, color=slice_color(max(0, levels[i])), linewidth=0.9)
                travelled += np.linalg.norm(b - a)
                if travelled >= axis_every_mm:
                    travelled = 0.0
                    tick = np.vstack([b, b + axis_length_mm * moves["axis"][i]])
                    axes.plot(*tick.T, color="#555555", linewidth=0.5)
            elif kinds[i] in (ramp, link):
                axes.plot(*segment.T, color="#888888", linewidth=0.6)
            elif kinds[i] == rapid:
                axes.plot(*segment.T, color="#bbbbbb", linewidth=0.4, linestyle=":")
        axes.view_init(*view)
        axes.set_title("%s: %d passes, %.0f mm cutting" % (label, len(paths.passes), paths.cutting_length), fontsize=8)
        axes.tick_params(labelsize=6)
    figure.suptitle(title, fontsize=9)
    figure.subplots_adjust(left=0.0, right=1.0, top=0.9, bottom=0.02, wspace=0.05, hspace=0.12)
    figure.savefig(path)
    return path
