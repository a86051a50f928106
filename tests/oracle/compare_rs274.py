#!/usr/bin/python3
"""LinuxCNC's own interpreter as the oracle of the reading (docs/oracle.md): `rs274`, the standalone
interpreter of Debian's linuxcnc-uspace, prints the canonical moves it makes of a program; hsm-feedsim's
--csv gives the moves our reader made. Both are compared in order: the kind (traverse, feed, arc), the end
point, the arc centre, the rotary axes and the programmed feed, to rs274's printed precision (4 decimals of the
program's unit: the comparison cannot be finer).

    /usr/bin/python3 tests/oracle/compare_rs274.py [PROGRAM ...] --feedsim build/freecad-1.1/bin/hsm-feedsim

Without programs: the LinuxCNC programs of ../shared/data/realworld_gcode/linuxcnc/ and tests/oracle/programs*/.
Prints one row per program (moves, first difference) and exits 1 when a program's moves differ, 2 when rs274
is missing. A program rs274 refuses (a HAL pin, a remapped M-code of one machine's configuration) is listed
with rs274's reason and not compared. Standard library only.
"""
import argparse
import csv
import glob
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
CORPUS = os.path.join(os.path.dirname(REPO), "shared", "data", "realworld_gcode", "linuxcnc")
INCH = 25.4
TOLERANCE_UNITS = 0.5e-4 + 1e-9  # rs274 prints 4 decimals of the program's unit
CANON = re.compile(r"^\s*\d+\s+N\S*\s+([A-Z0-9_]+)\((.*)\)\s*$")
MOVES = ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED")


PLANES = {"CANON_PLANE_XY": (0, 1, 2), "CANON_PLANE_XZ": (2, 0, 1), "CANON_PLANE_YZ": (1, 2, 0)}  # first, second, axis


class Move:
    """A canonical move: kind, end (x, y, z) mm, rotary end (a, b, c) deg, arc centre in its plane (two
    coordinates, mm, with their axis indices) or None, feed (mm/min, or 1/min in inverse time) or None."""

    def __init__(self, kind, end, rotary, centre, feed):
        self.kind, self.end, self.rotary, self.centre, self.feed = kind, end, rotary, centre, feed
        self.nowhere = False


def rs274_moves(program, tool_table):
    """[Move] as rs274 runs the program; (None, what rs274 said) when it stops on an error."""
    run = subprocess.run(["rs274", "-g", "-t", tool_table, program], capture_output=True, text=True, timeout=120,
                         stdin=subprocess.DEVNULL)
    unit, feed, feed_unit, inverse, plane, said = 1.0, 0.0, 1.0, False, PLANES["CANON_PLANE_XY"], []
    moves, position = [], ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    # rs274 prints positions in the program's coordinates; the machine is there plus the work offset (G54…,
    # G10) and G92's, which it prints as they change. Our reader gives the machine's position.
    work, shift = (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)

    def machine(values):
        return tuple(v * unit + w + g for v, w, g in zip(values, work, shift))
    for line in (run.stdout + "\n" + run.stderr).splitlines():
        match = CANON.match(line)
        if not match:
            if line.strip() and line.strip() != "executing":
                said.append(line.strip())  # rs274 stopped: its message, then the line it stopped at
            continue
        name, arguments = match.group(1), [a.strip() for a in match.group(2).split(",")]
        if name == "USE_LENGTH_UNITS":
            unit = INCH if "INCHES" in arguments[0] else 1.0
        elif name == "SET_G5X_OFFSET":
            work = tuple(float(v) * unit for v in arguments[1:4])
        elif name == "SET_G92_OFFSET":
            shift = tuple(float(v) * unit for v in arguments[0:3])
        elif name == "SET_FEED_RATE":
            # milltask's canon converts F to mm/min when it is set, in the units then in force (rs274 executes F
            # before the line's G20/G21): a later G20 does not change the speed
            feed, feed_unit = float(arguments[0]), unit
        elif name == "SET_FEED_MODE":
            inverse = arguments[-1].strip() == "1"
        elif name == "SELECT_PLANE":
            plane = PLANES.get(arguments[0], plane)
        elif name == "RIGID_TAP":  # in to (x, y, z) at the spindle's speed times the pitch, and back out
            bottom = machine(float(v) for v in arguments[:3])
            for end in (bottom, position[0]):
                moves.append(Move("STRAIGHT_FEED", end, position[1], None, None))
        elif name in MOVES:
            values = [float(v) for v in arguments]
            rate = feed if inverse else feed * feed_unit
            if name == "ARC_FEED":
                first, second, axis = plane
                end = [0.0, 0.0, 0.0]
                end[first], end[second], end[axis] = values[0], values[1], values[5]
                offset = machine((0.0, 0.0, 0.0))
                centre = ((first, values[2] * unit + offset[first]), (second, values[3] * unit + offset[second]))
                move = Move(name, machine(end), tuple(values[6:9]), centre, rate)
            else:
                move = Move(name, machine(values[:3]), tuple(values[3:6]), None,
                            None if name == "STRAIGHT_TRAVERSE" else rate)
            # a move that goes nowhere (as printed: 4 decimals) may make no block in our reader
            move.nowhere = max(abs(a - b) for a, b in zip(move.end + move.rotary, position[0] + position[1])) < 1e-9
            moves.append(move)
            position = (move.end, move.rotary)
    if said:
        return None, " / ".join(said[:2])[:200]
    return moves, None


