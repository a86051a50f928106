"""Feed-rate simulation of a raster path on the master bottom feature, on the three machine models.

    freecadcmd examples/feedrate_study.py [OUTPUT_DIR]      (default: out/)

Builds a Path Job whose operation follows the bottom face in 0.5 mm steps (the short-block character of a
finishing program), posts it with FreeCAD's LinuxCNC post, simulates the posted file with hsm-feedsim and
from Python on each machine preset, and writes: feedrate_probe.ngc, feedrate_<machine>.json/_blocks.csv/
_histograms.png/_map.png, and feedrate_comparison.csv/.md (simulated time against length/feed).
"""
import csv
import json
import os
import subprocess

import FreeCAD

from hsmplanner import feedsim
from hsmplanner.app import feedrate, master_feature_object, probe_paths
from hsmplanner.app.compat import post_module
from hsmplanner.scripting import build_program, output_dir, run_script

FEED_MM_MIN = 4000.0
REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
# the clone's build, or the command on the PATH (the Debian package's, with this example in /usr/share/doc)
FEEDSIM = build_program(REPO, "hsm-feedsim")


def main(argv):
    out = output_dir(argv)
    document = FreeCAD.newDocument("FeedRateStudy")
    part = master_feature_object.create(document)
    job, op = probe_paths.make_probe_job(part, FEED_MM_MIN)
    program = os.path.join(out, "feedrate_probe.ngc")
    post_module("linuxcnc").export([job] + job.Operations.Group, program, "--no-show-editor")

    rows = []
    for machine in feedsim.machine_names():
        result = feedrate.simulate_object(job, machine, blocks=True)
        feedsim.write_report(result, out, "feedrate_%s" % machine, "probe raster at %g mm/min" % FEED_MM_MIN)
        cli_json = os.path.join(out, "feedrate_%s_cli.json" % machine)
        subprocess.run([FEEDSIM, program, "--machine", machine, "--json", cli_json, "--quiet"], check=True)
        with open(cli_json) as stream:
            posted = json.load(stream)
        s = result.summary
        rows.append({"machine": machine, "blocks": s.block_count, "cutting_length_mm": round(s.cutting_length, 1),
                     "length_over_feed_s": round(s.naive_time, 1), "simulated_s": round(s.total_time, 1),
                     "simulated_over_estimate": round(s.total_time / s.naive_time, 2),
                     "posted_file_simulated_s": round(posted["total_time_s"], 1),
                     "cutting_time_at_0.9F_or_more_pct": round(100 * s.feed_classes_time[4], 1)})
    with open(os.path.join(out, "feedrate_comparison.csv"), "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(out, "feedrate_comparison.md"), "w") as stream:
        stream.write("| " + " | ".join(rows[0]) + " |\n|" + "---|" * len(rows[0]) + "\n")
        for row in rows:
            stream.write("| " + " | ".join(str(v) for v in row.values()) + " |\n")
    FreeCAD.closeDocument(document.Name)
    for row in rows:
        print("%-20s %6d blocks  length/feed %7.1f s  simulated %7.1f s (x%.2f)" % (
            row["machine"], row["blocks"], row["length_over_feed_s"], row["simulated_s"],
            row["simulated_over_estimate"]))


run_script(main)
