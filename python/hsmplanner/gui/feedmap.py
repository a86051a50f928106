"""Coin scene of a feed-rate map: each block of the path in the colour of its reached feed, rapids dotted,
and a legend drawn in screen space (its own camera), so that it shows in screenshots and saved images."""
import numpy as np
from pivy import coin

from hsmplanner.plots.common import feed_colors
from hsmplanner.plots.feedrate import block_polylines

from .overlay import add_backing, add_labels, colored_quads, packed_rgba, screen_root

LEGEND_STEPS = 20
LEGEND_TICKS = 4


def line_set(polylines, colors=None, width=2.0, pattern=None):
    """Polylines in one colour each (RGB rows), or grey; lit by their own colour only."""
    group = coin.SoSeparator()
    style = coin.SoDrawStyle()
    style.lineWidth = width
    if pattern:
        style.linePattern = pattern
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    vertices = coin.SoVertexProperty()
    points = np.vstack(polylines) if polylines else np.zeros((0, 3))
    vertices.vertex.setValues(0, len(points), points.tolist())
    if colors is None:
        vertices.orderedRGBA.setValue(0x999999FF)
        vertices.materialBinding = coin.SoMaterialBinding.OVERALL
    else:
        vertices.orderedRGBA.setValues(0, len(colors), packed_rgba(colors))
        vertices.materialBinding = coin.SoMaterialBinding.PER_FACE  # one colour per polyline (block)
    lines = coin.SoLineSet()
    lines.vertexProperty = vertices
    lines.numVertices.setValues(0, len(polylines), [len(p) for p in polylines])
    for node in (light, style, lines):
        group.addChild(node)
    return group


def block_colors(blocks, color_by):
    """RGB per block and the legend's (low, high, unit) for `color_by` ('Share…' or 'Feed (mm/min)').

    In mm/min the scale tops at the highest programmed cutting feed: rapids (drawn apart, dotted) would set
    it at the machine's rapid speed and paint every cut at F red."""
    if color_by.startswith("Feed"):
        cutting = blocks["motion"] != 0
        programmed = blocks["programmed_feed"][cutting] if np.any(cutting) else blocks["programmed_feed"]
        top = max(float(np.max(programmed)) * 60.0, 1e-9) if len(programmed) else 1.0
        return feed_colors(blocks["mean_feed"] * 60.0 / top), (0.0, top, "mm/min")
    ratios = blocks["mean_feed"] / np.maximum(blocks["programmed_feed"], 1e-12)
    return feed_colors(ratios), (0.0, 100.0, "% of F")


def map_node(blocks, color_by):
    """The map is an overlay: drawn over the part without the depth test. The tool-tip path runs below the
    face wherever the ball touches it off its tip (on every slope), so with the depth test the part hid the
    map in grey blotches."""
    root = coin.SoSeparator()
    overlay = coin.SoDepthBuffer()
    overlay.test = False
    root.addChild(overlay)
    lines = block_polylines(blocks)
    cutting = blocks["motion"] != 0
    colors, scale = block_colors(blocks, color_by)
    cut = [p for p, c in zip(lines, cutting) if c]
    if cut:
        root.addChild(line_set(cut, colors[cutting], width=2.5))
    rapid = [p for p, c in zip(lines, cutting) if not c]
    if rapid:
        root.addChild(line_set(rapid, None, width=1.0, pattern=0xF0F0))
    root.addChild(legend_node(*scale))
    return root


# At the left edge of the view, the labels right of the bar: FreeCAD 1.1's Tasks panel overlays the view's
# right side while a panel is open.
LEGEND_X = (-0.92, -0.86)
# Each kind of colour-bar legend in a band of its own down the left edge (y from -1 at the bottom to 1 at the
# top), so that a feed map, a machining-direction map and a stock map shown together do not draw over each
# other or over the model; a Roughing volume's legend is above them (roughing_view.legend_node).
LEGEND_SPAN = (-0.02, 0.38)            # the feed-rate map's
DIRECTION_LEGEND_SPAN = (-0.5, -0.14)  # the machining direction's
STOCK_LEGEND_SPAN = (-0.93, -0.62)     # the stock left's


def tick_texts(values, digits):
    """The numbers of a scale's ticks, rounded to `digits` decimals or as many more as it takes for ticks of
    different values to read differently (a narrow scale: 0.04271 … 0.04279, not 0.0427 five times)."""
    for places in range(digits, digits + 9):
        texts = ["%g" % round(v, places) for v in values]
        if len(set(texts)) == len(set(values)):
            return texts
    return ["%.6g" % v for v in values]


def legend_node(low, high, unit, title="mean reached feed", digits=0, colors=feed_colors, span=LEGEND_SPAN):
    """A vertical colour bar with labels at the left of the view, in normalised screen coordinates, from
    span[0] to span[1] in y; `colors(shares)` gives the RGB rows of shares of the scale in [0, 1]."""
    root = screen_root()
    (x0, x1), (y0, y1) = LEGEND_X, span
    corners, corners_colors = [], []
    for k in range(LEGEND_STEPS):
        a, b = y0 + (y1 - y0) * k / LEGEND_STEPS, y0 + (y1 - y0) * (k + 1) / LEGEND_STEPS
        corners.append([(x0, a), (x1, a), (x1, b), (x0, b)])
        corners_colors.append(colors([(k + 0.5) / LEGEND_STEPS])[0])
    ticks = [k / LEGEND_TICKS for k in range(LEGEND_TICKS + 1)]  # the scale's numbers, every quarter
    texts = tick_texts([low + f * (high - low) for f in ticks], digits)
    labels = [("%s %s" % (text, unit), x1 + 0.02, y0 + f * (y1 - y0) - 0.02)
              for text, f in zip(texts, ticks)] + [(title, x0, y1 + 0.06)]
    add_backing(root, labels, x0, y0 - 0.03, y1 + 0.09)
    root.addChild(colored_quads(corners, corners_colors))
    add_labels(root, labels)
    return root
