"""5-axis roughing part 1 on the roughing paper's test part, headless: the volume to remove of a 7-blade radial
compressor impeller, its faces classed, and one channel cut by the paper's five strategies.

    freecadcmd examples/roughing_partition.py [OUTPUT_DIR]      (default: out/)

Writes roughing_impeller.FCStd (the impeller, its blank and the volume to remove as Part features),
roughing_channel_classes.png (one channel, faces coloured by class), roughing_partitions.png (the channel's
sub-volumes by S1–S5 at the paper's 8 mm step), roughing_slice_volumes.png (each slice's volume: how even
the layers are), roughing_partitions.csv (per strategy and step: sub-volumes, their volumes, the time) and
roughing_volume.brep (the volume to remove).
"""
import csv
import os
import time

import FreeCAD
import Part

from hsmplanner import roughing
from hsmplanner.plots.roughing import save_face_classes, save_partitions, save_slice_volumes
from hsmplanner.scripting import output_dir, run_script

STEPS_MM = (8.0, 4.0)  # 100 % and 50 % of the paper's Ø8 r1 torus


def shape_of(brep):
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    return shape


def mesh_of(shape, tolerance=0.3):
    points, triangles = shape.tessellate(tolerance)
    return [(p.x, p.y, p.z) for p in points], list(triangles)


def main(argv):
    out = output_dir(argv)
    start = time.perf_counter()
    wheel = roughing.impeller()
    built = time.perf_counter() - start
    start = time.perf_counter()
    volume = roughing.volume_to_remove(wheel.stock_brep, wheel.part_brep)
    cut = time.perf_counter() - start
    print("impeller built in %.1f s; stock − part in %.1f s: %d channels, %.0f mm³ to remove of a %.0f mm³ blank"
          % (built, cut, len(volume.solids), volume.volume, volume.stock_volume))

    document = FreeCAD.newDocument("RoughingImpeller")
    for name, brep in (("Impeller", wheel.part_brep), ("Blank", wheel.stock_brep), ("VolumeToRemove", volume.brep)):
        document.addObject("Part::Feature", name).Shape = shape_of(brep)
    document.recompute()
    document.saveAs(os.path.join(out, "roughing_impeller.FCStd"))
    with open(os.path.join(out, "roughing_volume.brep"), "w") as stream:
        stream.write(volume.brep)

    channel = volume.solids[0]
    faces = shape_of(channel.brep).Faces
    classes = [c.name for c in channel.face_classes]
    save_face_classes([mesh_of(f) for f in faces], classes, os.path.join(out, "roughing_channel_classes.png"),
                      "One channel of the impeller's volume to remove (%.0f mm³): %d faces on %d surfaces"
                      % (channel.volume, len(faces), channel.group_count))

    rows, pictures, slice_volumes = [], {}, []
    for step in STEPS_MM:
        for name in ("S1", "S2", "S3", "S4", "S5"):
            start = time.perf_counter()
            result = roughing.partition(channel, wheel.part_brep, name, step=step)
            seconds = time.perf_counter() - start
            volumes = [s.volume for s in result.sub_volumes]
            mean = sum(volumes) / len(volumes)
            spread = (sum((v - mean) ** 2 for v in volumes) / len(volumes)) ** 0.5 / mean
            rows.append(dict(strategy=roughing.STRATEGY_LABELS[name], step_mm=step, sub_volumes=len(volumes),
                             volume_mm3=round(result.volume, 1), smallest_mm3=round(min(volumes), 1),
                             largest_mm3=round(max(volumes), 1), spread=round(spread, 3), seconds=round(seconds, 2),
                             setup_direction=" ".join("%.3f" % x for x in result.setup_direction) if name == "S3" else ""))
            print("  %-52s step %g mm: %2d sub-volumes, %7.1f to %7.1f mm³, %.2f s"
                  % (roughing.STRATEGY_LABELS[name], step, len(volumes), min(volumes), max(volumes), seconds))
            if step == STEPS_MM[0]:
                pictures[name] = [(s.slice, mesh_of(shape_of(s.brep), 0.5)) for s in result.sub_volumes]
                slice_volumes.append((roughing.STRATEGY_LABELS[name], volumes))
    with open(os.path.join(out, "roughing_partitions.csv"), "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    save_partitions(pictures, os.path.join(out, "roughing_partitions.png"),
                    "One channel of the impeller cut by the five strategies, step %g mm" % STEPS_MM[0])
    save_slice_volumes(slice_volumes, os.path.join(out, "roughing_slice_volumes.png"),
                       "Volume of each slice, step %g mm (one channel, %.0f mm³)" % (STEPS_MM[0], channel.volume))
    FreeCAD.closeDocument(document.Name)


run_script(main)
