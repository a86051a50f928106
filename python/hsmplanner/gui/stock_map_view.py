"""The stock a roughing strategy leaves on the part, drawn in the 3D view: the part's surface samples as points
coloured by the thickness left on them (viridis, as the study's pictures), with a legend in screen space."""
import numpy as np
from pivy import coin

from .feedmap import STOCK_LEGEND_SPAN as LEGEND_SPAN, legend_node
from .overlay import packed_rgba, unpickable


def thickness_colors(shares):
    """RGB rows of the study's colour map for shares of the scale in [0, 1]."""
    import matplotlib.cm as cm

    return cm.get_cmap("viridis")(np.clip(np.asarray(shares, dtype=float), 0.0, 1.0))[:, :3]


def stock_map_node(points, thickness, top_mm=None, title="stock left on the part"):
    """Points (N, 3) coloured by thickness (N,) over a scale from 0 to top_mm (default: the 99th percentile)."""
    points, thickness = np.asarray(points, dtype=float).reshape(-1, 3), np.asarray(thickness, dtype=float)
    top = top_mm or (float(np.percentile(thickness, 99)) if len(thickness) else 1.0) or 1.0
    root = coin.SoSeparator()
    root.addChild(unpickable())
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    style = coin.SoDrawStyle()
    style.pointSize = 3.0
    vertices = coin.SoVertexProperty()
    vertices.vertex.setValues(0, len(points), points.tolist())
    vertices.orderedRGBA.setValues(0, len(points), packed_rgba(thickness_colors(thickness / top)))
    vertices.materialBinding = coin.SoMaterialBinding.PER_VERTEX
    cloud = coin.SoPointSet()
    cloud.vertexProperty = vertices
    for node in (light, style, cloud):
        root.addChild(node)
    root.addChild(legend_node(0.0, top, "mm", title, digits=1, colors=thickness_colors, span=LEGEND_SPAN))
    return root
