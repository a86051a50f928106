"""Curve nets of the guidance-curve paper's Tables 1 and 2 on the master bottom feature, headless.

    freecadcmd examples/curve_nets.py [OUTPUT_DIR]      (default: out/)

Writes curve_nets.csv (one row per net: building direction, K, P, curves, elementary areas of each
composed area MA_j, time), curve_nets_table1.png and curve_nets_table2.png (plan views of the nets, areas
coloured) and curve_nets_4step.png (the 4-step method with its adapted planes).
"""
import csv
import os
import time

import numpy as np

import hsmplanner
from hsmplanner.app.master_feature import make_master_bottom_feature
from hsmplanner.plots.curve_nets import save_net_grid
from hsmplanner.scripting import output_dir, run_script

TABLE_1 = [("b1_to_b2", 0.25, 5.0), ("b1_to_b2", 0.75, 5.0), ("b2_to_b1", 0.25, 5.0), ("b2_to_b1", 0.75, 5.0)]
TABLE_2 = [(mode, k, step) for mode in ("boundaries_to_median", "median_to_boundaries")
           for k in (0.25, 0.5, 0.75) for step in (5.0, 10.0, 20.0)]


def along_direction(points, direction):
    """Points ordered along the net's direction (boundary edges may run backwards)."""
    return points if np.dot(points[-1] - points[0], direction) >= 0 else points[::-1]


def panel(net, title):
    direction = np.asarray(net.direction)
    curves = [(along_direction(np.asarray(c.sample(150)), direction), c.role.name) for c in net.curves]
    return curves, net.elementary_areas(), title


def main(argv):
    out = output_dir(argv)
    feature = make_master_bottom_feature()
    shape = feature.shape
    b1, b2 = shape.getElement(feature.boundary_1), shape.getElement(feature.boundary_2)
    bottom = shape.getElement(feature.bottom_face)

    rows, table_panels = [], {1: [], 2: []}
    for table, nets in ((1, TABLE_1), (2, TABLE_2)):
        for mode, k, step in nets:
            start = time.perf_counter()
            net = hsmplanner.curve_net(b1, b2, k, step, mode=mode, face=bottom)
            seconds = time.perf_counter() - start
            composed = [len(ma) for ma in net.composed_areas()]
            rows.append({"table": table, "building_direction": mode, "K": k, "P_mm": step,
                         "intermediate_curves": len(net.curves) - 2, "elementary_areas": composed[-1],
                         "composed_areas": " ".join(map(str, composed)), "time_ms": round(1000 * seconds, 1),
                         "warnings": " | ".join(net.warnings)})
            if step == 5.0:
                table_panels[table].append(panel(net, "%s, K %.2f: %d curves, %d areas"
                                                 % (mode.replace("_", " "), k, len(net.curves) - 2, composed[-1])))

    net, report = hsmplanner.guidance_curves(b1, b2, face=bottom)
    rows.append({"table": "4-step", "building_direction": "4-step method", "K": "0.5 / 0.75", "P_mm": "adapted",
                 "intermediate_curves": len(net.curves) - 2, "elementary_areas": len(net.elementary_areas()),
                 "composed_areas": " ".join(str(len(ma)) for ma in net.composed_areas()), "time_ms": "",
                 "warnings": "planes %.2f-%.2f mm apart; half 1 from %s, half 2 from %s"
                             % (report.smallest_step, report.largest_step, report.half1.start, report.half2.start)})

    with open(os.path.join(out, "curve_nets.csv"), "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    save_net_grid(table_panels[1], os.path.join(out, "curve_nets_table1.png"),
                  "Table 1: nets from one boundary to the other (P = 5 mm, minimum gap 2 mm)", columns=2)
    save_net_grid(table_panels[2], os.path.join(out, "curve_nets_table2.png"),
                  "Table 2: nets with the median (P = 5 mm)", columns=3)
    four = panel(net, "4-step method: median, then K 0.75 from the smoother guide of each half")
    save_net_grid([four], os.path.join(out, "curve_nets_4step.png"), "Guidance curves (paper §4.3)", columns=1)
    for row in rows:
        print("%-22s K %-9s P %-7s %2s curves, areas %s" % (row["building_direction"], row["K"], row["P_mm"],
                                                             row["intermediate_curves"], row["composed_areas"]))
    print("curve nets written to %s" % out)


run_script(main)
