"""Writes the roughing programs of examples/roughing_study.py posted for LinuxCNC: each strategy S1-S5 swept and
joined as the study does it (rapids kept out of the stock left), its A and C computed for the oracle's A/C
trunnion (tests/oracle/machine_xyzac.json) and written by our LinuxCNC 5-axis post (hsm_linuxcnc5x, G64 P0.01) for
that machine, so that LinuxCNC and the simulator read the program the post wrote for the machine both run.

By default the first channel of the impeller, into tests/oracle/programs_xyzac/roughing_S*.ngc (the default
set of make test-oracle: 50-70 s of LinuxCNC time each); with the word `all` the study's whole programs (all
seven channels, 6-9 min of LinuxCNC time each) into FOLDER (default build/oracle-roughing).

    scripts/run-freecadcmd.sh tests/oracle/make_roughing_programs.py [S1 S2 ...] [all [FOLDER]]
"""
import os
import sys

from hsmplanner import feedsim, roughing
from hsmplanner.app.posts import linuxcnc5x_post
from hsmplanner.app.roughing.commands import ProgramSource, sweep_commands
from hsmplanner.app.roughing.study import DEFAULT_FEED_MM_MIN
from hsmplanner.scripting import run_script, script_arguments

HERE = os.path.dirname(os.path.abspath(__file__))
MACHINE = os.path.join(HERE, "machine_xyzac.json")
OUT = os.path.join(HERE, "programs_xyzac")
STRATEGIES = ("S1", "S2", "S3", "S4", "S5")
RESOLUTION_MM = 0.2  # the study's, for keeping the rapids out of the stock left


def post(name, wheel, solids, model, folder):
    regions = [roughing.sweep(roughing.partition(solid, wheel.part_brep, name), solid, wheel.part_brep,
                              wheel.stock_brep) for solid in solids]
    moves, _ = roughing.keep_rapids_out_of_stock(roughing.join_paths(regions, wheel.stock_brep), wheel.stock_brep,
                                                 wheel.part_brep, resolution=RESOLUTION_MM)
    path = os.path.join(folder, "roughing_%s%s.ngc" % (name, "_all" if len(solids) > 1 else ""))
    label = "%s %s, impeller, F%g" % (name, roughing.STRATEGY_LABELS[name], DEFAULT_FEED_MM_MIN)
    linuxcnc5x_post.export([ProgramSource(label, sweep_commands(moves, model, DEFAULT_FEED_MM_MIN))], path,
                           "--machine=%s" % MACHINE)
    return path


def main(argv):
    words = script_arguments(argv)
    every = "all" in words  # freecadcmd takes words starting with '-' for itself
    asked = [a for a in words if a in STRATEGIES] or list(STRATEGIES)
    rest = [a for a in words if a not in STRATEGIES and a != "all"]
    folder = os.path.abspath(rest[0]) if every and rest else os.path.normpath(os.path.join(HERE, "..", "..", "build", "oracle-roughing"))
    unknown = rest if not every else rest[1:]
    if unknown:
        sys.exit("error: unknown strategy %s: use %s" % (", ".join(unknown), " ".join(STRATEGIES)))
    model = feedsim.load_machine(MACHINE)
    wheel = roughing.impeller()
    volume = roughing.volume_to_remove(wheel.stock_brep, wheel.part_brep)
    folder = folder if every else OUT
    os.makedirs(folder, exist_ok=True)
    solids = volume.solids if every else volume.solids[:1]
    for name in asked:
        path = post(name, wheel, solids, model, folder)
        summary = feedsim.simulate(path, model).summary
        print("%s: %s, %d blocks, simulated %.1f s" % (name, path, summary.block_count, summary.total_time))


run_script(main)
