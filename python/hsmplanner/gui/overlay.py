"""Coin pieces of our 3D-view overlays: colours packed for SoVertexProperty, and legends drawn in screen space
(their own orthographic camera, in normalised coordinates), so that they show in screenshots and saved
images. Used by the feed-rate map and the roughing volume."""
import numpy as np
from pivy import coin


def packed_rgba(rgb, alpha=None):
    """0xRRGGBBAA of each RGB row (0..1), opaque unless `alpha` (one per row) is given."""
    r, g, b = (np.clip(np.asarray(rgb, dtype=float).reshape(-1, 3), 0, 1) * 255).round().astype(np.uint32).T
    a = np.full(len(r), 255, dtype=np.uint32) if alpha is None else \
        (np.clip(np.asarray(alpha, dtype=float), 0, 1) * 255).round().astype(np.uint32)
    return [int(x) for x in (r << 24) | (g << 16) | (b << 8) | a]


def unpickable():
    style = coin.SoPickStyle()
    style.style = coin.SoPickStyle.UNPICKABLE
    return style


def screen_root(name=None):
    """A separator with its own camera over x, y in [-1, 1], flat colours and no depth test: what a legend is
    drawn in, over everything else."""
    root = coin.SoSeparator()
    if name:
        root.setName(name)
    root.addChild(unpickable())
    camera = coin.SoOrthographicCamera()
    camera.viewportMapping = coin.SoCamera.LEAVE_ALONE
    camera.position = (0.0, 0.0, 1.0)
    camera.height = 2.0
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    # No depth test: the colour bar and the text lie in the plane of the backing drawn before them, and would
    # fail the depth test against it (and against the model behind) unless an overlay above turned it off.
    on_top = coin.SoDepthBuffer()
    on_top.test = False
    for node in (camera, light, on_top):
        root.addChild(node)
    return root


def colored_quads(corners, colors):
    """Quadrilaterals (4 (x, y) corners each) in one colour each."""
    vertices = [(x, y, 0.0) for quad in corners for x, y in quad]
    properties = coin.SoVertexProperty()
    properties.vertex.setValues(0, len(vertices), vertices)
    rgba = packed_rgba(colors)
    properties.orderedRGBA.setValues(0, len(rgba), rgba)
    properties.materialBinding = coin.SoMaterialBinding.PER_FACE
    faces = coin.SoFaceSet()
    faces.vertexProperty = properties
    faces.numVertices.setValues(0, len(corners), [4] * len(corners))
    return faces


CHAR_WIDTH = 0.0135  # normalised width of one character of the 13 px font (7 px) in a view about 1000 px wide
BACKING = (0.2, 0.2, 0.23)


def add_backing(root, labels, edge, bottom, top, margin=0.02):
    """A dark panel behind a legend whose left-aligned `labels` (text, x, y) start right of `edge` (the bar's
    left side): white text stays readable on a white background (saveImage's "White", a user's light theme)."""
    right = max(x + CHAR_WIDTH * len(text) for text, x, _ in labels) + margin
    root.addChild(colored_quads([[(edge - margin, bottom - margin), (right, bottom - margin),
                                  (right, top + margin), (edge - margin, top + margin)]], [BACKING]))


def add_labels(root, labels, size=13):
    """White text, left-aligned at each (text, x, y)."""
    font = coin.SoFont()
    font.size = size
    root.addChild(font)
    text_colour = coin.SoBaseColor()
    text_colour.rgb = (1, 1, 1)
    root.addChild(text_colour)
    for text, x, y in labels:
        group = coin.SoSeparator()
        move = coin.SoTranslation()
        move.translation = (x, y, 0)
        label = coin.SoText2()
        label.string = text
        label.justification = coin.SoText2.LEFT
        group.addChild(move)
        group.addChild(label)
        root.addChild(group)
