"""The partition's bounded work measured in one run: for each case (the impeller's largest channel, a ball held
in a box) the partition's time, how long a cancel takes to be heard (asked while the splitter or the slices'
checks are under way), and the core's refusal of a step 20 times finer, with its estimate, before any split.

    freecadcmd tests/bench/bench_partition.py        (make bench)
"""
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))

import FreeCAD  # noqa: E402,F401 (before Part and the core)
import Part  # noqa: E402

from hsmplanner import roughing  # noqa: E402

CASES = [  # (name, strategy, step mm, cancel after s)
    ("impeller channel", "S1", 0.5, 3.0),
    ("impeller channel", "S2", 0.2, 6.0),
    ("impeller channel", "S4", 0.5, 5.0),
    ("impeller channel", "S5", 0.5, 5.0),
    ("ball in a box", "S5", 1.0, 2.0),
]


def volumes():
    wheel = roughing.impeller()
    ball = Part.makeSphere(20.0)
    return {"impeller channel": (roughing.volume_to_remove(wheel.stock_brep, wheel.part_brep).solids[0], wheel.part_brep),
            "ball in a box": (roughing.volume_to_remove(Part.makeBox(100, 100, 100, FreeCAD.Vector(-50, -50, -50)),
                                                        ball).solids[0], ball)}


def refusal(solid, part, strategy, step):
    """What the core says of a step 20 times finer, before any split (its estimate in seconds)."""
    try:
        roughing.partition(solid, part, strategy, step=step)
    except ValueError as error:
        return str(error)
    return "not refused"


def cancel_latency(solid, part, strategy, step, after):
    asked = []

    def progress(done):
        if time.perf_counter() - started < after:
            return True
        asked.append(time.perf_counter())
        return False

    started = time.perf_counter()
    try:
        roughing.partition(solid, part, strategy, step=step, progress=progress)
    except Exception as error:  # noqa: BLE001 (Cancelled is what is measured)
        if type(error).__name__ != "Cancelled":
            raise
        return time.perf_counter() - asked[0]
    return None  # finished before the cancel


def main():
    shapes = volumes()
    print("%-18s %-3s %6s %9s %10s %12s" % ("case", "", "step", "time s", "slices", "cancel s"))
    for name, strategy, step, after in CASES:
        solid, part = shapes[name]
        started = time.perf_counter()
        result = roughing.partition(solid, part, strategy, step=step)
        elapsed = time.perf_counter() - started
        latency = cancel_latency(solid, part, strategy, step, min(after, 0.5 * elapsed))
        print("%-18s %-3s %6.2f %9.1f %10d %12s" % (name, strategy, step, elapsed, len(result.sub_volumes),
                                                  "-" if latency is None else "%.2f" % latency))
        print("  refused at step %.3f: %s" % (step / 20.0, refusal(solid, part, strategy, step / 20.0)))


main()
