"""The tool tip's path of an operation whose moves carry A/B/C, drawn where the tip cuts.

FreeCAD's Path view provider turns each move's X Y Z by its A, B, C words (its PathSegmentWalker: a rotation
of yaw -C, pitch -B, roll -A about the path's Center) and sweeps an arc for each change of angle, as if X Y Z
were taken on a turning table. Our commands' X Y Z are the tool tip in the workpiece frame already
(app/roughing/commands.sweep_commands; with TCP: 840D TRAORI, LinuxCNC's TCP kinematics), so FreeCAD drew a
tilted path beside the part while its tool-axis ticks sat in the slot.

TipPathView gives an operation's view provider a display mode of its own, "Tip path": each move drawn as the
straight line the tip follows under TCP, feeds in the view's NormalColor and rapids in CAM's rapid colour (the
colours FreeCAD's drawing uses), LineWidth as FreeCAD's. There is one edge per move, in the order FreeCAD
numbers its own, so that a pick names the command as FreeCAD's drawing does ("12 G1 X…") and the Selection
and CAM's commands see the operation as ever. Only the drawing changes: the Path, which posts, Inspect and the
Job read, is untouched. A path without rotary words keeps FreeCAD's own mode ("Waypoints").
"""
import numpy as np
from pivy import coin

TIP_PATH_MODE = "Tip path"
FREECAD_MODE = "Waypoints"
ROTARY_WORDS = ("A", "B", "C")
CAM_PREFERENCES = "User parameter:BaseApp/Preferences/Mod/CAM"
DEFAULT_RAPID_RGBA = 2852126975  # CAM's own default rapid colour, 0xRRGGBBAA (170, 0, 0)


def turns_the_tool(commands):
    """Whether FreeCAD would turn some move of `commands` by a rotary word (any A, B or C)."""
    return any(word in command.Parameters for command in commands for word in ROTARY_WORDS)


def tip_edges(tips):
    """(n, 2, 3) segments, one per move: from the tip before the move to the move's tip. The first move starts
    where it ends (FreeCAD draws it from its StartPosition, a point the program never states)."""
    tips = np.asarray(tips, dtype=float).reshape(-1, 3)
    starts = np.vstack([tips[:1], tips[:-1]]) if len(tips) else tips
    return np.stack([starts, tips], axis=1)


def rapid_rgb():
    """CAM's colour of rapid moves (its preference, FreeCAD's default when unset), RGB in 0..1."""
    import FreeCAD

    value = FreeCAD.ParamGet(CAM_PREFERENCES).GetUnsigned("DefaultRapidPathColor", DEFAULT_RAPID_RGBA)
    return tuple(((value >> shift) & 0xFF) / 255.0 for shift in (24, 16, 8))


def edge_set():
    """FreeCAD's own edge set (Part's SoBrepEdgeSet: it shows a preselected or selected edge highlighted, as on
    FreeCAD's path drawing) when the Part GUI has registered it, Coin's indexed line set otherwise."""
    kind = coin.SoType.fromName(coin.SbName("SoBrepEdgeSet"))
    if kind.isBad() or not kind.canCreateInstance():
        return coin.SoIndexedLineSet()
    return coin.cast(kind.createInstance(), "SoIndexedLineSet")


def tip_path_node(edges, feeds, feed_rgb, rapid_rgb_, width):
    """The scene of `edges` (n, 2, 3): edge k in `feed_rgb` where feeds[k], else in `rapid_rgb_`; lines `width`
    pixels wide; picking reports edge k as line k."""
    root = coin.SoSeparator()
    root.setName("HsmTipPath")
    material = coin.SoMaterial()
    colours = [tuple(feed_rgb) if feed else tuple(rapid_rgb_) for feed in feeds]
    material.diffuseColor.setValues(0, len(colours), colours)
    binding = coin.SoMaterialBinding()
    binding.value = coin.SoMaterialBinding.PER_PART
    style = coin.SoDrawStyle()
    style.lineWidth = float(width)
    coordinates = coin.SoCoordinate3()
    points = np.asarray(edges, dtype=float).reshape(-1, 3)
    coordinates.point.setValues(0, len(points), points.tolist())
    lines = edge_set()
    lines.setName("HsmTipPathEdges")
    pairs = np.arange(len(points), dtype=np.int64).reshape(-1, 2)
    indices = np.column_stack([pairs, np.full(len(pairs), -1)]).reshape(-1)
    lines.coordIndex.setValues(0, len(indices), indices.tolist())
    for node in (material, binding, style, coordinates, lines):
        root.addChild(node)
    return root


