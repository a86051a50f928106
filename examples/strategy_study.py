"""The guidance-curve paper's hand study done by the machine: on the master bottom feature at
4 m/min on the paper's Mikron UCP 710 / 840D, 40 finishing variants — parallel planes every 15°, guide nets for
K in {0.25, 0.5, 0.75} x P in {5, 10, 20} x {B1 to B2, median to the boundaries, boundaries to the median}, and
the paper's 4-step method — each generated, simulated and scored, ranked by simulated time, with the Pareto
front of time against slowdowns; then the paper's step 4 (K increased or decreased to see if it improves) as a
golden-section search of K for the best net.

    freecadcmd examples/strategy_study.py [OUTPUT_DIR]      (default: out/)

Writes strategy_study.csv and .json (every row), strategy_study_ranked.txt (the ranked table, the Pareto front
and the K refinement), strategy_study.png (time against slowdown share with the Pareto front; the feed classes
of the fastest variants) and strategy_study_maps.png (the feed-rate maps of the fastest, the least slowed and
the 4-step variants side by side).
"""
import os
import time

from hsmplanner import study
from hsmplanner.plots.strategy_study import save_feed_maps, save_study_plot
from hsmplanner.scripting import output_dir, run_script

FEED_MM_MIN = 4000.0


def master_feature():
    """The master part and its bottom face's boundaries: (part shape, face name, b1, b2)."""
    import FreeCAD

    from hsmplanner.app import master_feature_object

    document = FreeCAD.newDocument("StrategyStudy")
    part = master_feature_object.create(document)
    b1, b2 = (part.Shape.getElement(n) for n in (part.Boundary1, part.Boundary2))
    return part.Shape, part.BottomFace, b1, b2


def table(rows):
    lines = ["%-4s %-44s %8s %8s %9s %6s %7s %6s %8s" % ("rank", "variant", "time s", "L/F s", "slowdown", "passes",
                                                         "entries", "short", "path m")]
    for number, row in enumerate(rows, 1):
        lines.append("%-4d %-44s %8.1f %8.1f %8.1f%% %6d %7d %6d %8.2f" % (
            number, study.short_name(row), row["time_s"], row["length_over_feed_s"], 100 * row["slowdown_share"],
            row["passes"], row["entries"], row["short_passes"], row["path_mm"] / 1000.0))
    return lines


def progress_bar(done, row):
    print("  [%-30s] %3.0f %% %s%s" % ("#" * int(30 * done), 100 * done, row["name"],
                                       " — " + row["error"] if row.get("error") else ""), flush=True)
    return True


def main(argv):
    out = output_dir(argv)
    part, face, b1, b2 = master_feature()
    grid = study.paper_grid(FEED_MM_MIN)
    print("%d variants on the master bottom feature at F%g on %s" % (len(grid), FEED_MM_MIN, grid[0]["machine"]))
    started = time.perf_counter()
    rows = study.study(part, face, b1, b2, grid, workers=0, progress=progress_bar)
    wall = time.perf_counter() - started
    failed = [r for r in rows if r.get("error")]
    ranked, front = study.rank(rows, "time"), study.rank(rows, "pareto")
    report = ["%d variants in %.1f s on %d workers (%d failed)" % (len(rows), wall, os.cpu_count(), len(failed)), ""]
    report += ["Ranked by simulated time:"] + table(ranked) + [""]
    report += ["Pareto front (no other variant is both faster and less slowed):"] + table(front) + [""]
    report += ["Failed: %s: %s" % (r["name"], r["error"]) for r in failed]
    report += ["Where the Pareto front's variants lose most time (runs of blocks below F/2; lost against length/feed):"]
    for row in front:
        report += ["  %s: %s" % (study.short_name(row), "; ".join(
            "%.2f s at X%.0f Y%.0f over %.0f mm (%s)" % (w["lost_s"], w["x_mm"], w["y_mm"], w["length_mm"], w["held_by"])
            for w in row["worst_slowdowns"]))]
    report += [""]

    best_guide = next(r for r in ranked if r["strategy"] == "guide")
    started = time.perf_counter()
    # the paper's "increase or decrease K slightly": a bracket of ±0.15 about the grid's best K
    low, high = max(0.05, best_guide["k"] - 0.15), min(0.95, best_guide["k"] + 0.15)
    best, tried = study.refine_k(part, face, b1, b2, p=best_guide["p"], feed_mm_min=FEED_MM_MIN, by="time",
                                 low=low, high=high, tolerance=0.02, max_evaluations=10, net_mode=best_guide["mode"],
                                 start=best_guide["k"])
    report += ["K refinement of the fastest guide net (%s, P%g) by golden section on [%.2f, %.2f], tolerance 0.02, "
               "%.1f s:" % (best_guide["mode"], best_guide["p"], low, high, time.perf_counter() - started)]
    report += ["  K = %.4f: %.1f s, slowdown %.1f %%" % (r["k"], r["time_s"], 100 * r["slowdown_share"])
               for r in tried if not r.get("error")]
    report += ["  best K = %.4f: %.1f s (the grid's K = %g: %.1f s)" % (best["k"], best["time_s"], best_guide["k"],
                                                                       best_guide["time_s"])]
    with open(os.path.join(out, "strategy_study_ranked.txt"), "w") as stream:
        stream.write("\n".join(report) + "\n")
    print("\n".join(report))
    study.write_csv(rows, os.path.join(out, "strategy_study.csv"))
    study.write_json(rows, os.path.join(out, "strategy_study.json"))
    save_study_plot(rows, os.path.join(out, "strategy_study.png"),
                    "Strategy study of the master bottom feature: %d variants at F%g mm/min (Mikron UCP 710 / 840D)"
                    % (len(rows), FEED_MM_MIN))
    least_slowed = study.rank(rows, "slowdown")[0]
    four_step = next(r for r in rows if r["strategy"] == "4-step")
    shown = list({r["name"]: r for r in (ranked[0], least_slowed, four_step, ranked[-1])}.values())
    save_feed_maps([(r, study.simulate_variant(r, study.variant_moves(r, part, face, b1, b2)[0]).blocks)
                    for r in shown], os.path.join(out, "strategy_study_maps.png"),
                   "Feed-rate maps: the fastest, the least slowed, the paper's 4-step method and the slowest variant")
    return rows


run_script(main)
