"""The five-strategy roughing study of the paper (Table 1), headless, and what the paper could not give: every
strategy of parts 1-2 (S1 planes — on this impeller its plane is the inlet's, so S1 is also the 3-axis Z-level
roughing a shop runs today — S2 coaxial cylinders, S3 setup planes, S4 offsets of the skin, S5 offsets of the
hub) on all channels of the impeller, the paper's Ø8 r1 torus at 70 % radial and 8 mm axial engagement, the
channels joined through the air into one program, simulated by the material-removal model (tri-dexel,
0.2 mm) and, posted for the A/C trunnion 840D, by the feed-rate simulator.

    freecadcmd examples/roughing_study.py [OUTPUT_DIR]      (default: out/)

Writes roughing_study.csv (per strategy the paper's V_r, path, in-material share and stick-out beside ours,
and ours only: V_r without the allowance layer, the simulated time against length/feed, the share of time each
axis held the speed, the stock left on the part: mean, max, standard deviation), roughing_study_stock.png (the
stock each strategy leaves on the part), roughing_study_bars.png (V_r and times), roughing_study_S*_stock.stl and
roughing_study.FCStd (the stock each leaves, as 1 mm blocks, with the part) and roughing_study_S*_840d.mpf.
"""
import csv
import os
import time

from hsmplanner import feedsim, roughing
from hsmplanner.app.posts import siemens840d_post
from hsmplanner.app.roughing_commands import ProgramSource, sweep_commands
from hsmplanner.plots.roughing_study import save_stock_maps, save_study_bars
from hsmplanner.scripting import output_dir, run_script

# Table 1 of the paper: V_r %, path mm, in material %, stick-out mm.
PAPER = {"S1": (43.1, 3332, 44.1, 57), "S2": (14.1, 2987, 54.4, 49), "S3": (16.0, 3863, 45.6, 47),
         "S4": (19.4, 2758, 56.2, 39), "S5": (9.3, 3343, 66.5, 44)}
FEED_MM_MIN = 2000.0
MACHINE = "mikron-ucp710-ac-840d"
RESOLUTION_MM = 0.2
STOCK_BLOCK_RAYS = 5  # the stock left as 1 mm blocks for FreeCAD and STL (0.2 mm ones would weigh 25 times more)
COLUMNS = ["strategy", "paper_vr", "vr", "vr_beyond_allowance", "paper_path_mm", "path_mm", "feed_mm",
           "paper_in_material", "in_material", "paper_stick_out_mm", "stick_out_mm", "gouge_mm3", "time_s",
           "length_over_feed_s", "held_by", "stock_mean_mm", "stock_max_mm", "stock_std_mm", "resolution_mm",
           "seconds"]


