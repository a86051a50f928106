"""The five-strategy roughing study of the paper (Table 1), headless, and what the paper could not give: every
strategy of parts 1-2 (S1 planes — on this impeller its plane is the inlet's, so S1 is also the 3-axis Z-level
roughing a shop runs today — S2 coaxial cylinders, S3 setup planes, S4 offsets of the skin, S5 offsets of the
hub) on all channels of the impeller, the paper's Ø8 r1 torus at 70 % radial and 8 mm axial engagement, the
channels joined through the air into one program, simulated by the material-removal model (tri-dexel,
0.2 mm) and, posted for the A/C trunnion 840D, by the feed-rate simulator. Each strategy three ways: as the
paper (one level per slice), with step-up levels inside the slices where the part leans, and with step-up
followed by a rest roughing of what it left with a Ø4 r0.5 torus (S3 on the stock left, 4 mm step).

    freecadcmd examples/roughing_study.py [OUTPUT_DIR] [channels=N] [strategies=S1,S5] [resolution=MM]

(the defaults: every channel, S1-S5, 0.2 mm). Writes roughing_study.csv (per row the paper's V_r, path,
in-material share and stick-out beside ours, and ours only: V_r without the allowance layer, the simulated
time against length/feed, the rest operation's time, the share of time each axis held the speed, the stock
left on the part: mean, max, standard deviation), roughing_study_stock.png (the stock each leaves on the part),
roughing_study_bars.png (V_r and times), roughing_study_pareto.png (V_r against time: what a shop trades),
roughing_study_S*_stock.stl and roughing_study.FCStd (the stock each step-up + rest row leaves, as 1 mm
blocks, with the part) and roughing_study_S*_840d.mpf (the step-up programs).
"""
import csv
import os
import sys
import time

from hsmplanner import roughing
from hsmplanner.app.roughing.study import COLUMNS, DEFAULT_FEED_MM_MIN, Rest, add_stock_mesh, study_strategy
from hsmplanner.geometry import shape_from_brep
from hsmplanner.plots.roughing_study import save_pareto, save_stock_maps, save_study_bars
from hsmplanner.scripting import output_dir, run_script, script_arguments

RESOLUTION_MM = 0.2
STOCK_BLOCK_RAYS = 5  # the stock left as 1 mm blocks for FreeCAD and STL (0.2 mm ones would weigh 25 times more)


def report(row):
    print("%s %s: V_r %.1f %% (paper %.1f), without the allowance %.1f %%; path %d mm (paper %d), in material %.1f %% "
          "(paper %.1f), stick-out %.1f mm (paper %d); 840D %.1f s (length/feed %.1f s; %s); stock %.2f/%.2f/%.2f mm; "
          "%.1f s" % (row["strategy"], row["variant"], row["vr"], row["paper_vr"], row["vr_beyond_allowance"],
                      row["path_mm"], row["paper_path_mm"], row["in_material"], row["paper_in_material"],
                      row["stick_out_mm"], row["paper_stick_out_mm"], row["time_s"], row["length_over_feed_s"],
                      row["held_by"], row["stock_mean_mm"], row["stock_max_mm"], row["stock_std_mm"], row["seconds"]))
    sys.stdout.flush()


def options(argv):
    """channels, strategies and resolution from the script's key=value arguments."""
    given = dict(a.split("=", 1) for a in script_arguments(argv) if "=" in a)
    unknown = set(given) - {"channels", "strategies", "resolution"}
    if unknown:
        sys.stderr.write("error: unknown option %s: use channels=N, strategies=S1,S5 or resolution=MM\n"
                         % ", ".join(sorted(unknown)))
        raise SystemExit(2)
    return (int(given.get("channels", 0)), given.get("strategies", "S1,S2,S3,S4,S5").split(","),
            float(given.get("resolution", RESOLUTION_MM)))


def save_document(wheel, meshes, path):
    """A FreeCAD document with the part and each strategy's stock left as a Mesh feature: what the study leaves,
    to look at in FreeCAD."""
    import FreeCAD

    document = FreeCAD.newDocument("RoughingStudy")
    part = document.addObject("Part::Feature", "Impeller")
    part.Shape = shape_from_brep(wheel.part_brep)
    for name, mesh in meshes:
        add_stock_mesh(document, "StockLeft_%s" % name, mesh, "%s stock left" % name)
    document.recompute()
    document.saveAs(path)
    FreeCAD.closeDocument(document.Name)
    return path


class Channels:
    """The volume to remove, its first `count` channels only (0: all): a quick run of the same study."""

    def __init__(self, volume, count):
        self.solids = volume.solids[:count] if count > 0 else volume.solids


def main(argv):
    out = output_dir(argv)
    channels, strategies, resolution = options(argv)
    started = time.perf_counter()
    wheel = roughing.impeller()
    volume = Channels(roughing.volume_to_remove(wheel.stock_brep, wheel.part_brep), channels)
    rows, maps, meshes = [], [], []
    for number, name in enumerate(strategies, 1):
        common = dict(resolution=resolution)
        print("%s (%d of %d), %d channel%s: as the paper, with step-up, with step-up and a rest roughing (%.0f s so "
              "far)" % (name, number, len(strategies), len(volume.solids), "" if len(volume.solids) == 1 else "s",
                        time.perf_counter() - started))
        sys.stdout.flush()
        for variant in (dict(step_up=False), dict(program=os.path.join(out, "roughing_study_%s_840d.mpf" % name)),
                        dict(rest=Rest(), stock_mesh_stride=STOCK_BLOCK_RAYS)):
            result = study_strategy(name, wheel.part_brep, wheel.stock_brep, volume, **common, **variant)
            report(result.row)
            rows.append(result.row)
        if result.removal is None:
            continue
        maps.append(result.stock_map)
        meshes.append((name, result.removal.stock_mesh))
        roughing.save_stl(result.removal.stock_mesh, os.path.join(out, "roughing_study_%s_stock.stl" % name),
                          "%s %s: stock left, blocks of %g mm" % (name, result.row["variant"],
                                                                  STOCK_BLOCK_RAYS * resolution))
    save_document(wheel, meshes, os.path.join(out, "roughing_study.FCStd"))
    with open(os.path.join(out, "roughing_study.csv"), "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    save_stock_maps(maps, os.path.join(out, "roughing_study_stock.png"),
                    "Stock left on the impeller by each strategy with step-up and a Ø4 rest roughing (Ø8 r1 torus, "
                    "0.5 mm allowance; tri-dexel at %g mm)" % resolution)
    save_study_bars(rows, os.path.join(out, "roughing_study_bars.png"),
                    "The five strategies on the impeller: volume left and machining time (840D A/C, F%g)" % DEFAULT_FEED_MM_MIN)
    save_pareto(rows, os.path.join(out, "roughing_study_pareto.png"),
                "Stock left beyond the allowance against machining time (840D A/C, F%g): the front a shop chooses on"
                % DEFAULT_FEED_MM_MIN)
    print("whole study: %.1f s" % (time.perf_counter() - started))
    return rows


run_script(main)
