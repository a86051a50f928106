#!/usr/bin/python3
"""Writes the G-code programs of the LinuxCNC oracle (docs/oracle.md) into tests/oracle/programs/.

Every program is in mm, G21 G90 G17, absolute, starts where the machine is after homing (X0 Y0 Z0) and ends
with M2. The programs are what a CAM system or a person would write; none is tuned to what either planner
does well. Run it again after changing a program here: `python3 tests/oracle/make_programs.py`.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PROGRAMS = os.path.join(HERE, "programs")


def fmt(value):
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def move(code, x=None, y=None, z=None, a=None, b=None, c=None, **words):
    parts = [code]
    for name, value in (("X", x), ("Y", y), ("Z", z), ("A", a), ("B", b), ("C", c)):
        if value is not None:
            parts.append(name + fmt(value))
    for name, value in words.items():
        parts.append(name + fmt(value))
    return " ".join(parts)


def program(title, mode, feed, body):
    """The common frame: a comment, units and plane, the path control mode, the feed, the moves, M2."""
    return [f"({title})", "G21 G90 G17", mode, f"F{feed}"] + body + ["M2"]


def line():
    return [move("G1", x=100)]


def square(side=50.0):
    return [move("G1", x=side), move("G1", y=side), move("G1", x=0), move("G1", y=0)]


def circle(radius, turns):
    """Full circles through the start point (centre at X=radius), four clockwise quarter arcs each, R format."""
    quarter = [(radius, radius), (2 * radius, 0), (radius, -radius), (0, 0)]
    return [move("G2", x=x, y=y, R=radius) for _ in range(turns) for x, y in quarter]


def chord_circle(radius, chords):
    """One circle through the start point (centre at X=radius), clockwise, as straight chords."""
    body = []
    for i in range(1, chords + 1):
        angle = math.pi - 2 * math.pi * i / chords  # clockwise from the start point at 180 degrees
        body.append(move("G1", x=radius + radius * math.cos(angle), y=radius * math.sin(angle)))
    return body


def pocket(length=60.0, width=30.0, step=2.0):
    """A zig-zag clearing a parallelogram pocket: long sides along X, each ending in a 135 degree turn into a
    short step-over (2 mm in Y, 2 mm back in X: 2.83 mm long), which joins the next long side at 45 degrees."""
    body, x, y, direction = [], 0.0, 0.0, 1
    passes = int(round(width / step)) + 1
    for k in range(passes):
        x += direction * length
        body.append(move("G1", x=x, y=y))
        if k == passes - 1:
            break
        x -= direction * step
        y += step
        body.append(move("G1", x=x, y=y))
        direction = -direction
    return body


def raster(passes=20, length=60.0, step=1.0):
    """A zig-zag: passes along X, each joined to the next by a 1 mm step in Y (two 90 degree turns)."""
    body, x, y = [], 0.0, 0.0
    for k in range(passes):
        x = length if k % 2 == 0 else 0.0
        body.append(move("G1", x=x, y=y))
        if k < passes - 1:
            y += step
            body.append(move("G1", x=x, y=y))
    return body


def spiral(chord=0.05, r_start=20.0, r_end=5.0, turns=3, depth=3.0):
    """A conical 3D spiral: the radius shrinks from r_start to r_end while Z goes down by depth over the turns,
    as 0.05 mm chords (the points are spaced by arc length). Starts with a straight approach from X0 Y0 Z0."""
    samples = 200000
    total = 2 * math.pi * turns

    def point(t):
        s = t / total
        r = r_start + (r_end - r_start) * s
        return (r * math.cos(t), r * math.sin(t), -depth * s)

    body = [move("G1", *point(0.0))]
    previous = point(0.0)
    walked = 0.0
    for i in range(1, samples + 1):
        p = point(total * i / samples)
        walked += math.dist(p, previous)
        previous = p
        if walked >= chord or i == samples:
            body.append(move("G1", *p))
            walked = 0.0
    return body


def sine(chord=0.5, length=100.0, amplitude=5.0, wavelength=25.0):
    """A freeform chain: y = A sin(2 pi x / wavelength) over 0..length as 0.5 mm chords (by arc length)."""
    samples = 100000
    body, previous, walked = [], (0.0, 0.0), 0.0
    for i in range(1, samples + 1):
        x = length * i / samples
        p = (x, amplitude * math.sin(2 * math.pi * x / wavelength))
        walked += math.dist(p, previous)
        previous = p
        if walked >= chord or i == samples:
            body.append(move("G1", *p))
            walked = 0.0
    return body


def rotary_chain(centre, radius=30.0, chords=200, turn=360.0, tilt=None):
    """A circle of the tool tip (workpiece frame) as straight chords, C turning with it by turn/chords per chord
    (1.8 degrees and 0.94 mm on R 30: the chains of short 5-axis blocks a post writes for a turned part);
    `centre` on the C axis (0, 0) or off it. Starts with a move to the circle's first point (at +X from the
    centre), with the tilting axis `tilt` = (letter, degrees) set there."""
    cx, cy = centre
    first = {"b" if tilt and tilt[0] == "B" else "a": tilt[1]} if tilt else {}
    body = [move("G1", x=cx + radius, y=cy, **first)]
    for i in range(1, chords + 1):
        angle = 2 * math.pi * i / chords
        body.append(move("G1", x=cx + radius * math.cos(angle), y=cy + radius * math.sin(angle), c=turn * i / chords))
    return body


def pole_line():
    """A line of the tip beside the pole: A at 0.5 degrees, C swinging 180 degrees over 40 mm, as a post writes
    a tool axis passing 0.5 degrees from C's axis."""
    return [move("G1", x=-20, y=2, a=0.5), move("G1", x=20, y=2, a=0.5, c=180)]


