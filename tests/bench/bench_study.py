"""The strategy study's engines measured in one run: the paper's 40-variant grid on the
master bottom feature at 4 m/min, on 1 worker, on 2 worker processes, and on a local Dask cluster of 2 workers
(processes of one thread; the cluster's start-up timed apart from the study on it). No cache: every variant is
computed each time. Prints the wall times, the 2-worker speed-up and Dask's overhead against the process pool.

    freecadcmd tests/bench/bench_study.py            (make bench)
"""
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))

import FreeCAD  # noqa: E402,F401 (before Part and the core)

from hsmplanner import study  # noqa: E402
from hsmplanner.app import master_feature_object  # noqa: E402


def timed(run):
    started = time.perf_counter()
    rows = run()
    failed = [r["name"] + ": " + r["error"] for r in rows if r.get("error")]
    if failed:
        raise RuntimeError("variants failed: %s" % "; ".join(failed))
    return time.perf_counter() - started, rows


def main():
    document = FreeCAD.newDocument("BenchStudy")
    part = master_feature_object.create(document)
    b1, b2 = (part.Shape.getElement(n) for n in (part.Boundary1, part.Boundary2))
    grid = study.paper_grid(4000.0)
    run = lambda **kwargs: study.study(part.Shape, part.BottomFace, b1, b2, grid, **kwargs)  # noqa: E731
    one, rows_one = timed(lambda: run(workers=1))
    two, rows_two = timed(lambda: run(workers=2))
    assert [r["time_s"] for r in rows_one] == [r["time_s"] for r in rows_two], "1 and 2 workers disagree"
    work = lambda rows: sum(r["seconds"] for r in rows)  # noqa: E731 (the variants' own time where they ran)
    print("%d variants: 1 worker %.1f s, 2 workers %.1f s: speed-up %.2fx (%.2f s a variant on one; the variants' "
          "own times sum to %.1f s on one worker, %.1f s on two)" % (len(grid), one, two, one / two, one / len(grid),
                                                                     work(rows_one), work(rows_two)))
    started = time.perf_counter()
    cluster, address = study.local_cluster(2)
    start_up = time.perf_counter() - started
    try:  # twice on the same cluster: the first run pays the workers' imports (the core, FreeCAD's Part)
        dask, rows_dask = timed(lambda: run(scheduler=address))
        warm, rows_warm = timed(lambda: run(scheduler=address))
    finally:
        cluster.close()
    assert [r["time_s"] for r in rows_dask] == [r["time_s"] for r in rows_two], "Dask and the process pool disagree"
    print("Dask local cluster of 2 workers: %.1f s (+%.1f s to start the cluster): %+.1f %% against the process "
          "pool's %.1f s (%+.1f %% with the start-up); again on the warm cluster %.1f s (%+.1f %%)"
          % (dask, start_up, 100 * (dask / two - 1), two, 100 * ((dask + start_up) / two - 1), warm,
             100 * (warm / two - 1)))
    print("the variants' own times on Dask: %.1f s (fresh), %.1f s (warm), against %.1f s in the process pool"
          % (work(rows_dask), work(rows_warm), work(rows_two)))
    FreeCAD.closeDocument(document.Name)


main()
