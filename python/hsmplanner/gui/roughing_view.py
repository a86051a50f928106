"""Coin scene of a roughing volume: its faces in the colour of their class (or of their slice), a little
transparent, drawn inset from where they lie, with their outlines and a legend in screen space.

The faces do not write depth: the part still hides what lies behind it, but the volume's own faces do not
hide each other, so the hub and the blade sides show through the stock's skin (the crossable faces, drawn
more transparent than the rest). Their colours are shaded under a light fixed to the model rather than
FreeCAD's headlight, so that every face keeps a colour one can name, whatever the view.

Why inset: most faces of the volume to remove are faces of the part (and the rest, of the stock). Drawn where
they lie, the two tessellations of one surface cross each other (each within its own deflection) and the
part shows through in blotches; on planes they lie exactly on each other and fight for every pixel. The
guide curve net is lifted along Z for that (view_providers.lift_over_the_part), but a volume's faces face
every way: here each vertex moves into its solid along the solid's normal there (the mean of its faces'
normals, so that faces stay joined at their edges), by more than both tessellations' deflection. Each solid
(a region, a sub-volume) is inset on its own, so neighbouring sub-volumes also stand apart. This is for the
eye only: the Shape, the picked faces and the saved file are untouched.
"""
import numpy as np
from pivy import coin

from ..app.progress import breathe
from .colors import FACE_CLASS_COLORS, FACE_CLASS_LABELS, SLICE_COLORS, SLICE_LABELS
from .feedmap import LEGEND_X
from .overlay import add_backing, add_labels, colored_quads, packed_rgba, screen_root, unpickable

WELD = 1e-6          # mm: tessellation vertices closer than this are one vertex
OUTLINE = (0.15, 0.15, 0.15)
SKIN_OPACITY = 0.35  # of the crossable faces, as a share of the others' opacity
# Faces are drawn in their colour, shaded under a light fixed to the model (not FreeCAD's headlight): a face
# seen at a grazing angle (a slot's overhanging wall) keeps a colour one can name.
LIGHT = np.array([-0.35, -0.45, 0.82]) / np.linalg.norm([-0.35, -0.45, 0.82])
SHADE_MIN = 0.6     # brightness of a face edge-on to that light


def solid_mesh(solid, deflection):
    """(vertices (n, 3), triangles (m, 3), face of each triangle (m,) 0-based in solid.Faces), vertices welded
    across the faces; triangles oriented out of the solid."""
    points, triangles, faces, offset = [], [], [], 0
    for index, face in enumerate(solid.Faces):
        breathe()  # a volume of many solids takes a second to draw: inside a recompute's dialog, events served
        vertices, facets = face.tessellate(deflection)
        if not facets:
            continue
        points.append(np.array([(v.x, v.y, v.z) for v in vertices], dtype=float))
        triangles.append(np.asarray(facets, dtype=np.int64) + offset)
        faces.append(np.full(len(facets), index, dtype=np.int64))
        offset += len(vertices)
    if not points:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64), np.zeros(0, dtype=np.int64)
    points = np.vstack(points)
    _, first, inverse = np.unique(np.round(points / WELD).astype(np.int64), axis=0, return_index=True,
                                  return_inverse=True)
    return points[first], inverse.reshape(-1)[np.vstack(triangles)], np.concatenate(faces)


