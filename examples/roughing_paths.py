"""5-axis roughing part 2, headless: the paper's impeller (one channel) and the slanted slot block swept by the five
strategies (S1 planes, S2 coaxial cylinders, S3 setup planes, S4 offsets of the stock skin, S5 offsets of the hub
or floor) with the paper's Ø8 r1 torus at 70 % radial engagement, each path checked for clearance independently,
posted for the A/C trunnion 840D (TRAORI) and LinuxCNC's xyzac-trt machine, and the posted programs simulated on
those machines. A strategy a part has no face for (S2 on the slot block: no cylindrical crossable face) is
listed with the reason.

    freecadcmd examples/roughing_paths.py [OUTPUT_DIR]      (default: out/)

Writes roughing_paths.png and roughing_paths_slot.png (the paths with their tool axes), roughing_paths.csv (per
part and strategy: passes, path lengths, the closest approach to the part, the spread of the tool axis, the
simulated time on each machine and what held the speed) and roughing_<part>_<strategy>_840d.mpf / _linuxcnc.ngc.
"""
import csv
import os
import time

import numpy as np

from hsmplanner import feedsim, roughing
from hsmplanner.app.posts import linuxcnc5x_post, siemens840d_post
from hsmplanner.app.roughing.commands import ProgramSource, sweep_commands
from hsmplanner.plots.roughing import save_sweeps
from hsmplanner.scripting import output_dir, run_script

STRATEGIES = ("S1", "S2", "S3", "S4", "S5")
FEED_MM_MIN = 2000.0  # a roughing feed of the paper's Ø8 torus in full slot
MACHINES = {"840d": ("mikron-ucp710-ac-840d", siemens840d_post, "--machine=mikron-ucp710-ac-840d", ".mpf"),
            "linuxcnc": ("linuxcnc-2.9-xyzac-trt", linuxcnc5x_post, "--machine=linuxcnc-2.9-xyzac-trt", ".ngc")}
COLUMNS = ["part", "strategy", "passes", "moves", "cutting_mm", "ramp_mm", "link_mm", "rapid_mm", "closest_mm",
           "too_close", "axis_spread_deg", "sweep_s", "840d_time_s", "840d_length_over_feed_s", "840d_held_by",
           "linuxcnc_time_s", "linuxcnc_length_over_feed_s", "linuxcnc_held_by", "note"]


def axis_spread_deg(paths):
    """The largest angle between the first tool axis and any other: 0 for 3 and 3+2 axes."""
    axes = np.asarray(paths.moves["axis"])
    return float(np.degrees(np.arccos(np.clip(axes @ axes[0], -1.0, 1.0))).max()) if len(axes) else 0.0


def post_and_simulate(row, paths, name, out):
    for key, (machine_name, post, args, suffix) in MACHINES.items():
        machine = feedsim.load_machine(machine_name)
        program = os.path.join(out, "roughing_%s_%s_%s%s" % (row["part"], name, key, suffix))
        commands = sweep_commands(paths, machine, FEED_MM_MIN)
        post.export([ProgramSource("%s %s" % (name, roughing.STRATEGY_LABELS[name]), commands)], program, args)
        simulated = feedsim.simulate(program, machine)
        shares = feedsim.speed_limit_shares(simulated.summary)
        row["%s_time_s" % key] = round(simulated.summary.total_time, 1)
        row["%s_length_over_feed_s" % key] = round(simulated.summary.naive_time, 1)
        row["%s_held_by" % key] = ", ".join("%s %.0f %%" % (k, 100 * v) for k, v in list(shares.items())[:3])


def sweep_part(label, shapes, out):
    volume = roughing.volume_to_remove(shapes.stock_brep, shapes.part_brep)
    solid = volume.solids[0]
    rows, drawn = [], []
    for name in STRATEGIES:
        row = dict.fromkeys(COLUMNS, "")
        row.update(part=label, strategy=name)
        start = time.perf_counter()
        try:
            result = roughing.partition(solid, shapes.part_brep, name)
        except ValueError as error:  # the part has no face for this strategy: say why, go on
            row["note"] = str(error)
            rows.append(row)
            print("%s %s: %s" % (label, name, error))
            continue
        paths = roughing.sweep(result, solid, shapes.part_brep, shapes.stock_brep)
        swept = time.perf_counter() - start
        report = roughing.check_clearance(paths, shapes.part_brep)
        row.update(passes=len(paths.passes), moves=len(paths.moves["kind"]), cutting_mm=round(paths.cutting_length, 1),
                   ramp_mm=round(paths.ramp_length, 1), link_mm=round(paths.link_length, 1),
                   rapid_mm=round(paths.rapid_length, 1), closest_mm=round(report.minimum, 3),
                   too_close=report.too_close, axis_spread_deg=round(axis_spread_deg(paths), 1), sweep_s=round(swept, 2),
                   note="; ".join(paths.warnings))
        post_and_simulate(row, paths, name, out)
        rows.append(row)
        drawn.append((name, paths))
        print("%s %s: %d passes, %.0f mm cutting, closest %.3f mm, axis spread %.0f°; 840D %.1f s (%s), LinuxCNC %.1f s "
              "(%s)" % (label, name, row["passes"], row["cutting_mm"], row["closest_mm"], row["axis_spread_deg"],
                        row["840d_time_s"], row["840d_held_by"], row["linuxcnc_time_s"], row["linuxcnc_held_by"]))
    return rows, drawn


def main(argv):
    out = output_dir(argv)
    rows = []
    for label, shapes, picture, title in (
            ("impeller", roughing.impeller(), "roughing_paths.png",
             "One impeller channel swept with a Ø8 r1 torus, 70 % radial engagement, 8 mm levels"),
            ("slot", roughing.slanted_slot_block(), "roughing_paths_slot.png",
             "The slanted slot block swept with a Ø8 r1 torus, 70 % radial engagement, 8 mm levels")):
        part_rows, drawn = sweep_part(label, shapes, out)
        rows += part_rows
        save_sweeps(drawn, os.path.join(out, picture), title)
    with open(os.path.join(out, "roughing_paths.csv"), "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    return rows


run_script(main)