def xyzac_programs():
    """The 5-axis programs on the table A/C trunnion (xyzac-trt-kins, TCP: X Y Z are the tool tip)."""
    return {
        "ac_01_c_turn_fixed_tip": program("C turns 90 degrees about a fixed tip 50 mm off its axis", "G64", 3000,
                                          [move("G1", x=50), move("G1", c=90, F=3600)]),
        "ac_02_c_turn_fast": program("C turns 360 degrees at F60000 deg/min, above its speed limit", "G64", 3000,
                                     [move("G1", x=50), move("G1", c=360, F=60000)]),
        "ac_03_a_tilt": program("A tilts 60 degrees about a fixed tip", "G64", 3000,
                                [move("G1", y=30, z=20), move("G1", a=60, F=1800)]),
        "ac_04_line_c": program("a 100 mm line turning C 90 degrees", "G64", 3000, [move("G1", x=100, c=90)]),
        "ac_05_line_a_c": program("a line in X Y Z turning A and C", "G64", 3000,
                                  [move("G1", x=60, y=20, z=-10, a=30, c=45)]),
        "ac_06_pole_f2000": program("tip line beside the pole, C swings 180 degrees", "G64", 2000, pole_line()),
        "ac_07_pole_f6000": program("tip line beside the pole, C swings 180 degrees", "G64", 6000, pole_line()),
        "ac_08_chain_c_axis_f2000": program("200 chords of R 30 about C's axis, C turning with them", "G64", 2000,
                                            rotary_chain((0, 0))),
        "ac_09_chain_c_axis_f6000": program("200 chords of R 30 about C's axis, C turning with them", "G64", 6000,
                                            rotary_chain((0, 0))),
        "ac_10_chain_offset_f2000": program("200 chords of R 30 about X40 Y0, C turning with them", "G64", 2000,
                                            rotary_chain((40, 0))),
        "ac_11_chain_offset_f6000": program("200 chords of R 30 about X40 Y0, C turning with them", "G64", 6000,
                                            rotary_chain((40, 0))),
        "ac_12_chain_c_axis_g61": program("200 chords of R 30 about C's axis, C turning, exact stop", "G61", 2000,
                                          rotary_chain((0, 0))),
        "ac_13_chain_tilted_p001": program("200 chords of R 30 at A 30, C turning, G64 P0.01 as the posts write",
                                           "G64 P0.01", 3000, rotary_chain((0, 0), tilt=("A", 30))),
    }