def element_name(number, command):
    """FreeCAD's name of a picked path command: its 1-based number, its G-code, '.' written ','."""
    return ("%d %s" % (number + 1, command.toGCode())).replace(".", ",")


class TipPathView:
    """Mixed into a Path operation's view provider (before FreeCAD's class): the "Tip path" display mode, chosen
    whenever the Path has rotary words. Its methods chain to the next class's."""

    def attach(self, vobj):
        super().attach(vobj)
        self.tip_root = coin.SoSeparator()
        self.tip_moves = np.zeros(0, dtype=np.int64)  # command index of each drawn edge
        vobj.addDisplayMode(self.tip_root, TIP_PATH_MODE)

    def getDisplayModes(self, vobj):
        return [TIP_PATH_MODE]  # FreeCAD adds its own "Waypoints"

    def setDisplayMode(self, mode):
        return mode

    def updateData(self, obj, prop):
        super().updateData(obj, prop)
        if prop == "Path":
            self.draw_tip_path(obj)

    def onChanged(self, vobj, prop):
        parent = getattr(super(), "onChanged", None)
        if parent is not None:
            parent(vobj, prop)
        if prop in ("NormalColor", "LineWidth") and getattr(vobj, "Object", None) is not None:
            self.draw_tip_path(vobj.Object)

    def draw_tip_path(self, obj):
        """Draws the Path's moves where the tip goes, and shows them instead of FreeCAD's drawing when FreeCAD
        would turn them (rotary words); FreeCAD's own drawing otherwise."""
        from hsmplanner.app.roughing.commands import program_moves

        root, vobj = getattr(self, "tip_root", None), getattr(obj, "ViewObject", None)
        if root is None or vobj is None:
            return
        root.removeAllChildren()
        commands = obj.Path.Commands
        self.tip_moves, tips, _, feeds = program_moves(commands)
        if len(tips):
            root.addChild(tip_path_node(tip_edges(tips), feeds, vobj.NormalColor[:3], rapid_rgb(), vobj.LineWidth))
        mode = TIP_PATH_MODE if turns_the_tool(commands) else FREECAD_MODE
        if vobj.DisplayMode != mode:
            vobj.DisplayMode = mode

    def showing_tip_path(self):
        vobj = getattr(getattr(self, "Object", None), "ViewObject", None)
        return vobj is not None and vobj.DisplayMode == TIP_PATH_MODE

    def getElement(self, detail):
        """The command of a picked edge of the tip path; FreeCAD's answer in its own mode."""
        if not self.showing_tip_path():
            raise NotImplementedError  # FreeCAD's view provider names what its drawing picked
        if not detail.isOfType(coin.SoLineDetail.getClassTypeId()):
            return ""
        edge = coin.cast(detail, "SoLineDetail").getLineIndex()
        if not 0 <= edge < len(self.tip_moves):
            return ""
        number = int(self.tip_moves[edge])
        return element_name(number, self.Object.Path.Commands[number])

    def getDetail(self, name):
        """The edge of a command named as getElement names it (to highlight what the Selection holds)."""
        if not self.showing_tip_path():
            raise NotImplementedError
        try:
            number = int(str(name).split(" ", 1)[0]) - 1
        except ValueError:
            return None
        edges = np.flatnonzero(self.tip_moves == number)
        if not len(edges):
            return None
        detail = coin.SoLineDetail()
        detail.setLineIndex(int(edges[0]))
        return detail
