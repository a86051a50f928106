"""Time of one live-preview update of the Guide curve net panel, from FreeCAD shapes to curves, measured in
one run beside the core alone: `freecadcmd tests/bench/bench_preview.py`.
"""
import sys
import time

import hsmplanner
from hsmplanner.app.guide_curve_net import NetParameters, build_guide_curve_net
from hsmplanner.app.master_feature import make_master_bottom_feature


def best_of(function, repeats=15):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times) * 1000, sorted(times)[len(times) // 2] * 1000


feature = make_master_bottom_feature()
b1, b2 = feature.shape.getElement(feature.boundary_1), feature.shape.getElement(feature.boundary_2)
face = feature.shape.getElement(feature.bottom_face)
net13 = NetParameters(mode="Boundaries to median", k=0.25, step=5.0)
cases = [
    ("core: curve_net, 13 curves, P 5 mm, on the face",
     lambda: hsmplanner.curve_net(b1, b2, 0.25, 5.0, mode="boundaries_to_median", face=face)),
    ("preview: shapes -> 13 curves as Part edges", lambda: build_guide_curve_net(b1, b2, face, net13, False)),
    ("preview: 4-step method", lambda: build_guide_curve_net(b1, b2, face, NetParameters(), False)),
    ("OK: 4-step method with the face split into areas", lambda: build_guide_curve_net(b1, b2, face, NetParameters())),
]
print("%-52s %9s %9s" % ("case", "best ms", "median ms"))
for name, function in cases:
    print("%-52s %9.1f %9.1f" % ((name,) + best_of(function, 5 if "split" in name else 15)))
sys.stdout.flush()  # freecadcmd 1.0 drops unflushed output on SystemExit
raise SystemExit(0)