def xyzbc_programs():
    """The 5-axis programs on the table B/C trunnion (xyzbc-trt-kins, TCP)."""
    return {
        "bc_01_b_tilt": program("B tilts 45 degrees about a fixed tip", "G64", 3000,
                                [move("G1", x=30, z=20), move("G1", b=45, F=1800)]),
        "bc_02_line_b_c": program("a line in X Y Z turning B and C", "G64", 3000,
                                  [move("G1", x=50, y=30, z=-5, b=-30, c=60)]),
        "bc_03_chain_tilted": program("200 chords of R 30 about C's axis at B 30, C turning with them", "G64", 3000,
                                      rotary_chain((0, 0), tilt=("B", 30))),
    }


def offsets_and_cycles():
    """Work offsets (G10 L2 / L20, G55), G92, G28 and G53, and canned cycles in G91 with L repeats."""
    return ["G0 X10 Y10 Z5", "G10 L2 P2 X20 Y-5 Z0", "G55 G0 X0 Y0", "G1 X15 Z2", "G54 G0 X5 Y5",
            "G92 X0 Y0", "G1 X10 Y10", "G92.1", "G0 X30 Y0", "G10 L20 P1 X0 Y0", "G1 X5 Y5", "G10 L2 P1 X0 Y0 Z0",
            "G0 Z10", "G91 G99 G81 X6 Y0 Z-4 R-3 L3", "G90 G80", "G98 G83 X40 Y20 Z-6 R2 Q1.5", "X44 Y20",
            "G73 X48 Y20 Z-3 R1 Q1", "G85 X52 Y20 Z-2 R1", "G89 X56 Y20 Z-2 R1 P0.5", "G82 X60 Y20 Z-2 R1 P0.2",
            "G80", "G28 Z20", "G53 G0 X10 Y10", "G0 X0 Y0 Z5"]


def all_programs():
    pocket_title = "pocket 60 x 30 mm zig-zag, 2 mm step-overs at 135 degrees"
    return {
        "01_line_g61": program("100 mm line, exact stop", "G61", 6000, line()),
        "02_line_g64": program("100 mm line, blending", "G64", 6000, line()),
        "03_square_g61": program("50 mm square, exact stop", "G61", 6000, square()),
        "04_square_g64": program("50 mm square, blending without tolerance", "G64", 6000, square()),
        "05_circle_r2": program("3 circles R 2 mm as G2 quarter arcs, R format", "G64", 6000, circle(2.0, 3)),
        "06_circle_r20": program("1 circle R 20 mm as G2 quarter arcs, R format", "G64", 6000, circle(20.0, 1)),
        "07_chords720_r20": program("circle R 20 mm as 720 chords", "G64", 4000, chord_circle(20.0, 720)),
        "08_pocket_g61": program(pocket_title + ", exact stop", "G61", 6000, pocket()),
        "09_pocket_g64": program(pocket_title + ", blending without tolerance", "G64", 6000, pocket()),
        "10_pocket_g64_p001_q001": program(pocket_title + ", G64 P0.01 Q0.01", "G64 P0.01 Q0.01", 6000, pocket()),
        "11_raster_g64": program("raster: 20 passes 60 mm, 1 mm apart", "G64", 4000, raster()),
        "12_spiral_p001": program("3D conical spiral of 0.05 mm chords, Q defaults to P", "G64 P0.01", 6000,
                                  spiral()),
        "13_spiral_p001_q0": program("3D conical spiral of 0.05 mm chords, naive CAM off", "G64 P0.01 Q0", 6000,
                                     spiral()),
        "14_sine_g64": program("sine wave A 5 mm, wavelength 25 mm, 0.5 mm chords", "G64", 6000, sine()),
        "15_sine_g64_p001": program("sine wave A 5 mm, wavelength 25 mm, 0.5 mm chords", "G64 P0.01", 6000,
                                    sine()),
        "16_offsets_cycles": program("work offsets, G92, G28, G53 and canned cycles in G91 with L", "G64", 1200,
                                     offsets_and_cycles()),
    }


def main():
    for folder, programs in ((PROGRAMS, all_programs()), (PROGRAMS + "_xyzac", xyzac_programs()),
                             (PROGRAMS + "_xyzbc", xyzbc_programs())):
        os.makedirs(folder, exist_ok=True)
        for name, lines in programs.items():
            path = os.path.join(folder, name + ".ngc")
            with open(path, "w") as f:
                f.write("\n".join(lines) + "\n")
            print(f"{path}: {len(lines)} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