def study_strategy(name, wheel, volume, machine, out):
    start = time.perf_counter()
    regions = []
    for solid in volume.solids:
        regions.append(roughing.sweep(roughing.partition(solid, wheel.part_brep, name), solid, wheel.part_brep,
                                      wheel.stock_brep))
    moves = roughing.join_paths(regions, wheel.stock_brep)
    removal = roughing.simulate_removal(moves, wheel.stock_brep, wheel.part_brep, resolution=RESOLUTION_MM,
                                        stock_mesh_stride=STOCK_BLOCK_RAYS)
    roughing.save_stl(removal.stock_mesh, os.path.join(out, "roughing_study_%s_stock.stl" % name),
                      "%s stock left, blocks of %g mm" % (name, STOCK_BLOCK_RAYS * RESOLUTION_MM))
    program = os.path.join(out, "roughing_study_%s_840d.mpf" % name)
    siemens840d_post.export([ProgramSource("%s %s" % (name, roughing.STRATEGY_LABELS[name]),
                                           sweep_commands(moves, machine, FEED_MM_MIN))], program,
                            "--machine=%s" % MACHINE)
    simulated = feedsim.simulate(program, machine)
    shares = feedsim.speed_limit_shares(simulated.summary)
    paper = PAPER[name]
    row = {"strategy": name, "paper_vr": paper[0], "vr": round(removal.remaining_share, 1),
           "vr_beyond_allowance": round(removal.beyond_allowance_share, 1), "paper_path_mm": paper[1],
           "path_mm": round(removal.path_length), "feed_mm": round(removal.feed_length), "paper_in_material": paper[2],
           "in_material": round(removal.in_material_share, 1), "paper_stick_out_mm": paper[3],
           "stick_out_mm": round(removal.stick_out, 1), "gouge_mm3": round(removal.gouge_volume, 2),
           "time_s": round(simulated.summary.total_time, 1), "length_over_feed_s": round(simulated.summary.naive_time, 1),
           "held_by": ", ".join("%s %.0f %%" % (k, 100 * v) for k, v in list(shares.items())[:3]),
           "stock_mean_mm": round(removal.thickness_mean, 2), "stock_max_mm": round(removal.thickness_max, 2),
           "stock_std_mm": round(removal.thickness_std, 2), "resolution_mm": removal.resolution,
           "seconds": round(time.perf_counter() - start, 1)}
    print("%s: V_r %.1f %% (paper %.1f), without the allowance %.1f %%; path %d mm (paper %d), in material %.1f %% "
          "(paper %.1f), stick-out %.1f mm (paper %d); 840D %.1f s (length/feed %.1f s; %s); stock %.2f/%.2f/%.2f mm; "
          "%.1f s" % (name, row["vr"], paper[0], row["vr_beyond_allowance"], row["path_mm"], paper[1],
                      row["in_material"], paper[2], row["stick_out_mm"], paper[3], row["time_s"],
                      row["length_over_feed_s"], row["held_by"], row["stock_mean_mm"], row["stock_max_mm"],
                      row["stock_std_mm"], row["seconds"]))
    return row, (name, removal.surface_points, removal.thickness, removal.weight), removal.stock_mesh


def save_document(wheel, meshes, path):
    """A FreeCAD document with the part and each strategy's stock left as a Mesh feature (all but the last
    hidden): what the study leaves, to look at in FreeCAD."""
    import FreeCAD
    import Mesh
    import Part

    document = FreeCAD.newDocument("RoughingStudy")
    part = document.addObject("Part::Feature", "Impeller")
    shape = Part.Shape()
    shape.importBrepFromString(wheel.part_brep)
    part.Shape = shape
    for name, (points, triangles) in meshes:
        feature = document.addObject("Mesh::Feature", "StockLeft_%s" % name)
        feature.Label = "%s stock left" % name
        feature.Mesh = Mesh.Mesh([[list(map(float, points[i])) for i in triangle] for triangle in triangles])
    document.recompute()
    document.saveAs(path)
    FreeCAD.closeDocument(document.Name)
    return path


def main(argv):
    out = output_dir(argv)
    started = time.perf_counter()
    wheel = roughing.impeller()
    volume = roughing.volume_to_remove(wheel.stock_brep, wheel.part_brep)
    machine = feedsim.load_machine(MACHINE)
    rows, maps, meshes = [], [], []
    for name in ("S1", "S2", "S3", "S4", "S5"):
        row, stock_map, mesh = study_strategy(name, wheel, volume, machine, out)
        rows.append(row)
        maps.append(stock_map)
        meshes.append((name, mesh))
    save_document(wheel, meshes, os.path.join(out, "roughing_study.FCStd"))
    with open(os.path.join(out, "roughing_study.csv"), "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    save_stock_maps(maps, os.path.join(out, "roughing_study_stock.png"),
                    "Stock left on the impeller by each strategy (Ø8 r1 torus, 0.5 mm allowance; tri-dexel at %g mm)"
                    % RESOLUTION_MM)
    save_study_bars(rows, os.path.join(out, "roughing_study_bars.png"),
                    "The five strategies on the impeller: volume left and machining time (840D A/C, F%g)" % FEED_MM_MIN)
    print("whole study: %.1f s" % (time.perf_counter() - started))
    return rows


run_script(main)
