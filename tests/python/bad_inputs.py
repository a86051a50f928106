"""Bad inputs of every public function and document-object property, run in child processes.

Each case is code run in a namespace that holds the master bottom feature (`part`, boundaries `b1`, `b2`,
bottom `face`) and helpers; it must raise the exception named with the words given (the input and the fix),
or leave `result` for which `check` holds. A child runs the cases one after another and reports each as a
JSON line; a crash, a hang (past TIMEOUT_S) or runaway memory (past MEMORY_LIMIT_BYTES) of a case fails
that case only, and the remaining cases go on in a new child.
"""
import json
import os
import select
import subprocess
import time

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
CHILD = os.path.join(REPO, "tests", "python", "bad_inputs_child.py")
TIMEOUT_S = 90
MEMORY_LIMIT_BYTES = 8 << 30

GCODE_OK = "G1 X1 F100\n"


def raises(name, code, error, words):
    return dict(name=name, code=code, error=error, words=words)


def holds(name, code, check):
    return dict(name=name, code=code, check=check)


CASES = [
    # --- inputs that once crashed -------------------------------------------------------------------------------
    raises("curve_net P 0.003 (crashed OCCT)", "h.curve_net(b1, b2, 0.5, 0.003, face=face)", "ValueError",
           "step P = 0.003 mm must be at least"),
    raises("parallel_finishing on the wall Face1", "h.parallel_finishing(part, 'Face1')", "ValueError",
           "Face1 is vertical"),
    raises("parallel_finishing on the wall Face7", "h.parallel_finishing(part, 'Face7')", "ValueError",
           "Face7 is vertical"),
    raises("parallel_finishing on the wall Face9", "h.parallel_finishing(part, 'Face9')", "ValueError",
           "Face9 is vertical"),
    raises("parallel_finishing on the wall Face10", "h.parallel_finishing(part, 'Face10')", "ValueError",
           "Face10 is vertical"),
    raises("parallel_finishing on a plane at 89.5°", "h.parallel_finishing(tilted(89.5), 'Face1')", "ValueError",
           "is vertical"),
    holds("parallel_finishing on a plane at 60° works", "result = h.parallel_finishing(tilted(60), 'Face1')",
          "result[1]['passes'] > 5"),
    raises("parallel_finishing with a 60 mm ball", "h.parallel_finishing(part, 'Face4', tool_diameter=60)",
           "ValueError", "no pass of the 60 mm ball rests on Face4"),
    # --- inputs that once hung ------------------------------------------------------------------------------------
    raises("curve_net P 1e-6", "h.curve_net(b1, b2, 0.5, 1e-6, face=face)", "ValueError", "step P = 1e-06 mm"),
    raises("curve_net P 0.05 needs 2800 planes", "h.curve_net(b1, b2, 0.5, 0.05, face=face)", "ValueError",
           "the limit is 2000 planes: use P of at least"),
    raises("parallel_finishing with a 1e6 mm tool", "h.parallel_finishing(part, 'Face4', tool_diameter=1e6)",
           "ValueError", "tool diameter 1e+06 mm is outside"),
    raises("guide_finishing with a 1e6 mm tool", "h.guide_finishing(part, 'Face4', [(b1, b2)], tool_diameter=1e6)",
           "ValueError", "tool diameter 1e+06 mm is outside"),
    raises("parallel_finishing with cusp 1e-9", "h.parallel_finishing(part, 'Face4', cusp_height=1e-9)",
           "ValueError", "cusp height 1e-09 mm must be at least"),
    raises("guide_finishing with cusp 1e-9", "h.guide_finishing(part, 'Face4', [(b1, b2)], cusp_height=1e-9)",
           "ValueError", "cusp height 1e-09 mm must be at least"),
    raises("a 2 m plate with a 1 mm ball at cusp 0.001: 31,600 passes",
           "h.parallel_finishing(plate(2000), 'Face1', tool_diameter=1, cusp_height=0.001)", "ValueError",
           "passes over the 2000 mm of Face1 (the limit is 10000): use a cusp height of at least"),
    raises("a 2 m plate at the paper's cusp: 4e7 cutter positions",
           "h.parallel_finishing(plate(2000), 'Face1', tool_diameter=4, cusp_height=0.01)", "ValueError",
           "cutter positions"),
    raises("optimal_direction grid 100000", "h.optimal_direction(face, feed_mm_min=4000, grid=100000)", "ValueError",
           "sample grid 100000"),
    raises("simulate trace_period 1e-9", "h.simulate(SEVEN_LINES, 'linuxcnc-2.9', trace_period=1e-9)", "ValueError",
           "trace period 1e-09 s"),
    # --- toolpaths that would gouge ---------------------------------------------------------------------------
    raises("parallel_finishing of the underside Face8", "h.parallel_finishing(part, 'Face8')", "ValueError",
           "Face8 faces down"),
    raises("guide_finishing of the underside Face8", "h.guide_finishing(part, 'Face8', [(b1, b2)])", "ValueError",
           "Face8 faces down"),
    raises("optimal_direction of a face that looks down", "h.optimal_direction(part.Face8, feed_mm_min=4000)",
           "ValueError", "the face looks down"),
    holds("the ball does not dip into a hole of the face",
          "plate = holed_plate(); result = h.parallel_finishing(plate, top_face(plate), tool_diameter=4)",
          "lowest_feed_z(result[0]) > 5.0 - 0.011"),
    holds("a net across a hole says so",
          "plate = holed_plate(); top = plate.Faces[top_face(plate) - 1]; "
          "result = h.curve_net(np.array([[0, 0.0, 5], [30, 0, 5]]), np.array([[0, 20.0, 5], [30, 20, 5]]), 0.5, 1, "
          "face=top, mode='median')",
          "any('over a hole' in w for w in result.warnings)"),
    # --- silent nonsense --------------------------------------------------------------------------------------
    holds("boundaries 500 mm above the face build a real net",
          "up = FreeCAD.Vector(0, 0, 500); result = h.curve_net(b1.translated(up), b2.translated(up), 0.5, 5, face=face)",
          "len(result.curves) < 20 and any('off the bottom face' in w for w in result.warnings)"),
    raises("min_gap 1e9", "h.curve_net(b1, b2, 0.5, 5, face=face, min_gap=1e9)", "ValueError",
           "minimum gap 1e+09 mm is as wide as the area"),
    raises("K 0.01 would need 331 curves", "h.curve_net(b1, b2, 0.01, 5, face=face)", "ValueError",
           "use K of at least"),
    raises("area_regions on a face the net is not on", "h.area_regions(h.curve_net(b1, b2, 0.5, 5, face=face), part.Face3)",
           "ValueError", "the net does not lie on this face"),
    raises("a face passed as a boundary", "h.curve_net(part.Face4, b2, 0.5, 5)", "ValueError",
           "the curve is a face"),
    raises("identical guides", "h.guide_finishing(part, 'Face4', [(b1, b1)])", "ValueError",
           "the guides of area 1 coincide"),
    raises("ball-end finishing with FreeCAD's default tool controller", "default_controller_finishing()", "ValueError",
           "ball-end finishing needs a ball end mill"),
    raises("feed-rate analysis of an operation with feeds of 0", "feedrate_of_zero_feed()", "ValueError",
           "cuts at F0"),
    holds("F0 on a rapid, as FreeCAD CAM's area operations end", "result = h.simulate('G1 X1 F100\\nG0 F0.000000 Z5\\n', 'linuxcnc-2.9').summary.block_count", "result == 2"),
    raises("a feed move after F0", "h.simulate('G1 X1 F100\\nG0 F0 Z5\\nG1 X2\\n', 'linuxcnc-2.9')", "ValueError", "line 3: a feed move at F0 (set at line 2)"),
    raises("G4 P-5", "h.simulate('G4 P-5\\n', 'linuxcnc-2.9')", "ValueError", "G4 P-5: a dwell lasts 0 s or more"),
    # --- canned cycles --------------------------------------------------------------------------------------
    raises("G81 without R", "h.simulate('G0 Z5\\nG81 X1 Z-2 F60\\n', 'linuxcnc-2.9')", "ValueError",
           "line 2: G81 needs R (the retract plane)"),
    raises("G83 Q0", "h.simulate('G0 Z5\\nG83 X1 Z-2 R1 Q0 F60\\n', 'linuxcnc-2.9')", "ValueError",
           "line 2: G83 needs Q > 0"),
    raises("G83 Q-1", "h.simulate('G0 Z5\\nG83 X1 Z-2 R1 Q-1 F60\\n', 'linuxcnc-2.9')", "ValueError",
           "line 2: G83 needs Q > 0"),
    raises("G83 a billion pecks", "h.simulate('G0 Z5\\nG83 X1 Z-1000000 R1 Q0.001 F60\\n', 'linuxcnc-2.9')",
           "ValueError", "is over 100,000 pecks: give a larger Q"),
    raises("G81 bottom above R", "h.simulate('G0 Z5\\nG81 X1 Z3 R1 F60\\n', 'linuxcnc-2.9')", "ValueError",
           "the bottom Z3 is above the retract plane R1"),
    raises("G81 at F0", "h.simulate('G0 Z5\\nG81 X1 Z-2 R1\\n', 'linuxcnc-2.9')", "ValueError",
           "G81 drills at F0: program a positive F"),
    raises("G81 in G18", "h.simulate('G0 Z5\\nG18 G81 X1 Z-2 R1 F60\\n', 'linuxcnc-2.9')", "ValueError",
           "G81 in G18"),
    holds("G81 a billion mm away", "result = h.simulate('G0 Z5\\nG81 X1000000000 Z-2 R1 F60\\n', "
          "'linuxcnc-2.9').summary.block_count", "result >= 3"),
    raises("G82 P-5", "h.simulate('G0 Z5\\nG82 X1 Z-2 R1 P-5 F60\\n', 'linuxcnc-2.9')", "ValueError",
           "line 2: G82 P-5: a dwell lasts 0 s or more"),
    holds("G82 P1e9 dwells as asked", "result = h.simulate('G0 Z5\\nG82 X1 Z-2 R1 P1000000000 F60\\n', "
          "'linuxcnc-2.9').summary.dwell_time", "result == 1e9"),
    # --- the cycle time of a Job ---------------------------------------------------------------------------
    raises("cycle time of None", "from hsmplanner.app import cycle_time; cycle_time.job_rows(None)", "ValueError",
           "is not a CAM Job: pick a Job"),
    raises("cycle time of a part", "from hsmplanner.app import cycle_time; cycle_time.job_rows(new_master())",
           "ValueError", "is not a CAM Job"),
    raises("cycle time of an empty Job", "from hsmplanner.app import cycle_time; cycle_time.job_rows(empty_job())",
           "ValueError", "has no active operation: add one"),
    raises("cycle time on no such machine",
           "from hsmplanner.app import cycle_time; cycle_time.job_rows(one_rapid_op(), 'no-such-machine')",
           "ValueError", "no-such-machine"),
    raises("cycle time object of a string", "from hsmplanner.app import cycle_time_object; "
           "cycle_time_object.create('a job')", "ValueError", "is not a CAM Job"),
    holds("clock of absurd seconds", "from hsmplanner.app.cycle_time import clock; "
          "result = [clock(0), clock(-5), clock(1e9), clock(None)]", "result[0] == '0:00' and result[3] == ''"),
    raises("clearance height NaN", "import Path; from hsmplanner.app.clearance_moves import via_clearance; "
           "via_clearance([Path.Command('G0', {'X': 0.0, 'Y': 0.0, 'Z': 5.0})], float('nan'))", "ValueError",
           "clearance height nan mm is not a number"),
    holds("clearance height below the first move", "import Path; from hsmplanner.app.clearance_moves import "
          "via_clearance; result = via_clearance([Path.Command('G0', {'X': 0.0, 'Y': 0.0, 'Z': 5.0})], -1e9)",
          "result[0].Parameters == {'Z': 5.0} and len(result) == 4"),
    holds("no moves to reach", "from hsmplanner.app.clearance_moves import via_clearance; "
          "result = via_clearance([], 1e9)", "result == []"),
    holds("cusp range of a tool of diameter 0, -4, NaN, 1e9", "from hsmplanner.app.finishing_ops import "
          "cusp_limits; from types import SimpleNamespace as N; result = [cusp_limits(N(Tool=N(Diameter=d))) "
          "for d in (0.0, -4.0, float('nan'), 1e9, 1e-9)]",
          "all(r == (0.001, 10.0) for r in result)"),
    holds("legend ticks of NaN and equal values", "from hsmplanner.gui.feedmap import tick_texts; "
          "result = [tick_texts([float('nan')] * 5, 4), tick_texts([1.0] * 5, 0), tick_texts([0, 1e-9, 2e-9], 0)]",
          "len(result[0]) == 5 and result[1] == ['1'] * 5 and len(set(result[2])) == 3"),
    # --- numbers in G-code that are not numbers ---------------------------------------------------------------
    raises("X1e400", "h.simulate('G1 X1e400 F100\\n', 'linuxcnc-2.9')", "ValueError", "line 1: 'X1E400': G-code numbers have no exponent"),
    raises("Y nan", "h.simulate('G1 X1 F100\\nG1 Y nan\\nG1 X5\\n', 'linuxcnc-2.9')", "ValueError", "line 2: 'Y NAN' is not"),
    raises("X inf", "h.simulate('G1 X inf F100\\n', 'linuxcnc-2.9')", "ValueError", "line 1: 'X INF' is not"),
    raises("G2 with no words", "h.simulate('G1 X1 F100\\nG2\\n', 'linuxcnc-2.9')", "ValueError",
           "line 2: G2 without an end point or a centre"),
    raises("a 200 MB file without a line end", "h.simulate(endless_file(200 << 20), 'linuxcnc-2.9')", "ValueError",
           "line 1: the line is longer than 65536 characters"),
    raises("binary garbage", "h.simulate(bytes(range(1, 256)).decode('latin-1') + '\\n', 'linuxcnc-2.9')",
           "ValueError", "line 1: unexpected character '\\x01' (byte 1)"),
    raises("a coordinate beyond 1e9 mm", "h.simulate('G1 X12345678901 F100\\n', 'linuxcnc-2.9')", "ValueError",
           "is out of range"),
    holds("far but finite coordinates give a finite time",
          "result = h.simulate('G1 X999999999 F1\\n', 'mikron-ucp710-840d').summary.total_time",
          "math.isfinite(result) and result > 1e9"),
    # --- more of the same spirit: curve nets ------------------------------------------------------------------
    raises("K nan", "h.curve_net(b1, b2, float('nan'), 5)", "ValueError", "K = nan is outside ]0,1["),
    raises("K inf", "h.curve_net(b1, b2, float('inf'), 5)", "ValueError", "K = inf is outside"),
    raises("K as text", "h.curve_net(b1, b2, 'half', 5)", "ValueError", "could not convert string to float"),
    raises("P nan", "h.curve_net(b1, b2, 0.5, float('nan'))", "ValueError", "step P = nan mm"),
    raises("P inf", "h.curve_net(b1, b2, 0.5, float('inf'))", "ValueError", "step P = inf mm"),
    raises("fit tolerance 0", "h.curve_net(b1, b2, 0.5, 5, fit_tolerance=0)", "ValueError", "fit tolerance 0 mm must be in"),
    raises("fit tolerance 5", "h.curve_net(b1, b2, 0.5, 5, fit_tolerance=5)", "ValueError", "fit tolerance 5 mm must be in"),
    raises("min_gap -1", "h.curve_net(b1, b2, 0.5, 5, min_gap=-1)", "ValueError", "minimum gap -1 mm must be positive"),
    raises("min_gap 0", "h.curve_net(b1, b2, 0.5, 5, min_gap=0)", "ValueError", "minimum gap 0 mm must be positive"),
    raises("direction zero", "h.curve_net(b1, b2, 0.5, 5, direction=(0, 0, 0))", "ValueError", "machining direction is zero"),
    raises("direction nan", "h.curve_net(b1, b2, 0.5, 5, direction=(float('nan'), 0, 0))", "ValueError",
           "machining direction is zero"),
    raises("unknown mode", "h.curve_net(b1, b2, 0.5, 5, mode='zigzag')", "ValueError", "mode 'zigzag' is unknown"),
    raises("the same edge twice", "h.curve_net(b1, b1, 0.5, 5)", "ValueError", "the boundaries coincide"),
    raises("empty BREP text", "h.curve_net('', b2, 0.5, 5)", "ValueError", "BREP text is empty"),
    raises("BREP text that is not BREP", "h.curve_net('hello', b2, 0.5, 5)", "ValueError", "BREP text"),
    raises("a curve of one point", "h.curve_net(np.array([[1.0, 2, 3]]), b2, 0.5, 5)", "ValueError", "distinct point"),
    raises("a curve with nan", "h.curve_net(np.array([[0.0, 0, 0], [float('nan'), 1, 0]]), b2, 0.5, 5)", "ValueError",
           "is not finite"),
    raises("intermediate_curve K 1.5", "h.intermediate_curve(b1, b2, 1.5, 5)", "ValueError", "K = 1.5 is outside"),
    raises("4-step min_step 0.001", "h.guidance_curves(b1, b2, face=face, min_step=0.001)", "ValueError",
           "smallest step 0.001 mm must be at least"),
    raises("4-step K median 1.2", "h.guidance_curves(b1, b2, k_median=1.2)", "ValueError", "K of the median = 1.2"),
    holds("progress that returns False cancels a net",
          "try:\n    h.curve_net(b1, b2, 0.5, 5, face=face, progress=lambda done: False)\n    result = 'ran'\n"
          "except h.Cancelled as error:\n    result = str(error)", "result == 'curve net cancelled'"),
    raises("progress that is not callable", "h.curve_net(b1, b2, 0.5, 5, progress=3)", "ValueError",
           "progress must be a callable"),
    # --- finishing --------------------------------------------------------------------------------------------
    raises("bottom face Face0", "h.parallel_finishing(part, 'Face0')", "ValueError", "is not a face name"),
    raises("bottom face Face99", "h.parallel_finishing(part, 'Face99')", "ValueError",
           "bottom face Face99 does not exist: the part has 10 faces"),
    raises("bottom face 'Top'", "h.parallel_finishing(part, 'Top')", "ValueError", "is not a face name"),
    raises("angle nan", "h.parallel_finishing(part, 'Face4', angle_deg=float('nan'))", "ValueError",
           "the angle of the planes must be a number"),
    raises("tolerance 0", "h.parallel_finishing(part, 'Face4', tolerance=0)", "ValueError", "machining tolerance 0 mm"),
    raises("tolerance 5", "h.parallel_finishing(part, 'Face4', tolerance=5)", "ValueError", "machining tolerance 5 mm"),
    raises("clearance -1", "h.parallel_finishing(part, 'Face4', clearance=-1)", "ValueError", "clearance -1 mm"),
    raises("clearance 1e9", "h.parallel_finishing(part, 'Face4', clearance=1e9)", "ValueError", "clearance 1e+09 mm"),
    raises("threads -1", "h.parallel_finishing(part, 'Face4', threads=-1)", "ValueError", "threads -1 must be"),
    raises("threads 1e6", "h.parallel_finishing(part, 'Face4', threads=1000000)", "ValueError", "threads 1000000"),
    raises("sweep sideways", "h.parallel_finishing(part, 'Face4', sweep='sideways')", "ValueError", "sweep 'sideways'"),
    raises("extension 1e6", "h.parallel_finishing(part, 'Face4', extension=1e6)", "ValueError", "extension 1e+06 mm"),
    raises("cusp height as large as the radius", "h.parallel_finishing(part, 'Face4', cusp_height=2)", "ValueError",
           "below the tool radius"),
    raises("tool diameter nan", "h.parallel_finishing(part, 'Face4', tool_diameter=float('nan'))", "ValueError",
           "tool diameter"),
    raises("tool diameter 0.01", "h.parallel_finishing(part, 'Face4', tool_diameter=0.01)", "ValueError",
           "tool diameter 0.01 mm is outside"),
    raises("guide_finishing without areas", "h.guide_finishing(part, 'Face4', [])", "ValueError", "no area to machine"),
    raises("guide_finishing along the tool axis", "h.guide_finishing(part, 'Face4', [(b1, b2)], direction=(0, 0, 1))",
           "ValueError", "must be a horizontal vector"),
    raises("guide_finishing with guides that do not overlap",
           "h.guide_finishing(part, 'Face4', [(np.array([[0, 0.0, -20], [10, 0, -20]]), np.array([[50, 10.0, -20], [60, 10, -20]]))])",
           "ValueError", "do not overlap"),
    holds("progress that returns False cancels finishing",
          "try:\n    h.parallel_finishing(part, 'Face4', progress=lambda done: done < 0.2)\n    result = 'ran'\n"
          "except h.Cancelled as error:\n    result = str(error)", "result == 'finishing cancelled'"),
    # --- feed-rate simulation ---------------------------------------------------------------------------------
    raises("an unknown machine", "h.simulate(GCODE_OK, 'no-such-machine')", "ValueError", "no-such-machine"),
    raises("a machine dict without axes", "h.simulate(GCODE_OK, dict(name='m', controller='linuxcnc'))", "ValueError",
           "missing \"axes\""),
    raises("a machine with a negative velocity", "h.simulate(GCODE_OK, machine_with(max_velocity_mm_min=-5))",
           "ValueError", "must be positive"),
    raises("a machine field set to 0 from Python", "m = h.load_machine('linuxcnc-2.9'); m.max_acceleration = (0, 1000, 1000); "
           "h.simulate(GCODE_OK, m)", "ValueError", "max acceleration of axis X"),
    raises("a program file that does not exist", "h.simulate('no_such_program.ngc', 'linuxcnc-2.9')", "ValueError",
           "neither an existing file nor G-code text"),
    raises("G1 before any feed", "h.simulate('G1 X10\\n', 'linuxcnc-2.9')", "ValueError", "line 1: no feed rate"),
    raises("an arc whose end is off its circle", "h.simulate('G1 X10 F100\\nG2 X0 Y0 I-3\\n', 'linuxcnc-2.9')",
           "ValueError", "line 2: arc end point is not on the circle"),
    raises("an unclosed comment", "h.simulate('G1 X1 F100 (oops\\n', 'linuxcnc-2.9')", "ValueError",
           "line 1: comment '(' is not closed"),
    raises("65 words on a line", "h.simulate('G1 F100 ' + 'X1 ' * 65 + '\\n', 'linuxcnc-2.9')", "ValueError",
           "more than 64 words on one line"),
    raises("an unknown word refused", "h.simulate('G1 X1 F100 U5\\n', 'linuxcnc-2.9', refuse_unknown_words=True)",
           "ValueError", "'U5' is not understood"),
    raises("a rotary axis the machine has not", "h.simulate('G1 X1 F100 A5\\n', 'linuxcnc-2.9')",
           "ValueError", "the program turns A but machine \"linuxcnc-2.9\" has no such axis"),
    raises("a zero orientation vector", "h.simulate('TRAORI\\nG1 X1 A3=0 B3=0 C3=0 F100\\n', 'mikron-ucp710-ac-840d')",
           "ValueError", "line 2: orientation vector A3 B3 C3 = (0, 0, 0) has no length"),
    raises("an orientation out of travel", "h.simulate('TRAORI\\nG1 X1 A3=0 B3=0 C3=-1 F100\\n', 'linuxcnc-2.9-xyzac-trt')",
           "ValueError", "outside the travel"),
    raises("a trace period below 0", "h.simulate(GCODE_OK, 'linuxcnc-2.9', trace_period=-1)", "ValueError",
           "trace_period -1 s must be positive"),
    # --- machining direction, geometry ------------------------------------------------------------------------
    raises("direction with no tooth", "h.optimal_direction(face, feed_mm_min=4000, teeth=0)", "ValueError", "teeth Z = 0"),
    raises("direction with no spindle", "h.optimal_direction(face, feed_mm_min=4000, spindle_rpm=0)", "ValueError",
           "spindle speed"),
    raises("direction with no feed", "h.optimal_direction(face)", "ValueError", "give the programmed feed"),
    raises("direction with angle step 5°", "h.optimal_direction(face, feed_mm_min=4000, angle_step=5)", "ValueError",
           "the angle step 5°"),
    raises("direction with a grid of 1", "h.optimal_direction(face, feed_mm_min=4000, grid=1)", "ValueError",
           "the sample grid 1 × 1"),
    raises("drop along a zero axis", "h.drop_on_face(face, [[10, 10, 0]], axis=(0, 0, 0))", "ValueError",
           "the axis to drop points along is zero"),
    raises("a billion samples of a curve", "h.sample_curve(b1, 10**9)", "ValueError", "sample count is 1000000000"),
    raises("a summary of something that is not a shape", "h.shape_summary(42)", "TypeError",
           "expected a FreeCAD Part shape"),
    # --- document-object properties: clamped at the door ------------------------------------------------------
    holds("Guide curve net Step 0.003 is clamped and recomputes",
          "net = new_net(); net.Step = 0.003; net.recompute(); result = (net.Step.Value, net.isValid())",
          "result == (0.5, True)"),
    holds("Guide curve net K 5 is clamped", "net = new_net(); net.K = 5; result = net.K", "result == 0.99"),
    holds("Guide curve net MinGap 1e9 is clamped", "net = new_net(); net.MinGap = 1e9; result = net.MinGap.Value",
          "result == 50.0"),
    holds("Machining direction Grid 100000 is clamped",
          "a = new_direction(); a.Grid = 100000; a.ToolDiameter = 1e6; a.AngleStep = 1e-9; "
          "result = (a.Grid, a.ToolDiameter.Value, a.AngleStep)", "result == (500, 100.0, 0.01)"),
    holds("Finishing CuspHeight 1e-9 is clamped",
          "op = new_planes(); op.CuspHeight = 1e-9; op.Tolerance = 50; result = (op.CuspHeight.Value, op.Tolerance.Value)",
          "result == (0.001, 1.0)"),
    holds("a master feature of zero length is invalid, with a message, and the document lives",
          "m = new_master(); m.Length = 0; m.recompute(); result = m.isValid()", "result is False"),
    # --- 5-axis roughing: the test parts and the Roughing volume (one line, the object stays valid) ----------
    raises("slanted slot deeper than the block", "from hsmplanner.app.roughing import parts as roughing_parts\n"
           "s, _ = roughing_parts.create_slanted_slot_block(new_document()); s.SlotDepth = 40; status_error(s)",
           "ValueError", "does not fit in the block: make it smaller or the block larger"),
    holds("slanted slot tilted 75° is clamped to 59°", "from hsmplanner.app.roughing import parts as roughing_parts\n"
          "s, _ = roughing_parts.create_slanted_slot_block(new_document()); s.Tilt = 75; result = s.Tilt.Value",
          "result == 59.0"),
    raises("impeller blades too thick for the inlet", "from hsmplanner.app.roughing import parts as roughing_parts\n"
           "d = new_document(); w = d.addObject('Part::FeaturePython', 'W'); roughing_parts.Impeller(w); "
           "w.Thickness = 30; status_error(w)", "ValueError", "the blades are too thick for the inlet"),
    holds("impeller of 100 blades is clamped to 24", "from hsmplanner.app.roughing import parts as roughing_parts\n"
          "d = new_document(); w = d.addObject('Part::FeaturePython', 'W'); roughing_parts.Impeller(w); "
          "w.Blades = 100; result = w.Blades", "result == 24"),
    raises("roughing volume without a part", "o = new_slot_roughing(); o.Part = None; roughing_error(o)", "ValueError",
           "Part is not set: link the part"),
    raises("roughing volume whose stock is the part", "o = new_slot_roughing(); o.Stock = o.Part; roughing_error(o)",
           "ValueError", "Part and Stock are both SlantedSlotBlock: link the blank"),
    raises("roughing volume of a sheet (not a closed solid)",
           "o = new_slot_roughing(); o.Part = new_solid(Part.makePlane(50, 50, FreeCAD.Vector(10, -5, 10)), "
           "document=o.Document); roughing_error(o)", "ValueError", "the part holds no solid"),
    raises("roughing volume of an open shell made a solid",
           "o = new_slot_roughing(); box = Part.makeBox(5, 5, 5, FreeCAD.Vector(5, 5, 5))\n"
           "o.Part = new_solid(Part.Solid(Part.Shell(box.Faces[:5])), document=o.Document); roughing_error(o)",
           "ValueError", "the part is not a valid solid"),
    raises("roughing volume in a stock that does not contain the part",
           "o = new_slot_roughing(); o.Stock = new_solid(Part.makeBox(10, 10, 10), document=o.Document)\n"
           "roughing_error(o)",
           "ValueError", "the stock does not contain the part"),
    raises("roughing volume in a stock beside the part",
           "o = new_slot_roughing(); o.Stock = new_solid(Part.makeBox(10, 10, 10, FreeCAD.Vector(500, 0, 0)), "
           "document=o.Document); roughing_error(o)", "ValueError", "the stock"),
    holds("roughing volume Step 0 is clamped to 0.5 mm and computes",
          "o = new_slot_roughing(); o.Step = 0; roughing_error(o); result = (o.Step.Value, o.SubVolumeCount)",
          "result == (0.5, 50)"),
    holds("roughing volume Step nan is clamped",
          "o = new_slot_roughing(); o.Step = float('nan'); result = o.Step.Value", "result == 0.5"),
    raises("roughing volume Step 1e9 (beyond the volume)", "o = new_slot_roughing(); o.Step = 1e9; roughing_error(o)",
           "ValueError", "step 500 mm is larger than the volume's extent"),
    raises("roughing volume S2 on the slot (no cylindrical crossable face)",
           "o = new_slot_roughing(Strategy='S2'); roughing_error(o)", "ValueError",
           "S2 needs a cylindrical crossable face (an outlet cylinder) and this volume has none: use S1, S3, S4 or S5"),
    raises("roughing volume S1 between two spheres (no planar crossable face)",
           "d = new_document(); from hsmplanner.app.roughing import volume as roughing_object\n"
           "o = roughing_object.create(new_solid(Part.makeSphere(10), 'Ball', d), "
           "new_solid(Part.makeSphere(20), 'Blank', d), Strategy='S1'); roughing_error(o)", "ValueError",
           "S1 needs a planar crossable face"),
    raises("roughing volume Region 5 of 1", "o = new_slot_roughing(); o.Region = 5; roughing_error(o)", "ValueError",
           "Region 5: the volume to remove has 1 region: give 1 to 1"),
    holds("roughing volume Region -1 is clamped to all regions", "o = new_slot_roughing(); o.Region = -1; "
          "roughing_error(o); result = (o.Region, o.SubVolumeCount)", "result == (0, 4)"),
    raises("roughing volume S3 on a grid of 0.25 mm", "o = new_slot_roughing(Strategy='S3'); o.SetupGrid = 0.25; "
           "roughing_error(o)", "ValueError", "use a coarser grid"),
    holds("roughing volume cancelled keeps its previous result and stays valid", "result = cancelled_roughing()",
          "result == (True, True, True)"),
    # --- roughing sweep and clearance, 5-axis kinematics: absurd numbers and shapes ---------
    raises("sweep radial engagement NaN", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.sweep(p, v, w.part_brep, w.stock_brep, radial_engagement=float('nan'))",
           "ValueError", "radial engagement = nan must be in [0.01, 1]"),
    raises("sweep radial engagement 1e-9 (endless rings)", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.sweep(p, v, w.part_brep, w.stock_brep, radial_engagement=1e-9)",
           "ValueError", "must be in [0.01, 1]"),
    raises("sweep radial engagement 1e9", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.sweep(p, v, w.part_brep, w.stock_brep, radial_engagement=1e9)",
           "ValueError", "must be in [0.01, 1]"),
    raises("sweep allowance -1", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.sweep(p, v, w.part_brep, w.stock_brep, allowance=-1.0)",
           "ValueError", "allowance = -1 is outside [0, 10]"),
    raises("sweep tolerance 1e-9", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.sweep(p, v, w.part_brep, w.stock_brep, tolerance=1e-9)",
           "ValueError", "tolerance = 1e-09 is outside"),
    raises("sweep ramp angle 0", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.sweep(p, v, w.part_brep, w.stock_brep, ramp_angle_deg=0.0)",
           "ValueError", "ramp angle = 0 is outside"),
    raises("sweep cutter diameter NaN", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.sweep(p, v, w.part_brep, w.stock_brep, tool=r.cutter(diameter=float('nan')))",
           "ValueError", "cutter diameter = nan mm is outside [0.1, 100] mm"),
    raises("sweep cutter diameter 1e9", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.sweep(p, v, w.part_brep, w.stock_brep, tool=r.cutter(diameter=1e9))",
           "ValueError", "is outside [0.1, 100] mm"),
    raises("sweep with an empty part", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.sweep(p, v, '', w.stock_brep)", "ValueError", "BREP"),
    raises("clearance spacing 0", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.check_clearance({'tip': [[0, 0, 40]], 'axis': [[0, 0, 1]]}, w.part_brep, spacing=0.0)",
           "ValueError", "spacing 0 mm is outside [0.01, 100] mm"),
    raises("clearance spacing NaN", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.check_clearance({'tip': [[0, 0, 40]], 'axis': [[0, 0, 1]]}, w.part_brep, spacing=float('nan'))",
           "ValueError", "spacing nan mm is outside"),
    raises("clearance tips of the wrong shape", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.check_clearance({'tip': [[0, 0]], 'axis': [[0, 0, 1]]}, w.part_brep)",
           "ValueError", "tips and axes must be (N, 3) arrays"),
    raises("clearance with a NaN tip", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.check_clearance({'tip': [[float('nan'), 0, 0]], 'axis': [[0, 0, 1]]}, w.part_brep)",
           "ValueError", "move 0: its tip must be finite and its axis not zero"),
    raises("clearance with a zero axis", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.check_clearance({'tip': [[0, 0, 0]], 'axis': [[0, 0, 0]]}, w.part_brep)",
           "ValueError", "its axis not zero"),
    raises("clearance over 2 million positions", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nr.check_clearance({'tip': [[0, 0, 0], [1e6, 0, 0]], "
           "'axis': [[0, 0, 1], [0, 0, 1]]}, w.part_brep, spacing=0.01)", "ValueError", "use a larger spacing"),
    holds("clearance of no moves", "from hsmplanner import roughing as r\nw = r.slanted_slot_block(); v = r.volume_to_remove(w.stock_brep, w.part_brep); p = r.partition(v, w.part_brep, 'S1')\nresult = r.check_clearance({'tip': np.zeros((0, 3)), 'axis': np.zeros((0, 3))}, "
          "w.part_brep).positions", "result == 0"),
    raises("forward kinematics at NaN angles", "m = h.feedsim.load_machine('mikron-ucp710-ac-840d')\n"
           "h._core.forward_kinematics(m, [0, 0, 0], [float('nan'), 0])", "ValueError", "must be finite numbers"),
    raises("inverse kinematics of a zero tool axis", "m = h.feedsim.load_machine('mikron-ucp710-ac-840d')\n"
           "h._core.inverse_kinematics(m, [0, 0, 0], [0, 0, 0])", "ValueError", "cannot point the tool along (0, 0, 0)"),
    raises("inverse kinematics from a NaN tip", "m = h.feedsim.load_machine('mikron-ucp710-ac-840d')\n"
           "h._core.inverse_kinematics(m, [float('nan'), 0, 0], [0, 0, 1])", "ValueError", "must be finite numbers"),
    raises("machine with a rotary axis at 1e9 deg/min", "import json\nm = json.load(open(REPO + "
           "'/resources/machines/mikron-ucp710-ac-840d.json')); m['rotary_axes'][0]['max_velocity_deg_min'] = 1e9\n"
           "h.simulate('G1 X1 F100\\n', m)", "ValueError", "rotary axis A: max velocity = 1e+09 deg/min is outside [0.06, 6e+06] deg/min"),
    raises("machine with three rotary axes", "import json\nm = json.load(open(REPO + "
           "'/resources/machines/mikron-ucp710-ac-840d.json')); m['rotary_axes'].append(dict(m['rotary_axes'][0], name='B')); del m['kinematics']\n"
           "h.simulate('G1 X1 F100\\n', m)", "ValueError", "a machine has at most two"),
    raises("machine file whose axis says continuous 'yes'", "import json, tempfile\nm = json.load(open(REPO + "
           "'/resources/machines/mikron-ucp710-ac-840d.json')); m['rotary_axes'][0]['continuous'] = 'yes'\n"
           "path = tempfile.mkdtemp() + '/mikron-edited.json'\njson.dump(m, open(path, 'w'))\nh.feedsim.load_machine(path)",
           "ValueError", "mikron-edited.json rotary axis A: \"continuous\" must be true or false, got \"yes\""),
    raises("machine file whose name is a number", "import json, tempfile\nm = json.load(open(REPO + "
           "'/resources/machines/mikron-ucp710-ac-840d.json')); m['name'] = 1\n"
           "path = tempfile.mkdtemp() + '/named-1.json'\njson.dump(m, open(path, 'w'))\nh.feedsim.load_machine(path)",
           "ValueError", "named-1.json: \"name\" must be text in quotes, got 1"),
    raises("an A word a million degrees out of travel", "h.simulate('TRAORI\\nG1 X10 A1000000 F2000\\n', 'mikron-ucp710-ac-840d')",
           "ValueError", "line 2: A1e+06 is outside the travel of A on machine \"mikron-ucp710-ac-840d\" [-100, 120] deg"),
    raises("an A word of 200 degrees", "h.simulate('TRAORI\\nG1 X10 A200 F2000\\n', 'mikron-ucp710-ac-840d')",
           "ValueError", "line 2: A200 is outside the travel of A"),
    raises("an A word of -500 degrees on the LinuxCNC trunnion", "h.simulate('G1 X10 A-500 F2000\\n', 'linuxcnc-2.9-xyzac-trt')",
           "ValueError", "line 1: A-500 is outside the travel of A"),
    raises("impeller blade lean 45 deg (no blades)", "from hsmplanner import roughing as r\nr.impeller(lean_deg=45)",
           "ValueError", "blade lean = 45° must be in [-30°, 30°]"),
    raises("impeller blade lean NaN", "from hsmplanner import roughing as r\nr.impeller(lean_deg=float('nan'))",
           "ValueError", "blade lean = nan° must be in [-30°, 30°]"),
    raises("impeller wrap 720 deg (ran minutes)", "from hsmplanner import roughing as r\nr.impeller(wrap_deg=720)",
           "ValueError", "blade wrap = 720° must be in [-120°, 120°]"),
    raises("impeller outlet radius 1e5 mm", "from hsmplanner import roughing as r\nr.impeller(outlet_radius=1e5)",
           "ValueError", "outlet radius = 100000 mm is larger than a test part's 1000 mm"),
    raises("impeller outlet 30 times the hub inlet", "from hsmplanner import roughing as r\nr.impeller(outlet_radius=300)",
           "ValueError", "more than 20 times the hub inlet radius"),
    raises("slanted slot block 1e6 mm long", "from hsmplanner import roughing as r\nr.slanted_slot_block(length=1e6)",
           "ValueError", "length = 1e+06 mm is larger than a test part's 1000 mm"),
    holds("a 5-axis block turning C 1e9 degrees is bounded work", "result = h.simulate('TRAORI\\nG1 X1 C999999999 F100\\n', "
          "'mikron-ucp710-ac-840d').summary.total_time", "result > 1000"),    # --- material removal and joined regions: absurd settings, bounded work ----------------------
    raises("removal resolution NaN", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, resolution=float('nan'))",
           "ValueError", "resolution nan mm is outside [0.005, 50] mm"),
    raises("removal resolution 1e-6 (endless rays)", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, resolution=1e-6)",
           "ValueError", "is outside [0.005, 50] mm"),
    raises("removal resolution 0.006 (too many rays)", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, resolution=0.006)",
           "ValueError", "use a resolution of at least"),
    raises("removal on 10000 threads (the process would abort)", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, threads=10000)",
           "ValueError", "material removal: threads 10000 must be 0 (all cores) to 256"),
    raises("rapids kept out of the stock with margin NaN", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.keep_rapids_out_of_stock(m, w.stock_brep, w.part_brep, margin=float('nan'))",
           "ValueError", "margin nan mm is outside [0, 1000] mm"),
    raises("rapids kept out of the stock with margin 1e9", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.keep_rapids_out_of_stock(m, w.stock_brep, w.part_brep, margin=1e9)",
           "ValueError", "margin 1e+09 mm is outside [0, 1000] mm"),
    raises("rapids kept out of the stock at resolution 1e-9", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.keep_rapids_out_of_stock(m, w.stock_brep, w.part_brep, resolution=1e-9)",
           "ValueError", "is outside [0.005, 50] mm"),
    holds("rapids kept out of the stock of an empty program", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\ne = {'tip': np.zeros((0, 3)), 'axis': np.zeros((0, 3)), 'kind': np.zeros(0, dtype=int)}\nresult = len(r.keep_rapids_out_of_stock(e, w.stock_brep, w.part_brep)[0]['tip'])",
          "result == 0"),
    raises("removal then an operation that is not a (paths, tool) pair", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, resolution=0.4, then=[(m,)])",
           "ValueError", "then[0] must be a (paths, tool) pair"),
    raises("rapids kept out of the stock after a number", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.keep_rapids_out_of_stock(m, w.stock_brep, w.part_brep, after=[(1, None)])",
           "ValueError", "after[0]: paths must be a SweepResult or a dict of tip, axis and kind arrays, not int"),
    raises("removal rest spacing NaN", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, resolution=0.4, rest_spacing=float('nan'))",
           "ValueError", "rest spacing nan mm is outside [0.4 (the resolution), 20] mm"),
    raises("sweep step-up minimum NaN", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nv = r.volume_to_remove(w.stock_brep, w.part_brep).solids[0]\np = r.partition(v, w.part_brep, 'S1')\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.sweep(p, v, w.part_brep, w.stock_brep, step_up_minimum=float('nan'))",
           "ValueError", "step-up minimum = nan is outside [0.1, 100]"),
    raises("sweep step-up scallop 1e9", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nv = r.volume_to_remove(w.stock_brep, w.part_brep).solids[0]\np = r.partition(v, w.part_brep, 'S1')\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.sweep(p, v, w.part_brep, w.stock_brep, step_up_scallop=1e9)",
           "ValueError", "step-up scallop = 1e+09 is outside [0.01, 10]"),
    raises("split of what is left at resolution 1e-9", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nv = r.volume_to_remove(w.stock_brep, w.part_brep).solids[0]\np = r.partition(v, w.part_brep, 'S1')\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.split_what_is_left(p, v, w.part_brep, m, resolution=1e-9)",
           "ValueError", "resolution 1e-09 mm is outside [0.1, 5] mm"),
    raises("split of what is left with a NaN tip", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nv = r.volume_to_remove(w.stock_brep, w.part_brep).solids[0]\np = r.partition(v, w.part_brep, 'S1')\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nm['tip'][0, 0] = float('nan')\nr.split_what_is_left(p, v, w.part_brep, m)",
           "ValueError", "move 0: its tip must be finite and its axis not zero"),
    holds("split of what is left of no moves", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nv = r.volume_to_remove(w.stock_brep, w.part_brep).solids[0]\np = r.partition(v, w.part_brep, 'S1')\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\ne = {'tip': np.zeros((0, 3)), 'axis': np.zeros((0, 3)), 'kind': np.zeros(0, dtype=int)}\ns = r.split_what_is_left(p, v, w.part_brep, e, resolution=0.5)\nresult = (s.levels, abs(s.between_levels + s.unreachable - s.volume) < 1e-6 * s.volume, s.between_levels > 0)",
          "result == (0, True, True)"),
    raises("partition on -1 threads", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nv = r.volume_to_remove(w.stock_brep, w.part_brep)\ns = r._settings()\ns.threads = -1\nr._core.roughing.partition(v.solids[0], w.part_brep, r.strategy('S1'), s, None)",
           "ValueError", "partition: threads -1 must be 0 (all cores) to 256"),
    raises("partition of an impeller channel by 799 cylinders (S2, step 0.05)", "from hsmplanner import roughing as r\nw = r.impeller()\nv = r.volume_to_remove(w.stock_brep, w.part_brep)\nr.partition(v, w.part_brep, 'S2', step=0.05)",
           "ValueError", "s of splitting on a 2-core machine, more than the 60 s a partition may take; use a step of at least 0.12 mm"),
    raises("partition of a ball in a box by 1331 spheres (S5, step 0.05)", "import Part, FreeCAD\nfrom hsmplanner import roughing as r\nb = Part.makeSphere(20.0)\nv = r.volume_to_remove(Part.makeBox(100, 100, 100, FreeCAD.Vector(-50, -50, -50)), b)\nr.partition(v, b, 'S5', step=0.05)",
           "ValueError", "by 1331 offsets of the hub: about"),
    raises("program clearance with max turn NaN", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nrc.interpolated_program([Path.Command('G1', {'X': 1.0, 'A': 5.0})], m, max_turn_deg=float('nan'))",
           "ValueError", "max_turn_deg nan must be within [0.0001, 10] degrees"),
    raises("program clearance with max turn 1e-9", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nrc.interpolated_program([Path.Command('G1', {'X': 1.0, 'A': 5.0})], m, max_turn_deg=1e-9)",
           "ValueError", "max_turn_deg 1e-09 must be within"),
    raises("program clearance with orientation None", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nrc.interpolated_program([], m, orientation=None)",
           "ValueError", "orientation None must be 'angles'"),
    raises("program clearance of an angle NaN", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nrc.interpolated_program([Path.Command('G1', {'X': 1.0}), Path.Command('G1', {'X': 2.0, 'A': float('nan')})], m)",
           "ValueError", "block 1 has a position or angle that is not a finite number"),
    raises("program clearance of A1e9", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nrc.interpolated_program([Path.Command('G1', {'X': 1.0}), Path.Command('G1', {'X': 2.0, 'A': 1e9})], m)",
           "ValueError", "use a larger max_turn_deg"),
    raises("program clearance of a number", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nw = r.slanted_slot_block()\nrc.program_clearance(5, m, w.part_brep)",
           "TypeError", "commands must be FreeCAD Path commands"),
    raises("program clearance of a posted arc", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nrc.posted_program('G17 G90\\nG1 X0 Y0 Z50 F100\\nG2 X10 Y0 I5 J0 F100\\n', m)",
           "ValueError", "line 3 is an arc"),
    raises("program clearance of a malformed posted line", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nrc.posted_program('G1 X1 Y\\n', m)",
           "ValueError", "line 1: 'Y' is not a letter followed by a number"),
    holds("program clearance of no commands", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nw = r.slanted_slot_block()\nreport, block = rc.program_clearance([], m, w.part_brep)\nresult = (report.positions, block)",
          "result == (0, -1)"),
    holds("program clearance of an empty posted text", "import Path\nfrom hsmplanner import feedsim, roughing as r\nfrom hsmplanner.app.roughing import commands as rc\nm = feedsim.load_machine('linuxcnc-2.9-xyzac-trt')\nw = r.slanted_slot_block()\nreport, block = rc.program_clearance('', m, w.part_brep)\nresult = (report.positions, block)",
          "result == (0, -1)"),
    raises("removal chip section 0", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, chip_section=0.0)",
           "ValueError", "chip section 0"),
    raises("removal stick-out spacing NaN", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, stick_out_spacing=float('nan'))",
           "ValueError", "stick-out spacing nan mm"),
    raises("removal allowance -1", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, allowance=-1.0)",
           "ValueError", "allowance -1 mm"),
    raises("removal stock mesh stride 1000", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, w.stock_brep, w.part_brep, stock_mesh_stride=1000)",
           "ValueError", "stock mesh stride 1000"),
    raises("removal of a NaN tip", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nm['tip'][1, 0] = float('nan')\nr.simulate_removal(m, w.stock_brep, w.part_brep)",
           "ValueError", "its tip must be finite"),
    raises("removal of a move 1e9 mm long", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nm['tip'][1, 0] = 1e9\nr.simulate_removal(m, w.stock_brep, w.part_brep)",
           "ValueError", "more than 10000000 tool positions"),
    raises("removal with kinds of the wrong length", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nm['kind'] = np.array([0])\nr.simulate_removal(m, w.stock_brep, w.part_brep)",
           "ValueError", "kinds must be an (N,) array"),
    raises("removal with an empty stock", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.simulate_removal(m, '', w.part_brep)", "ValueError", "BREP"),
    holds("removal of no moves leaves everything", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nresult = r.simulate_removal({'tip': np.zeros((0, 3)), 'axis': np.zeros((0, 3)), 'kind': np.zeros(0, dtype=int)}, w.stock_brep, w.part_brep, resolution=1.0).remaining_share",
          "abs(result - 100.0) < 1e-9"),
    raises("join with a NaN clearance", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nm = {'tip': np.array([[0.0, 0, 40], [10.0, 20, 28]]), 'axis': np.array([[0.0, 0, 1], [0.0, 0, 1]]), 'kind': np.array([0, 3])}\nr.join_paths([m, m], w.stock_brep, clearance=float('nan'))",
           "ValueError", "clearance nan mm is outside [0, 1000] mm"),
    # --- the strategy study: absurd grids and settings, refused before anything runs ------------------
    raises("study K NaN", "from hsmplanner import study as st\nst.variants(k=(float('nan'),), p=(10,))", "ValueError", "K = nan is outside ]0, 1["),
    raises("study P -1", "from hsmplanner import study as st\nst.variants(k=(0.5,), p=(-1,))", "ValueError", "P = -1 mm must be positive"),
    raises("study feed NaN", "from hsmplanner import study as st\nst.variants(planes_deg=(0,), feeds_mm_min=(float('nan'),))", "ValueError", "feed nan mm/min must be positive"),
    raises("study 1e9 plane angles", "from hsmplanner import study as st\nst.variants(planes_deg=range(0, 10**9))", "ValueError", "narrow the ranges"),
    raises("study workers -1", "from hsmplanner import study as st\nst.study(part, 'Face4', b1, b2, st.variants(planes_deg=(0,)), workers=-1)", "ValueError", "workers -1 must be an integer"),
    raises("study an empty grid", "from hsmplanner import study as st\nst.study(part, 'Face4', b1, b2, [])", "ValueError", "the grid is empty"),
    raises("refine K tolerance NaN", "from hsmplanner import study as st\nst.refine_k(part, 'Face4', b1, b2, tolerance=float('nan'))", "ValueError", "K tolerance nan"),
    raises("refine K 1e9 evaluations", "from hsmplanner import study as st\nst.refine_k(part, 'Face4', b1, b2, max_evaluations=10**9)", "ValueError", "max evaluations 1000000000"),
    raises("study 1e9 net modes", "from hsmplanner import study as st\nst.variants(k=(0.5,), p=(10,), net_modes=__import__('itertools').repeat('b1_to_b2', 10**9))", "ValueError", "net modes: narrow the ranges"),
    raises("study net mode None", "from hsmplanner import study as st\nst.variants(k=(0.5,), p=(10,), net_modes=[None])", "ValueError", "net mode None is unknown"),
    raises("study scheduler 42", "from hsmplanner import study as st\nst.study(part, 'Face4', b1, b2, st.variants(planes_deg=(0,)), scheduler=42)", "ValueError", "scheduler 42 must be a Dask scheduler's address"),
    raises("study Dask cluster of -1 workers", "from hsmplanner import study as st\nst.local_cluster(-1)", "ValueError", "workers -1 must be an integer in [1, 256]"),
    raises("refine K start NaN", "from hsmplanner import study as st\nst.refine_k(part, 'Face4', b1, b2, start=float('nan'))", "ValueError", "start K nan must lie inside ]0, 1["),
    raises("finishing check cusp NaN", "from hsmplanner import toolpaths as tp\ntp.check_finishing(tool_diameter=10, cusp_height=float('nan'))", "ValueError", "cusp height"),
    raises("study plane angle inf", "from hsmplanner import study as st\nst.variants(planes_deg=(float('inf'),))", "ValueError", "plane angle inf° must lie within [-360, 360]"),
    raises("study range 0:1e9:1e-9", "from hsmplanner import study as st\nst.parse_range('0:1e9:1e-9', 'P')", "ValueError", "P: 1000000000000000000 values (more than 10000)"),
    raises("study range NaN step", "from hsmplanner import study as st\nst.parse_range('0:10:nan', 'K')", "ValueError", "K: 'nan' is not a finite number"),
    raises("study range of a list", "from hsmplanner import study as st\nst.parse_range([1, 2], 'K')", "ValueError", "K: [1, 2] is not text"),
    raises("refine K bounds NaN", "from hsmplanner import study as st\nst.refine_k(part, 'Face4', b1, b2, low=float('nan'))", "ValueError", "K bounds [nan"),
    raises("refine K on a face the part has not", "from hsmplanner import study as st\nst.refine_k(part, 'Face99', b1, b2)", "ValueError", "bottom face 'Face99' does not exist: the part has"),
    raises("study of a face the part has not", "from hsmplanner import study as st\nst.study(part, 'Face99', b1, b2, st.variants(planes_deg=(0,)))", "ValueError", "Face99' does not exist"),
    raises("clearance limit NaN", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nr.check_clearance({'tip': [[0, 0, 40]], 'axis': [[0, 0, 1]]}, w.part_brep, limit=float('nan'))",
           "ValueError", "clearance limit nan mm must be a finite distance"),
    raises("clearance limit -1", "from hsmplanner import roughing as r\nw = r.slanted_slot_block()\nr.check_clearance({'tip': [[0, 0, 40]], 'axis': [[0, 0, 1]]}, w.part_brep, limit=-1)",
           "ValueError", "clearance limit -1 mm"),
    raises("STL of a triangle past the points", "from hsmplanner import roughing as r\nr.save_stl((np.zeros((3, 3)), np.array([[0, 1, 7]])), '/tmp/hsm-bad.stl')",
           "ValueError", "triangle corners must be indices of the 3 points (0 to 2), got 0 to 7"),
    raises("STL of 2-D points", "from hsmplanner import roughing as r\nr.save_stl((np.zeros((3, 2)), np.array([[0, 1, 2]])), '/tmp/hsm-bad.stl')",
           "ValueError", "save_stl takes ((N, 3) points"),
    # --- the FreeCAD 1.0 port's helpers: comments, script arguments, exact boxes -----------------------------
    holds("a head comment of nested parentheses, a 1e6-character label and a number",
          "from hsmplanner.app.op_comments import comment_text\n"
          "result = [comment_text('a ((b)) c)'), comment_text('(' * 10**6), comment_text(1e9), comment_text('')]",
          "result[0] == 'a [[b]] c]' and '(' not in result[1] and len(result[1]) == 10**6 and result[2] == '1000000000.0'"
          " and result[3] == ''"),
    holds("head comments mended in an empty program",
          "import types\nfrom hsmplanner.app.op_comments import mend_leading_comments\ncommands = []\n"
          "mend_leading_comments(commands, types.SimpleNamespace(Label='x (y)', Comment='(z'))",
          "commands == []"),
    holds("script arguments of an empty argv, freecadcmd alone, and a script with none",
          "from hsmplanner.scripting import script_arguments\n"
          "result = [script_arguments([]), script_arguments(['freecadcmd']), script_arguments(['freecadcmd', 'a.py'])]",
          "result == [[], [], []]"),
    holds("the exact box of no shape, a null shape and an empty compound",
          "from hsmplanner.app.stock_heights import exact_box, exact_stock_z\n"
          "result = [exact_box([]), exact_box([Part.Shape()]), exact_box([None]), exact_stock_z(object())]",
          "result == [None, None, None, None]"),
]