def our_moves(feedsim, program, machine, out):
    """[Move] as our reader reads the program (hsm-feedsim --moves); (None, reason) if it refuses."""
    path = os.path.join(out, os.path.basename(program) + ".csv")
    run = subprocess.run([feedsim, program, "--machine", machine, "--moves", path], capture_output=True, text=True,
                         timeout=600)
    if run.returncode != 0:
        return None, (run.stderr.strip() or run.stdout.strip())[:300]
    kinds = {"G0": "STRAIGHT_TRAVERSE", "G1": "STRAIGHT_FEED"}
    moves = []
    with open(path) as stream:
        for row in csv.DictReader(stream):
            kind = kinds.get(row["motion"], "ARC_FEED")
            end = tuple(float(row[k]) for k in ("x", "y", "z"))
            centre = tuple(float(row[k]) for k in ("centre_x", "centre_y", "centre_z"))
            moves.append(Move(kind, end, tuple(float(row["rotary_%d" % k]) for k in (1, 2, 3)),
                              centre if kind == "ARC_FEED" else None,
                              None if kind == "STRAIGHT_TRAVERSE" else float(row["feed_mm_min"])))
    return moves, None


def machine_of(program):
    """The machine a program was written for: the oracle's machine file of its folder, or by its name."""
    folder = os.path.basename(os.path.dirname(program))
    for suffix in ("xyzac", "xyzbc"):
        if folder == "programs_" + suffix:
            return os.path.join(HERE, "machine_%s.json" % suffix)
    if folder == "programs":
        return os.path.join(HERE, "machine.json")
    return "linuxcnc-2.9-xyzac-trt" if "xyzac" in os.path.basename(program) else "linuxcnc-2.9"


def first_difference(theirs, ours, unit):
    """The first move that differs (index in rs274's moves, what), or None. A move rs274 prints where the one
    before ended is skipped when ours has no block for it: our reader makes none of a move of zero length, and
    rs274's 4 decimals print a tiny move as one."""
    tolerance = TOLERANCE_UNITS * unit + 1e-6  # rs274's 4 printed decimals of the program's unit
    j = 0
    for index, a in enumerate(theirs):
        if j == len(ours):
            if a.nowhere:
                continue
            return index, "rs274 %d moves, ours %d" % (len(theirs), len(ours))
        difference = differs(a, ours[j], tolerance, unit)
        if difference is None:
            j += 1
        elif not a.nowhere:
            return index, difference
    if j < len(ours):
        return len(theirs), "rs274 %d moves, ours %d" % (len(theirs), len(ours))
    return None


def differs(a, b, tolerance, unit):
    """What differs between rs274's move a and ours b, or None."""
    if a.kind != b.kind:
        return "rs274 %s, ours %s" % (a.kind, b.kind)
    if max(abs(x - y) for x, y in zip(a.end, b.end)) > tolerance:
        return "end rs274 %s, ours %s" % (fmt(a.end), fmt(b.end))
    if max(abs(x - y) for x, y in zip(a.rotary, b.rotary)) > 0.5e-4 + 1e-6:
        return "rotary axes rs274 %s, ours %s" % (fmt(a.rotary), fmt(b.rotary))
    if a.centre is not None and max(abs(v - b.centre[axis]) for axis, v in a.centre) > tolerance:
        return "arc centre rs274 %s, ours %s" % (fmt([v for _, v in a.centre]), fmt(b.centre))
    if a.feed is not None and abs(a.feed - b.feed) > 0.5e-4 * unit + 0.5e-4 + 1e-9 * a.feed:  # both printed
        return "feed rs274 %.4f, ours %.4f mm/min" % (a.feed, b.feed)
    return None


def fmt(values):
    return "(%s)" % ", ".join("%.4f" % v for v in values)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("programs", nargs="*")
    parser.add_argument("--feedsim", required=True, help="the hsm-feedsim to compare (or a wrapper running it)")
    parser.add_argument("--machine", default=None, help="for every program (default: as the oracle's, by folder)")
    parser.add_argument("--out", default=os.path.join(REPO, "build", "rs274"),
                        help="folder for the moves written (inside the repository: seen from a FreeCAD root too)")
    args = parser.parse_args()
    if shutil.which("rs274") is None:
        print("rs274 is missing: install Debian's linuxcnc-uspace (it has the standalone interpreter)")
        return 2
    programs = args.programs or sorted(glob.glob(os.path.join(CORPUS, "*.ngc")) +
                                       glob.glob(os.path.join(HERE, "programs*", "*.ngc")))
    os.makedirs(args.out, exist_ok=True)
    out = tempfile.mkdtemp(prefix="compare.", dir=args.out)
    tool_table = os.path.join(out, "tool.tbl")
    with open(tool_table, "w") as stream:  # every pocket a real program calls, as the oracle's machine has
        # diameter 0: cutter radius compensation (G41/G42), which the simulator does not apply, moves nothing
        stream.writelines("T%d P%d D0 Z0 ;\n" % (t, t) for t in range(1, 100))
    failed = 0
    print("%-40s %7s  %s" % ("program", "moves", "result"))
    for program in programs:
        theirs, refused = rs274_moves(program, tool_table)
        name = os.path.basename(program)
        if theirs is None:
            print("%-40s %7s  rs274 refuses it: %s" % (name, "-", refused))
            continue
        ours, error = our_moves(args.feedsim, program, args.machine or machine_of(program), out)
        if ours is None:
            print("%-40s %7d  OURS REFUSES: %s" % (name, len(theirs), error))
            failed += 1
            continue
        unit = INCH if re.search(r"\bG20\b", open(program, errors="replace").read(), re.I) else 1.0
        difference = first_difference(theirs, ours, unit)
        if difference is None:
            print("%-40s %7d  same moves" % (name, len(theirs)))
        else:
            failed += 1
            print("%-40s %7d  DIFFERENT at move %d: %s" % (name, len(theirs), difference[0] + 1, difference[1]))
    shutil.rmtree(out, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
