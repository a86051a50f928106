"""GUI test: a 5-axis Volume roughing operation (S3 on the slanted slot block, A tilted) drawn where its tool tip
goes. FreeCAD's own drawing turns each move by its A/C words (off the part); the operation's "Tip path" mode
draws the moves as written: the drawn box is the program's tip box, the tool-axis ticks lie in it, a click on
the path picks the operation and names the command under the cursor. The same operation on a 3-axis machine
(3+2, no rotary words) keeps FreeCAD's drawing, and the mode survives saving and reopening."""
import os
import sys
import tempfile

import FreeCAD
import FreeCADGui as Gui
import numpy as np
from pivy import coin

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import GuiRun, show_only  # noqa: E402

run = GuiRun()
state = {}
TOLERANCE_MM = 0.01    # float32 coordinates of a ~100 mm part, and nothing more
PICK_PIXELS = 3.0      # a click names the command whose edge passes this close to the cursor
FIVE_AXIS, THREE_AXIS = "mikron-ucp710-ac-840d", "mikron-ucp710-840d"


def program_tips(commands):
    """(n, 3) tips and (n,) feed flags of the G0/G1 moves, each word modal, read from the commands as a post
    reads them (independently of the view provider's own reading)."""
    position, tips, feeds = {"X": 0.0, "Y": 0.0, "Z": 0.0}, [], []
    for command in commands:
        if command.Name in ("G0", "G1"):
            position.update({k: v for k, v in command.Parameters.items() if k in position})
            tips.append((position["X"], position["Y"], position["Z"]))
            feeds.append(command.Name == "G1")
    return np.asarray(tips), np.asarray(feeds)


def viewport():
    """The 3D view's viewport, from its size: FreeCAD 1.1.3 crashes when a document whose view was asked for its
    viewer (ActiveView.getViewer()) closes (the viewer's Python object is freed twice)."""
    width, height = Gui.ActiveDocument.ActiveView.getSize()
    return coin.SbViewportRegion(width, height)


def box_of(node):
    """(min, max) of a scene node as Coin bounds it (what the view draws)."""
    action = coin.SoGetBoundingBoxAction(viewport())
    action.apply(node)
    box = action.getBoundingBox()
    return np.array(box.getMin().getValue()), np.array(box.getMax().getValue())


def find_node(root, name):
    search = coin.SoSearchAction()
    search.setName(coin.SbName(name))
    search.setInterest(coin.SoSearchAction.FIRST)
    search.apply(root)
    path = search.getPath()
    return path.getTail() if path is not None else None


def freecads_drawing(op):
    """FreeCAD's own drawing of the path: the display mode's child that is not our tip path."""
    root, ours = op.ViewObject.RootNode, op.ViewObject.Proxy.tip_root
    for i in range(root.getNumChildren()):
        child = root.getChild(i)
        if child.isOfType(coin.SoSwitch.getClassTypeId()):
            for k in range(child.getNumChildren()):
                if child.getChild(k) != ours:
                    return child.getChild(k)
    return None


def box_text(box):
    return "[%s] - [%s]" % (", ".join("%.3f" % v for v in box[0]), ", ".join("%.3f" % v for v in box[1]))


def within(inner, outer, slack):
    return bool(np.all(inner[0] >= outer[0] - slack) and np.all(inner[1] <= outer[1] + slack))



def view_the_path(op):
    job = op.Proxy.getJob(op)
    show_only(op, *job.Model.Group)
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    run.process_events(0.5)


def check_drawn_at_the_tips(op, label):
    """The drawn path's box is the program's tip box; nothing the operation's view draws lies beyond it but the
    ticks, which start in it. Returns the boxes for the notes."""
    tips, _ = program_tips(op.Path.Commands)
    program = (tips.min(axis=0), tips.max(axis=0))
    node = find_node(op.ViewObject.RootNode, "HsmTipPath")
    run.check("%s: the tip path is drawn" % label, node is not None)
    if node is None:
        return {}
    drawn = box_of(node)
    run.check("%s: drawn box = program's tip box within %g mm" % (label, TOLERANCE_MM),
              np.allclose(drawn[0], program[0], atol=TOLERANCE_MM) and np.allclose(drawn[1], program[1],
                                                                                  atol=TOLERANCE_MM),
              "drawn %s, program %s" % (box_text(drawn), box_text(program)))
    ticks = op.ViewObject.Proxy.ticks
    length = op.ViewObject.Proxy.TICK_LENGTH_MM
    segments = np.asarray(ticks.getChild(ticks.getNumChildren() - 1).vertexProperty.getValue().vertex.getValues(),
                          dtype=float).reshape(-1, 2, 3) if ticks is not None else np.zeros((0, 2, 3))
    run.check("%s: tool-axis ticks drawn" % label, len(segments) > 10, "%d ticks" % len(segments))
    if len(segments):
        bases = (segments[:, 0].min(axis=0), segments[:, 0].max(axis=0))
        run.check("%s: the ticks start inside the drawn path's box" % label, within(bases, drawn, TOLERANCE_MM),
                  "tick bases %s, path %s" % (box_text(bases), box_text(drawn)))
    whole = box_of(op.ViewObject.RootNode)
    run.check("%s: the view draws nothing off the tip path but the ticks' %g mm" % (label, length),
              within(whole, drawn, length + TOLERANCE_MM), "all %s, path %s" % (box_text(whole), box_text(drawn)))
    return {"drawn": box_text(drawn), "program tips": box_text(program), "all the view draws": box_text(whole)}


