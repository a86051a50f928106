"""5-axis roughing part 2 on the paper's impeller, headless: one channel swept by the strategies swept so far
(S1 planes, S2 coaxial cylinders, S3 setup planes) with the paper's Ø8 r1 torus at 70 % radial engagement,
each path checked for clearance independently, posted for the A/C trunnion 840D (TRAORI) and LinuxCNC's
xyzac-trt machine, and the posted programs simulated on those machines.

    freecadcmd examples/roughing_paths.py [OUTPUT_DIR]      (default: out/)

Writes roughing_paths.png (the three paths of the channel with their tool axes), roughing_paths.csv (per
strategy: passes, path lengths, the closest approach to the part, the simulated time on each machine and what
held the speed) and roughing_<strategy>_840d.mpf / _linuxcnc.ngc (the programs).
"""
import csv
import os
import time

from hsmplanner import feedsim, roughing
from hsmplanner.app.posts import linuxcnc5x_post, siemens840d_post
from hsmplanner.app.roughing_commands import ProgramSource, sweep_commands
from hsmplanner.plots.roughing import save_sweeps
from hsmplanner.scripting import output_dir, run_script

STRATEGIES = ("S1", "S2", "S3")
FEED_MM_MIN = 2000.0  # a roughing feed of the paper's Ø8 torus in full slot
MACHINES = {"840d": ("mikron-ucp710-ac-840d", siemens840d_post, "--machine=mikron-ucp710-ac-840d", ".mpf"),
            "linuxcnc": ("linuxcnc-2.9-xyzac-trt", linuxcnc5x_post, "--machine=linuxcnc-2.9-xyzac-trt", ".ngc")}


def main(argv):
    out = output_dir(argv)
    wheel = roughing.impeller()
    volume = roughing.volume_to_remove(wheel.stock_brep, wheel.part_brep)
    channel = volume.solids[0]
    rows, drawn = [], []
    for name in STRATEGIES:
        start = time.perf_counter()
        result = roughing.partition(channel, wheel.part_brep, name)
        paths = roughing.sweep(result, channel, wheel.part_brep, wheel.stock_brep)
        swept = time.perf_counter() - start
        report = roughing.check_clearance(paths, wheel.part_brep)
        row = {"strategy": name, "passes": len(paths.passes), "moves": len(paths.moves["kind"]),
               "cutting_mm": round(paths.cutting_length, 1), "ramp_mm": round(paths.ramp_length, 1),
               "link_mm": round(paths.link_length, 1), "rapid_mm": round(paths.rapid_length, 1),
               "closest_mm": round(report.minimum, 3), "too_close": report.too_close, "sweep_s": round(swept, 2)}
        for key, (machine_name, post, args, suffix) in MACHINES.items():
            machine = feedsim.load_machine(machine_name)
            program = os.path.join(out, "roughing_%s_%s%s" % (name, key, suffix))
            commands = sweep_commands(paths, machine, FEED_MM_MIN)
            post.export([ProgramSource("%s %s" % (name, roughing.STRATEGY_LABELS[name]), commands)], program, args)
            simulated = feedsim.simulate(program, machine)
            shares = feedsim.speed_limit_shares(simulated.summary)
            row["%s_time_s" % key] = round(simulated.summary.total_time, 1)
            row["%s_length_over_feed_s" % key] = round(simulated.summary.naive_time, 1)
            row["%s_held_by" % key] = ", ".join("%s %.0f %%" % (k, 100 * v) for k, v in list(shares.items())[:3])
        rows.append(row)
        drawn.append((name, paths))
        print("%s: %d passes, %.0f mm cutting, closest %.3f mm; 840D %.1f s (%s), LinuxCNC %.1f s (%s)"
              % (name, row["passes"], row["cutting_mm"], row["closest_mm"], row["840d_time_s"], row["840d_held_by"],
                 row["linuxcnc_time_s"], row["linuxcnc_held_by"]))
    with open(os.path.join(out, "roughing_paths.csv"), "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    save_sweeps(drawn, os.path.join(out, "roughing_paths.png"),
                "One impeller channel swept with a Ø8 r1 torus, 70 % radial engagement, 8 mm levels")
    return rows


run_script(main)