def vertex_normals(vertices, triangles):
    """Unit normals at the vertices: the area-weighted mean of their triangles' (outward) normals."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    weighted = np.cross(b - a, c - a)
    normals = np.zeros_like(vertices)
    for k in range(3):
        np.add.at(normals, triangles[:, k], weighted)
    length = np.linalg.norm(normals, axis=1)
    return normals / np.where(length > 0.0, length, 1.0)[:, None]


def face_normals(vertices, triangles, faces):
    """Normals for the display: per triangle corner, the unit normal of its face at that vertex (the mean of
    the face's triangles there), so that a face is smooth and its edges sharp. (normals (k, 3), index of the
    normal of each corner (m, 3), face of each normal (k,))."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    weighted = np.cross(b - a, c - a)
    keys = faces[:, None] * len(vertices) + triangles
    unique, inverse = np.unique(keys.reshape(-1), return_inverse=True)
    normals = np.zeros((len(unique), 3))
    np.add.at(normals, inverse.reshape(-1), np.repeat(weighted, 3, axis=0))
    length = np.linalg.norm(normals, axis=1)
    normals = normals / np.where(length > 0.0, length, 1.0)[:, None]
    return normals, inverse.reshape(-1, 3), unique // len(vertices)


def outlines(triangles, faces):
    """Edges (k, 2) of the faces' outlines: edges of a face's triangles used once within that face (the seam
    of a periodic face is used twice once welded, so it is not drawn), each once."""
    edges = np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    edges.sort(axis=1)
    owners = np.concatenate([faces, faces, faces])
    keyed = np.column_stack([owners, edges])
    unique, counts = np.unique(keyed, axis=0, return_counts=True)
    return np.unique(unique[counts == 1][:, 1:], axis=0)


def inset_of(solid, inset):
    """The inset of a solid: `inset`, but at most a quarter of its thickness (about 2 V / A), so that a thin
    sub-volume does not turn inside out."""
    area = solid.Area
    return min(inset, 0.25 * 2.0 * solid.Volume / area) if area > 0 else 0.0


def volume_mesh(shape, deflection, inset):
    """The shape's solids tessellated and inset: (vertices, triangles, index in shape.Faces of each triangle,
    outline edges)."""
    all_vertices, all_triangles, all_faces, all_lines = [], [], [], []
    vertex_offset = face_offset = 0
    for solid in ([shape] if shape.ShapeType == "Solid" else shape.Solids):
        vertices, triangles, faces = solid_mesh(solid, deflection)
        if len(triangles):
            vertices = vertices - inset_of(solid, inset) * vertex_normals(vertices, triangles)
            all_vertices.append(vertices)
            all_triangles.append(triangles + vertex_offset)
            all_faces.append(faces + face_offset)
            all_lines.append(outlines(triangles, faces) + vertex_offset)
            vertex_offset += len(vertices)
        face_offset += len(solid.Faces)
    if not all_vertices:
        empty = np.zeros((0, 3))
        return empty, empty.astype(np.int64), np.zeros(0, dtype=np.int64), np.zeros((0, 2), dtype=np.int64)
    return np.vstack(all_vertices), np.vstack(all_triangles), np.concatenate(all_faces), np.vstack(all_lines)


def palette(sub_volumes):
    """Colours and legend labels: of the slices (alternating) or of the face classes."""
    return (SLICE_COLORS, SLICE_LABELS) if sub_volumes else (FACE_CLASS_COLORS, FACE_CLASS_LABELS)


def transparencies(transparency, sub_volumes):
    """Transparency of each colour of the palette: the crossable faces (the stock's skin, air to the tool) let
    the part's faces behind them show; the others, and the slices, have the view's Transparency."""
    if sub_volumes:
        return [float(transparency)] * len(SLICE_COLORS)
    skin = 1.0 - SKIN_OPACITY * (1.0 - float(transparency))
    return [skin] + [float(transparency)] * (len(FACE_CLASS_COLORS) - 1)