@run.step
def five_axis_roughing_op(run):
    from hsmplanner.app.roughing import volume as roughing_object, operation as roughing_op, parts as roughing_parts
    from hsmplanner.app.compat import create_job
    from hsmplanner.gui.finishing_ops_gui import COMMANDS

    Gui.activateWorkbench("HSMPlannerWorkbench")
    document = FreeCAD.newDocument("FiveAxisView")
    part, stock = roughing_parts.create_slanted_slot_block(document)
    document.recompute()
    volume = roughing_object.create(part, stock, Strategy="S3")
    job = create_job([part])
    roughing_op.torus_controller(job)
    document.recompute()
    # as the Volume roughing command makes it, without its task panel
    command = COMMANDS["HSM_VolumeRoughing"]
    op = command.res.objFactory(command.res.name, obj=None, parentJob=job)
    op.ViewObject.Proxy = command.view_provider(op.ViewObject, command.res)
    op.Machine = FIVE_AXIS
    op.Volume = volume
    document.recompute()
    run.wait_until(lambda: run.valid(op) and op.Passes > 0, 120.0, "the 5-axis operation computed")
    state.update(document=document, op=op, job=job, part=part, stock=stock,
                 gcode=op.Path.toGCode())
    run.check("its moves tilt A", any(abs(c.Parameters.get("A", 0.0)) > 1.0 for c in op.Path.Commands))
    run.check("drawn in the Tip path mode", op.ViewObject.DisplayMode == "Tip path", op.ViewObject.DisplayMode)


@run.step
def five_axis_path_drawn_on_the_part(run):
    op, stock = state["op"], state["stock"]
    view_the_path(op)
    notes = check_drawn_at_the_tips(op, "5-axis")
    freecad = box_of(freecads_drawing(op))
    notes["FreeCAD's own drawing (hidden)"] = box_text(freecad)
    run.notes["5-axis boxes, mm"] = notes
    tips, feeds = program_tips(op.Path.Commands)
    block = stock.Shape.BoundBox
    stock_box = (np.array([block.XMin, block.YMin, block.ZMin]), np.array([block.XMax, block.YMax, block.ZMax]))
    radius = float(op.ToolController.Tool.Diameter) / 2.0
    inside = np.all((tips[feeds] >= stock_box[0] - radius) & (tips[feeds] <= stock_box[1] + radius), axis=1)
    run.notes["feed tips in the stock grown by the tool radius"] = "%d of %d" % (np.sum(inside), len(inside))
    run.check("the cuts are in the stock: 90 % of the feed moves' tips in it, grown by the tool's radius (the "
              "rest enter from above)", np.mean(inside) >= 0.9, run.notes["feed tips in the stock grown by the tool radius"])
    run.check("FreeCAD's own drawing would put them elsewhere (why the Tip path mode)",
              not within((freecad[0], freecad[1]), stock_box, radius), box_text(freecad))
    run.screenshot("five_axis_tip_path")


@run.step
def feeds_and_rapids_in_freecads_colours(run):
    from hsmplanner.gui.tip_path import rapid_rgb

    op = state["op"]
    node = find_node(op.ViewObject.RootNode, "HsmTipPath")
    if node is None:
        run.check("the tip path is drawn, in colours", False)
        return
    material = next(node.getChild(i) for i in range(node.getNumChildren())
                    if node.getChild(i).isOfType(coin.SoMaterial.getClassTypeId()))
    colours = [tuple(round(v, 3) for v in c.getValue()) for c in material.diffuseColor.getValues()]
    _, feeds = program_tips(op.Path.Commands)
    feed = tuple(round(v, 3) for v in op.ViewObject.NormalColor[:3])
    rapid = tuple(round(v, 3) for v in rapid_rgb())
    run.check("one colour per move", len(colours) == len(feeds), "%d colours, %d moves" % (len(colours), len(feeds)))
    run.check("feeds in the view's NormalColor, rapids in CAM's rapid colour", feed != rapid and colours == [
        feed if f else rapid for f in feeds], "feed %s rapid %s, drawn %s" % (feed, rapid, sorted(set(colours))))
    op.ViewObject.NormalColor = (0.0, 0.0, 1.0)
    material = find_node(op.ViewObject.RootNode, "HsmTipPath").getChild(0)
    run.check("a new NormalColor redraws the feeds", (0.0, 0.0, 1.0) in
              [tuple(c.getValue()) for c in material.diffuseColor.getValues()])
    op.ViewObject.NormalColor = feed


