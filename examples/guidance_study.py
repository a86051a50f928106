"""The guidance-curve paper's study on the master bottom feature: the main job of `make demo`.

    freecadcmd examples/guidance_study.py [OUTPUT_DIR]      (default: out/)

Five finishing strategies of the bottom face with a 4 mm ball, 0.01 mm cusp and tolerance, upward
sweeping: parallel planes along X; guide curves over one area (boundary to boundary); 2 areas (one curve,
K 0.75 from boundary 1); 4 areas (the 4-step method: median, K 0.75 per half); 14 areas (13 curves, K 0.25
from each boundary to the median). Each at F = 2, 4 and 6 m/min, posted for the Siemens 840D
(study_<strategy>_F<feed>.mpf) and simulated on the paper's Mikron UCP 710. Writes study.csv and study.md
(the comparison table), study_<strategy>_map.png and _histograms.png (at 4 m/min), study_times.png and
study.FCStd (the document with the Job, the nets and the operations).
"""
import csv
import os

import FreeCAD

from hsmplanner import evaluation, feedsim
from hsmplanner.app import finishing, finishing_ops, guide_curve_net_object, master_feature_object
from hsmplanner.app.compat import create_job
from hsmplanner.app.posts import siemens840d_post
from hsmplanner.plots.feedrate import save_strategy_times
from hsmplanner.scripting import output_dir, run_script

MACHINE = "mikron-ucp710-840d"
FEEDS_MM_MIN = (2000.0, 4000.0, 6000.0)
NETS = {  # strategy: (net mode, K, areas of the operation)
    "guide_1_area": ("Median only", 0.5, "Between the boundaries"),
    "guide_2_areas": ("Boundary 1 to boundary 2", 0.75, "Elementary areas of the net"),
    "guide_4_areas": ("4-step method", 0.75, "Elementary areas of the net"),
    "guide_14_areas": ("Boundaries to median", 0.25, "Elementary areas of the net"),
}


def build(document):
    part = master_feature_object.create(document)
    links = dict(boundary_1=(part, part.Boundary1), boundary_2=(part, part.Boundary2),
                 bottom_face=(part, part.BottomFace))
    job = create_job([part])
    controller = finishing.ball_end_controller(job, 4.0, FEEDS_MM_MIN[0])
    operations = {}
    plane = finishing_ops.CreateParallelPlaneFinishing("parallel_planes", parentJob=job)
    plane.Face = (part, part.BottomFace)
    operations["parallel_planes"] = plane
    for name, (mode, k, areas) in NETS.items():
        net = guide_curve_net_object.create(document, name="Net_" + name, Mode=mode, K=k, **links)
        op = finishing_ops.CreateGuideCurveFinishing(name, parentJob=job)
        op.Net, op.Areas = net, areas
        operations[name] = op
    for op in operations.values():
        op.ToolController = controller
    return job, controller, operations


def main(argv):
    out = output_dir(argv)
    document = FreeCAD.newDocument("GuidanceStudy")
    job, controller, operations = build(document)
    rows, times = [], {}
    for feed in FEEDS_MM_MIN:
        controller.HorizFeed = FreeCAD.Units.Quantity("%g mm/min" % feed)
        document.recompute()
        for name, op in operations.items():
            if not op.isValid():
                raise RuntimeError("%s failed: %s" % (name, op.State))
            program = os.path.join(out, "study_%s_F%d.mpf" % (name, feed))
            siemens840d_post.export([job, controller, op], program, "--tolerance=0.01")
            result = feedsim.simulate(program, MACHINE, blocks=True)
            figures = evaluation.evaluate(result)
            areas = len(op.Net.Curves) - 1 if hasattr(op, "Net") and op.Areas.startswith("Elementary") else 1
            rows.append(dict(
                strategy=name, areas=areas, feed_mm_min=int(feed), passes=op.Passes,
                path_length_mm=round(figures["path_length_mm"], 1), blocks=figures["blocks"],
                machining_time_s=round(figures["machining_time_s"], 1),
                length_over_feed_s=round(figures["naive_time_s"], 1),
                time_over_estimate=round(figures["time_over_naive"], 2),
                tool_entries=figures["tool_entries"],
                short_sequences_pct=round(100 * figures["short_sequence_share"], 1),
                short_passes_pct=round(100 * evaluation.short_share(op.PassLengths), 1),
                **{"time_at_%s_F_pct" % label: round(100 * share, 1)
                   for label, share in zip(("lt0.3", "0.3-0.5", "0.5-0.7", "0.7-0.9", "ge0.9"),
                                           figures["feed_classes_time"])}))
            times.setdefault(name, []).append(figures["machining_time_s"])
            if feed == 4000.0:
                feedsim.write_report(result, out, "study_%s" % name, "%s at 4 m/min" % name.replace("_", " "))
            print("%-16s F%-5d %4d passes  %8.1f mm  %6d blocks  %6.1f s (length/feed %6.1f s)  entries %4d  "
                  "short passes %4.1f %%" % (name, feed, op.Passes, figures["path_length_mm"], figures["blocks"],
                                             figures["machining_time_s"], figures["naive_time_s"],
                                             figures["tool_entries"], 100 * evaluation.short_share(op.PassLengths)))
    write_tables(out, rows)
    save_strategy_times(times, FEEDS_MM_MIN, os.path.join(out, "study_times.png"),
                        "Finishing the master bottom feature on the Mikron UCP 710 / 840D model")
    document.saveAs(os.path.join(out, "study.FCStd"))
    FreeCAD.closeDocument(document.Name)


def write_tables(out, rows):
    with open(os.path.join(out, "study.csv"), "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(out, "study.md"), "w") as stream:
        stream.write("| " + " | ".join(rows[0]) + " |\n|" + "---|" * len(rows[0]) + "\n")
        for row in rows:
            stream.write("| " + " | ".join(str(v) for v in row.values()) + " |\n")


run_script(main)
