"""The machining-direction paper's two cases, headless, with a validation by simulation.

    freecadcmd examples/machining_direction.py [OUTPUT_DIR]      (default: out/)

Case 1: the top of a cylinder of radius 10 about Y, Ø10 ball, Sz 0.01 mm, a_max 3 m/s²: the acceptable and
optimal directions against the programmed feed (the paper's Fig. 10): direction_case1_feeds.png and .csv.
Case 2: a 100 × 100 × 15 mm surface of valleys, Ø10 ball, fz 0.2 mm at 6000 mm/min and 15,000 rpm, the
Mikron model's slowest axis: the optimal direction (direction_case2.png: the beams' rate and the map of
local best directions), then parallel planes every 10° from 0° to 180°, each simulated on the Mikron UCP
710 / 840D model (direction_case2_validation.png and .csv: the paper's Fig. 12), with the choices of the
beams and of the least predicted time marked.
"""
import csv
import math
import os

import numpy as np

import hsmplanner
from hsmplanner.app import surfaces
from hsmplanner.direction import directions_over_feeds, fastest, simulated_directions
from hsmplanner.plots.direction import save_direction_report, save_direction_validation, save_directions_over_feeds
from hsmplanner.scripting import output_dir, run_script

MACHINE = "mikron-ucp710-840d"
CASE1 = dict(tool_diameter=10.0, scallop=0.01, spindle_rpm=18000.0, teeth=4, acceleration_m_s2=3.0, machine=None)
CASE2 = dict(tool_diameter=10.0, scallop=0.01, feed_per_tooth=0.2, spindle_rpm=15000.0, teeth=2, machine=MACHINE)


def case1(out):
    face = surfaces.cylinder_top()
    feeds = np.arange(2000.0, 30001.0, 1000.0)
    rows = directions_over_feeds(face, feeds, grid=21, **CASE1)
    switching = math.sqrt((10.0 + 5.0) * 3000.0) * 60.0
    save_directions_over_feeds(
        rows, os.path.join(out, "direction_case1_feeds.png"),
        "Case 1: cylinder R10 about Y, Ø10 ball, Sz 0.01 mm, a_max 3 m/s², Z 4 at 18,000 rpm\n"
        "the optimum leaves 0° above √((R+Ro)·a) = %.0f mm/min" % switching)
    with open(os.path.join(out, "direction_case1_feeds.csv"), "w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(["feed_mm_min", "optimal_deg", "acceptable_deg"])
        for feed, optimum, acceptable in rows:
            writer.writerow([int(feed), optimum, " ".join("%g" % a for a in acceptable)])
    last_transverse = max(feed for feed, optimum, _ in rows if optimum == 0.0)
    print("case 1: optimal direction 0° up to %.0f mm/min (its formula: %.0f), %.0f° at %.0f mm/min"
          % (last_transverse, switching, rows[-1][1], feeds[-1]))


def case2(out):
    face = surfaces.valleys()
    result = hsmplanner.optimal_direction(face, **CASE2)
    rows = simulated_directions(face, "Face1", range(0, 181, 10), tool_diameter=10.0, scallop=0.01,
                                feed_mm_min=6000.0, machine=MACHINE)
    for row in rows:
        print("  planes at %3d°: %4d passes, %6.1f s simulated (%6.1f s by length/feed)"
              % (row["angle_deg"], row["passes"], row["simulated_s"], row["length_over_feed_s"]))
    save_direction_report(result, os.path.join(out, "direction_case2.png"),
                          "Case 2: valleys 100 × 100 × 15 mm at 45°, Ø10 ball, fz 0.2 mm, 6000 mm/min")
    with open(os.path.join(out, "direction_case2_validation.csv"), "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows({k: round(v, 1) if isinstance(v, float) else v for k, v in row.items()} for row in rows)
    save_direction_validation(
        rows, [("directional beams", result.angle_deg), ("least predicted time", result.fastest_angle_deg)],
        os.path.join(out, "direction_case2_validation.png"),
        "Case 2: parallel planes every 10°, simulated on the Mikron UCP 710 / 840D")
    best = fastest(rows)
    print("case 2: directional beams %.0f° (α %.3f), least predicted time %.0f°, fastest simulated %.0f° (%.1f s)"
          % (result.angle_deg, result.alpha, result.fastest_angle_deg, best["angle_deg"], best["simulated_s"]))


def main(argv):
    out = output_dir(argv)
    case1(out)
    case2(out)


run_script(main)