def run_cases(names=None, timeout_s=TIMEOUT_S):
    """Runs the cases (all by default) in child processes; returns {name: report dict}."""
    cases = {c["name"]: c for c in CASES}
    pending = [c["name"] for c in CASES if names is None or c["name"] in names]
    reports = {}
    while pending:
        env = dict(os.environ, HSM_BAD_INPUT_CASES=json.dumps([cases[name] for name in pending]))
        child = subprocess.Popen(["freecadcmd", CHILD], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                                 text=True, bufsize=1)
        running, started = None, time.time()
        try:
            while True:
                ready, _, _ = select.select([child.stdout], [], [], 1.0)
                if ready:
                    line = child.stdout.readline()
                    if not line:
                        break  # the child ended
                    if line.startswith("HSM-CASE-START "):
                        running, started = json.loads(line[len("HSM-CASE-START "):]), time.time()
                    elif line.startswith("HSM-CASE-RESULT "):
                        report = json.loads(line[len("HSM-CASE-RESULT "):])
                        reports[report["name"]] = report
                        pending.remove(report["name"])
                        running = None
                if running is not None and time.time() - started > timeout_s:
                    child.kill()
                    break
                if not ready and child.poll() is not None:
                    break
        finally:
            if child.poll() is None:
                child.kill()
            child.wait()
        if running is not None:
            elapsed = time.time() - started
            reports[running] = dict(name=running, outcome="hang" if elapsed > timeout_s else "crash",
                                    detail="the child %s after %.0f s (exit %s)" % (
                                        "was killed" if elapsed > timeout_s else "died", elapsed, child.returncode))
            pending.remove(running)
        elif pending and child.returncode not in (0, None):
            raise RuntimeError("the bad-input child failed before any case (exit %s)" % child.returncode)
        elif pending:
            for name in pending:
                reports[name] = dict(name=name, outcome="missing", detail="the child ended without running it")
            break
    return reports