def volume_node(shape, codes, sub_volumes, deflection, inset, transparency):
    """The scene of a roughing volume's shape whose faces have `codes` (FaceColorIndex), and the face (0-based,
    in shape.Faces) of each of its triangles, which picking reports; (None, []) when there is nothing to draw.
    Only the faces can be picked (not the outlines, nor the legend)."""
    vertices, triangles, faces, lines = volume_mesh(shape, deflection, inset)
    if not len(triangles):
        return None, faces
    colors, labels = palette(sub_volumes)
    codes = np.asarray(codes, dtype=np.int64)
    root = coin.SoSeparator()
    root.setName("HsmRoughingVolume")
    coordinates = coin.SoCoordinate3()
    coordinates.point.setValues(0, len(vertices), vertices.tolist())
    root.addChild(coordinates)

    # Each corner gets its face's colour shaded by its normal under a fixed light, with its class's opacity.
    normals, normal_index, normal_faces = face_normals(vertices, triangles, faces)
    palette_index = (codes % len(colors))[normal_faces]
    shade = SHADE_MIN + (1.0 - SHADE_MIN) * np.abs(normals @ LIGHT)
    rgb = np.asarray(colors, dtype=float)[palette_index] * shade[:, None]
    alpha = 1.0 - np.asarray(transparencies(transparency, sub_volumes))[palette_index]
    properties = coin.SoVertexProperty()
    properties.vertex.setValues(0, len(vertices), vertices.tolist())
    properties.orderedRGBA.setValues(0, len(rgb), packed_rgba(rgb, alpha))
    properties.materialBinding = coin.SoMaterialBinding.PER_VERTEX_INDEXED
    surfaces = coin.SoSeparator()
    flat = coin.SoLightModel()
    flat.model = coin.SoLightModel.BASE_COLOR
    see_through = coin.SoDepthBuffer()
    see_through.write = False  # its faces do not hide each other: the skin does not hide the hub behind it
    hints = coin.SoShapeHints()
    hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE
    hints.shapeType = coin.SoShapeHints.UNKNOWN_SHAPE_TYPE  # no face culled: seen through, from inside too
    offset = coin.SoPolygonOffset()  # the outlines in front of their faces
    face_set = coin.SoIndexedFaceSet()
    face_set.setName("HsmRoughingFaces")
    face_set.vertexProperty = properties
    separators = np.full((len(triangles), 1), -1)
    indices = np.hstack([triangles, separators]).reshape(-1)
    face_set.coordIndex.setValues(0, len(indices), indices.tolist())
    corners = np.hstack([normal_index, separators]).reshape(-1)
    face_set.materialIndex.setValues(0, len(corners), corners.tolist())
    for node in (flat, see_through, hints, offset, face_set):
        surfaces.addChild(node)
    root.addChild(surfaces)

    edges = coin.SoSeparator()
    edges.addChild(unpickable())
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    colour = coin.SoBaseColor()
    colour.rgb = OUTLINE
    style = coin.SoDrawStyle()
    style.lineWidth = 1.0
    line_set = coin.SoIndexedLineSet()
    line_indices = np.column_stack([lines, np.full(len(lines), -1)]).reshape(-1)
    line_set.coordIndex.setValues(0, len(line_indices), line_indices.tolist())
    for node in (light, colour, style, line_set):
        edges.addChild(node)
    root.addChild(edges)
    root.addChild(legend_node(colors, labels))
    return root, faces


def legend_node(colors, labels, title="Roughing volume"):
    """Coloured squares with their labels at the left of the view (as the feed-rate legend, clear of 1.1's
    overlaid Tasks panel), in normalised screen coordinates (its own camera: it shows in screenshots and saved
    images)."""
    root = screen_root("HsmRoughingLegend")
    # top left, above the feed-rate, direction and stock legends (feedmap's spans, up to 0.47): all show
    (x0, x1), top, height, gap = LEGEND_X, 0.85, 0.07, 0.05
    rows = [top - k * (height + gap) for k in range(len(colors))]  # each square's top
    texts = [(label, x1 + 0.02, y - 0.5 * height - 0.015) for label, y in zip(labels, rows)] + \
        [(title, x0, top + 0.04)]
    add_backing(root, texts, x0, rows[-1] - height, top + 0.07)
    root.addChild(colored_quads([[(x0, y - height), (x1, y - height), (x1, y), (x0, y)] for y in rows], colors))
    add_labels(root, texts)
    return root