@run.step
def a_click_on_the_path_picks_the_command_under_it(run):
    op, document = state["op"], state["document"]
    view = Gui.ActiveDocument.ActiveView
    tips, feeds = program_tips(op.Path.Commands)
    moves = [i for i, c in enumerate(op.Path.Commands) if c.Name in ("G0", "G1")]
    longest = max(range(1, len(tips)), key=lambda k: feeds[k] * np.linalg.norm(tips[k] - tips[k - 1]))
    middle = FreeCAD.Vector(*(0.5 * (tips[longest] + tips[longest - 1])))
    x, y = view.getPointOnScreen(middle)
    info = view.getObjectInfo((int(round(x)), int(round(y))))
    run.notes["picked at the longest cut's middle"] = info and {k: info.get(k) for k in ("Object", "Component")}
    run.check("a click on the drawn path picks the operation", bool(info) and info.get("Object") == op.Name, str(info))
    component = (info or {}).get("Component") or ""
    try:
        number = int(component.split(" ", 1)[0]) - 1
    except ValueError:
        number = -1
    run.check("and names a move command as FreeCAD does ('12 G1 X…')", number in moves and
              component.split(" ", 2)[1] == op.Path.Commands[number].Name, component)
    if number in moves:
        k = moves.index(number)
        a = np.array(view.getPointOnScreen(FreeCAD.Vector(*tips[max(k - 1, 0)])))
        b = np.array(view.getPointOnScreen(FreeCAD.Vector(*tips[k])))
        share = np.clip(np.dot(np.array([x, y]) - a, b - a) / max(np.dot(b - a, b - a), 1e-12), 0.0, 1.0)
        miss = float(np.linalg.norm(a + share * (b - a) - np.array([x, y])))
        run.check("the named command's move passes under the cursor", miss <= PICK_PIXELS, "%.1f px away" % miss)
        Gui.Selection.clearSelection()
        Gui.Selection.addSelection(document.Name, op.Name, component)
        selected = Gui.Selection.getSelectionEx()
        run.check("the command can be selected", bool(selected) and selected[0].Object == op and
                  component in selected[0].SubElementNames, str([s.SubElementNames for s in selected]))
        run.screenshot("five_axis_tip_path_selected")
        Gui.Selection.clearSelection()
    run.check("the view left the Path as it was (posts read it)", op.Path.toGCode() == state["gcode"])


@run.step
def posted_as_before(run):
    from hsmplanner.app.posts import siemens840d_post

    job, op = state["job"], state["op"]
    program = siemens840d_post.export([job, op.ToolController, op], "-", "--machine=%s" % FIVE_AXIS)
    run.check("the 840D post writes the A tilt of the program", "TRAORI" in program and " A" in program,
              program[:200])


@run.step
def three_axis_path_stays_freecads(run):
    op, document = state["op"], state["document"]
    op.Machine = THREE_AXIS  # S3 written 3+2: no rotary words
    document.recompute()
    run.wait_until(lambda: run.valid(op) and not any("A" in c.Parameters for c in op.Path.Commands), 120.0,
                   "the 3+2 path computed")
    run.check("FreeCAD's own drawing for a path without rotary words", op.ViewObject.DisplayMode == "Waypoints",
              op.ViewObject.DisplayMode)
    tips, _ = program_tips(op.Path.Commands)
    tips = np.vstack([tips, np.zeros(3)])  # FreeCAD draws from its StartPosition, the origin
    program, drawn = (tips.min(axis=0), tips.max(axis=0)), box_of(freecads_drawing(op))
    run.notes["3+2 boxes, mm"] = {"FreeCAD's drawing": box_text(drawn), "program tips and origin": box_text(program)}
    run.check("FreeCAD draws it at its tips", np.allclose(drawn[0], program[0], atol=TOLERANCE_MM)
              and np.allclose(drawn[1], program[1], atol=TOLERANCE_MM),
              "drawn %s, program %s" % (box_text(drawn), box_text(program)))
    view_the_path(op)
    run.screenshot("three_axis_freecad_path")
    op.Machine = FIVE_AXIS
    document.recompute()
    run.wait_until(lambda: run.valid(op) and op.ViewObject.DisplayMode == "Tip path", 120.0,
                   "the 5-axis path back in the Tip path mode")


@run.step
def tip_path_after_saving_and_reopening(run):
    document = state["document"]
    path = os.path.join(tempfile.mkdtemp(), "five_axis_view.FCStd")
    document.saveAs(path)
    name = state["op"].Name
    FreeCAD.closeDocument(document.Name)
    document = FreeCAD.openDocument(path)
    op = document.getObject(name)
    run.wait_until(lambda: op.ViewObject.DisplayMode == "Tip path"
                   and find_node(op.ViewObject.RootNode, "HsmTipPath") is not None, 30.0,
                   "the reopened operation drawn in the Tip path mode")
    run.check("the reopened Path is the saved one", op.Path.toGCode() == state["gcode"])
    view_the_path(op)
    run.notes["reopened 5-axis boxes, mm"] = check_drawn_at_the_tips(op, "reopened")
    run.screenshot("five_axis_tip_path_reopened")


run.start()
