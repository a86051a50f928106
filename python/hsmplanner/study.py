"""Automatic strategy study of finishing: a grid of variants — parallel planes at an
angle, guide curves (net mode, K, P, median or not), the 4-step method — at feed set points on machine models,
each generated, simulated on its machine and scored; the rows ranked by simulated time, by the share of time
below half the feed, or as a Pareto front of both.

    rows = study(part, "Face4", b1, b2, variants(planes_deg=range(0, 180, 15), k=(0.25, 0.5, 0.75),
                                               p=(5, 10, 20), feeds_mm_min=(4000,)), workers=2)
    for row in rank(rows, "time")[:5]: print(row["name"], row["time_s"])

Works without FreeCAD (shapes as BREP text or Part shapes). Variants are independent: they run in worker
processes (`workers`, default all cores) and every finished row is kept when another fails or the study is
cancelled (its row says so). Results are cached by their inputs in `cache_dir` (a variant whose inputs did not
change is read back, not recomputed). Bad grids are refused by name before anything runs.
"""
import concurrent.futures
import concurrent.futures.process
import contextlib
import csv
import hashlib
import itertools
import json
import math
import multiprocessing
import os
import signal
import sys
import threading
import time

import numpy as np

from . import _core, curvenet, evaluation, feedsim, toolpaths
from .geometry import as_brep, shape_from_brep

GUIDE_MODES = {False: "b1_to_b2", True: "boundaries_to_median"}  # median or not
MODE_LABELS = {"b1_to_b2": "B1→B2", "b2_to_b1": "B2→B1", "median": "median", "median_to_boundaries": "median→B",
               "boundaries_to_median": "B→median"}
FEED_CLASS_NAMES = ["below_20", "20_40", "40_60", "60_80", "above_80"]  # the paper's five, % of F
MAX_VARIANTS = 10000
WORST_REGIONS = 3  # the slowdown regions kept per row
ROW_VERSION = 2  # part of the cache key: rows cached before the scores changed are computed again
SCHEDULER_TIMEOUT_S = 20
IDLE_S = 0.2  # how often idle() runs while variants run elsewhere


def _check(condition, message):
    if not condition:
        raise ValueError(message)


def _bounded(values, what):
    """The values as a list, refused past MAX_VARIANTS before they are all made (a range of 1e9 angles)."""
    values = list(itertools.islice(iter(values), MAX_VARIANTS + 1))
    _check(len(values) <= MAX_VARIANTS, "more than %d %s: narrow the ranges" % (MAX_VARIANTS, what))
    return values


RANGE_HELP = "numbers separated by commas (0,45,90), or start:stop:step with stop left out as in range() (0:180:15)"


def _number(text, field):
    try:
        value = float(text)
    except ValueError:
        raise ValueError("%s: %r is not a number: give %s" % (field, text.strip(), RANGE_HELP)) from None
    if not math.isfinite(value):
        raise ValueError("%s: %r is not a finite number" % (field, text.strip()))
    return value


def _too_many(field, count):
    return ValueError("%s: %d values (more than %d): narrow the range" % (field, count, MAX_VARIANTS))


def parse_range(text, field):
    """The values of a range as the user typed it: "0,45,90", or "0:180:15" (start:stop:step, stop excluded:
    180° is 0° again for planes). Empty text is no value. ValueError names `field` and what is wrong; more than
    MAX_VARIANTS values are refused before any is made (a typo of 0:180:0.000001 would fill the memory)."""
    _check(text is None or isinstance(text, str), "%s: %r is not text: give %s (lists go to variants())"
           % (field, text, RANGE_HELP))
    text = (text or "").strip()
    if not text:
        return []
    if ":" not in text:
        if text.count(",") >= MAX_VARIANTS:  # counted before splitting: as cheap as the text is long
            raise _too_many(field, text.count(",") + 1)
        return [_number(item, field) for item in text.split(",") if item.strip()]
    parts = text.split(":")
    if len(parts) != 3:
        raise ValueError("%s: %r: write start:stop:step (e.g. 0:180:15), or %s" % (field, text, RANGE_HELP))
    start, stop, step = (_number(part, field) for part in parts)
    if not step > 0:
        raise ValueError("%s: the step of %r must be positive" % (field, text))
    span = (stop - start) / step - 1e-9  # the tolerance keeps 0:0.3:0.1 at 3 values, not 4
    if not math.isfinite(span):  # 0:1:1e-320: more values than a float counts (ceil would overflow)
        raise ValueError("%s: %r gives more than %d values: narrow the range" % (field, text, MAX_VARIANTS))
    count = math.ceil(span)
    if count > MAX_VARIANTS:
        raise _too_many(field, count)
    if count <= 0:
        raise ValueError("%s: %r gives no value: stop must be above start" % (field, text))
    return [round(start + i * step, 9) for i in range(count)]  # rounded: 0.1 × 3 is 0.3, not 0.30000000000000004


def variants(planes_deg=(), k=(), p=(), median=(False, True), four_step=False, feeds_mm_min=(4000.0,),
             machines=(feedsim.DEFAULT_MACHINE,), net_modes=None):
    """The grid as a list of variant dicts: every plane angle, every guide net (K × P × median or not), the
    4-step method if asked, each at every feed on every machine. net_modes (names of curvenet.MODES, e.g.
    ("b1_to_b2", "median_to_boundaries", "boundaries_to_median")) replaces the median choice when given: both
    directions of the paper's median nets. ValueError names a bad range: K outside ]0, 1[, P <= 0, a feed
    <= 0, an unknown machine or net mode, an empty grid, more than 10,000 variants."""
    planes_deg, k, p, median, feeds_mm_min, machines = (
        _bounded(values, what) for values, what in ((planes_deg, "plane angles"), (k, "K values"), (p, "P values"),
                                                    (median, "median choices"), (feeds_mm_min, "feeds"),
                                                    (machines, "machines")))
    modes = [GUIDE_MODES[bool(m)] for m in median] if net_modes is None else _bounded(net_modes, "net modes")
    for mode in modes:
        _check(mode in curvenet.MODES, "net mode %r is unknown: use one of %s" % (mode, ", ".join(curvenet.MODES)))
    for value in planes_deg:
        _check(-360.0 <= float(value) <= 360.0, "plane angle %r° must lie within [-360, 360] (θ and θ + 180° are "
                                                "the same planes)" % (value,))
    for value in k:
        _check(0.0 < float(value) < 1.0, "K = %r is outside ]0, 1[: the guide curve lies between the boundaries "
                                         "(the paper uses 0.25 to 0.75)" % (value,))
    for value in p:
        _check(float(value) > 0.0, "P = %r mm must be positive: the step of the net's planes" % (value,))
    _check(bool(k) == bool(p), "guide curves need both K (%s) and P (%s): give both ranges or neither" % (k, p))
    for value in feeds_mm_min:
        _check(float(value) > 0.0, "feed %r mm/min must be positive" % (value,))
    known = set(feedsim.machine_names())
    for name in machines:
        _check(isinstance(name, str) and name in known,
               "machine %r is unknown: use one of %s" % (name, ", ".join(sorted(known))))
    # counted before any is made: 10,000 K by 10,000 P would be 10^8 variants filling the memory
    count = (len(planes_deg) + len(k) * len(p) * len(modes) + bool(four_step)) * len(feeds_mm_min) * len(machines)
    _check(count <= MAX_VARIANTS, "%d variants (more than %d): narrow the ranges" % (count, MAX_VARIANTS))
    shapes = [dict(strategy="planes", angle_deg=float(a)) for a in planes_deg]
    shapes += [dict(strategy="guide", mode=m, k=float(kk), p=float(pp), median="median" in m)
               for kk in k for pp in p for m in modes]
    if four_step:
        shapes.append(dict(strategy="4-step"))
    grid = [dict(shape, feed_mm_min=float(f), machine=name) for shape in shapes for f in feeds_mm_min for name in machines]
    _check(bool(grid), "the grid is empty: give plane angles, K and P ranges or four_step=True, and feeds and machines")
    for variant in grid:
        variant["name"] = variant_name(variant)
    # a value typed twice (K 0.5,0.5) is one variant, not two rows racing for one cache file
    unique = {}
    for variant in grid:
        unique.setdefault(variant["name"], variant)
    return list(unique.values())


def paper_grid(feed_mm_min=4000.0, machine=feedsim.DEFAULT_MACHINE):
    """The guidance-curve paper's hand study as one grid, 40 variants: parallel planes every 15°, guide nets for
    K in {0.25, 0.5, 0.75} x P in {5, 10, 20} x (B1 to B2, median to the boundaries, boundaries to the median —
    the paper's three constructions), and its 4-step method."""
    return variants(planes_deg=range(0, 180, 15), k=(0.25, 0.5, 0.75), p=(5, 10, 20),
                    net_modes=("b1_to_b2", "median_to_boundaries", "boundaries_to_median"), four_step=True,
                    feeds_mm_min=(feed_mm_min,), machines=(machine,))


def variant_name(v):
    if v["strategy"] == "planes":
        head = "planes %g°" % v["angle_deg"]
    elif v["strategy"] == "guide":
        head = "guide %s K%g P%g" % (MODE_LABELS.get(v["mode"], v["mode"]), v["k"], v["p"])
    else:
        head = "4-step"
    return "%s F%g %s" % (head, v["feed_mm_min"], v["machine"])


def short_name(row):
    """The strategy part of a variant's name, without feed and machine ('planes 30°', 'guide B1→B2 K0.75 P5')."""
    return row["name"].split(" F")[0]


def variant_moves(variant, part_brep, face, b1_brep, b2_brep, finishing=None):
    """The variant's finishing path: (moves, path statistics) — what run_variant scores and a feed map draws."""
    settings, part_brep = dict(finishing or {}), as_brep(part_brep)
    if variant["strategy"] == "planes":
        return toolpaths.parallel_finishing(part_brep, face, variant["angle_deg"], **settings)
    part = shape_from_brep(part_brep)
    b1, b2 = shape_from_brep(as_brep(b1_brep)), shape_from_brep(as_brep(b2_brep))
    bottom = part.getElement(face)
    if variant["strategy"] == "guide":
        net = curvenet.curve_net(b1, b2, variant["k"], step=variant["p"], mode=variant["mode"], face=bottom)
    else:
        net, _ = curvenet.guidance_curves(b1, b2, face=bottom)
    return toolpaths.guide_finishing(part_brep, face, net, **settings)


def simulate_variant(variant, moves):
    """The variant's moves simulated at its feed on its machine, block by block (feedsim's result)."""
    return feedsim.simulate_moves(moves, variant["feed_mm_min"], machine=variant["machine"], blocks=True)


def run_variant(variant, part_brep, face, b1_brep, b2_brep, finishing=None):
    """One variant generated, simulated and scored: its row (the variant's fields, then the scores, and the
    seconds it took where it ran: what a variant costs, and how an engine's time splits into work and
    overhead)."""
    started = time.perf_counter()
    moves, stats = variant_moves(variant, part_brep, face, b1_brep, b2_brep, finishing)
    row = score(variant, stats, simulate_variant(variant, moves))
    row["seconds"] = time.perf_counter() - started
    return row


def score(variant, stats, result):
    """The row of a simulated variant: times, path, blocks, entries, passes, short passes, the share of
    cutting time below half the programmed feed and the time shares of the paper's five feed classes."""
    row = dict(variant)
    scores = evaluation.evaluate(result)
    total = sum(scores["feed_classes_time"]) or 1.0
    blocks = result.blocks
    times = np.asarray(blocks["time"])
    cutting, slow = np.asarray(blocks["motion"]) != 0, _slow_cutting(blocks)
    lengths = np.asarray(stats.get("pass_lengths", []))
    row.update(time_s=scores["machining_time_s"], length_over_feed_s=scores["naive_time_s"],
               path_mm=scores["path_length_mm"], blocks=scores["blocks"], entries=scores["tool_entries"],
               passes=int(stats.get("passes", len(lengths))),
               short_passes=int(np.sum(lengths < evaluation.SHORT_SEQUENCE_MM)),
               # the share of cutting time spent below half the programmed feed (blocks' mean feed)
               slowdown_share=float(times[slow].sum() / times[cutting].sum()) if times[cutting].sum() > 0 else 0.0)
    for name, t in zip(FEED_CLASS_NAMES, scores["feed_classes_time"]):
        row["time_share_" + name] = t / total
    row["worst_slowdowns"] = worst_slowdowns(blocks)
    row["error"] = ""
    return row


def _slow_cutting(blocks):
    """Per block: a cutting block whose mean feed is below half the programmed one (slower than 0.5·F: where the machine loses time)."""
    feed = np.asarray(blocks["programmed_feed"])
    return (np.asarray(blocks["motion"]) != 0) & (np.asarray(blocks["mean_feed"]) < 0.5 * feed)


def worst_slowdowns(blocks, count=WORST_REGIONS):
    """Where the machine loses the most time: runs of consecutive cutting blocks whose mean feed is below half
    the programmed one, the `count` that lose most against length/feed, each as {x_mm, y_mm, z_mm (the run's
    middle, weighted by time), length_mm, time_s, lost_s, held_by (what set the blocks' speed limit longest:
    an axis, or F where the feed itself did and the time went to the ramps between short blocks)}."""
    feed = np.asarray(blocks["programmed_feed"])
    edges = np.flatnonzero(np.diff(np.concatenate(([0], _slow_cutting(blocks).astype(np.int8), [0]))))
    time, length = np.asarray(blocks["time"]), np.asarray(blocks["length"])
    middle = 0.5 * (np.asarray(blocks["start"]) + np.asarray(blocks["end"]))
    regions = []
    for begin, end in zip(edges[::2], edges[1::2]):
        span = slice(begin, end)
        weights = time[span] if time[span].sum() > 0 else np.ones(end - begin)
        x, y, z = np.average(middle[span], axis=0, weights=weights)
        limits = np.bincount(np.asarray(blocks["limit"])[span], weights=time[span], minlength=len(feedsim.SPEED_LIMITS))
        regions.append(dict(x_mm=round(float(x), 2), y_mm=round(float(y), 2), z_mm=round(float(z), 2),
                            length_mm=round(float(length[span].sum()), 2), time_s=round(float(time[span].sum()), 3),
                            lost_s=round(float((time[span] - length[span] / feed[span]).sum()), 3),
                            held_by=feedsim.SPEED_LIMITS[int(np.argmax(limits))]))
    return sorted(regions, key=lambda r: -r["lost_s"])[:count]


def _key(variant, inputs):
    text = json.dumps([ROW_VERSION, variant, [hashlib.sha256(str(x).encode()).hexdigest() for x in inputs]],
                      sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:32]


def _run_cached(variant, inputs, finishing, cache_dir):
    # the thread count changes how fast a variant runs, not its result: not part of the key
    settings = {k: v for k, v in (finishing or {}).items() if k != "threads"}
    path = os.path.join(cache_dir, _key([variant, settings], inputs) + ".json") if cache_dir else None
    if path and os.path.isfile(path):
        with open(path) as stream:
            row = json.load(stream)
        row["cached"] = True
        return row
    try:
        row = run_variant(variant, *inputs, finishing=finishing)
    except Exception as error:  # a failed variant is reported in its row; the others go on
        return dict(variant, error="%s: %s" % (type(error).__name__, error))
    if path:
        os.makedirs(cache_dir, exist_ok=True)
        # written aside and renamed: a worker stopped mid-write or two writing the same variant leave no
        # half file for a later read
        temporary = "%s.%d.tmp" % (path, os.getpid())
        with open(temporary, "w") as stream:
            json.dump(row, stream)
        os.replace(temporary, path)
    row["cached"] = False
    return row


def study(part, face, b1, b2, grid, workers=0, cache_dir=None, finishing=None, progress=None, scheduler=None,
          idle=None, scheduler_timeout_s=SCHEDULER_TIMEOUT_S):
    """Every variant of `grid` (variants()) on the bottom face `face` ('Face4') of `part` between boundaries b1
    and b2 (shapes or BREP text; None for a grid of plane directions only), in worker processes (0: all cores; 1: in this process), or on a Dask
    cluster when `scheduler` is its address ('tcp://host:8786') or a distributed.Client (`workers` is then
    the cluster's). Returns the rows in the grid's order; a failed variant's row has its `error`, a cancelled
    one 'cancelled'. progress(done, row) after each finished variant; returning False cancels the rest.
    idle(), if given, is called about five times a second while variants run elsewhere (workers, a cluster):
    a GUI stays responsive and its Cancel is seen mid-variant; returning False cancels too. A worker process
    that dies (a crash in a variant) fails its variant's row, not the study. A scheduler that does not answer,
    or has no worker, within `scheduler_timeout_s` is a ValueError naming it."""
    _check(bool(grid), "the grid is empty: nothing to study")
    _check(isinstance(scheduler_timeout_s, (int, float)) and 0.1 <= scheduler_timeout_s <= 3600,
           "scheduler timeout %r s must be in [0.1, 3600]" % (scheduler_timeout_s,))
    _check(isinstance(workers, int) and 0 <= workers <= 256, "workers %r must be an integer in [0, 256] (0: all cores)"
           % (workers,))
    needs_boundaries = any(v.get("strategy") != "planes" for v in grid)
    _check(not needs_boundaries or (b1 is not None and b2 is not None),
           "guide-curve and 4-step variants need the boundaries b1 and b2 (edges of the face): give them, or study "
           "plane directions only")
    inputs = _inputs(part, face, b1, b2)
    # one thread per variant: the variants are the parallel work (threads in each worker would only compete)
    finishing = dict({"threads": 1}, **(finishing or {}))
    toolpaths.check_finishing(**finishing)  # a cusp above the ball's radius is said once, not in every row
    rows = [None] * len(grid)
    done = 0

    def finished(index, row):
        nonlocal done
        rows[index] = row
        done += 1
        return progress(done / len(grid), row) if progress else True

    if scheduler is not None:
        _run_on_dask(scheduler, grid, inputs, finishing, cache_dir, finished, idle, scheduler_timeout_s)
    elif (workers or os.cpu_count() or 1) == 1:
        for index, variant in enumerate(grid):
            if finished(index, _run_cached(variant, inputs, finishing, cache_dir)) is False:
                break
    else:
        _run_on_processes(workers or os.cpu_count(), grid, inputs, finishing, cache_dir, finished, idle)
    return [row if row is not None else dict(variant, error="cancelled") for row, variant in zip(rows, grid)]


def _inputs(part, face, b1, b2):
    """What every variant runs on, as it travels to workers: the shapes as BREP text (no boundaries: None). A
    bottom face the part does not have is refused here, naming the faces it has."""
    brep = as_brep(part)
    count = _core.summarize_brep(brep).faces
    number = toolpaths.face_number(face)
    _check(number <= count, "bottom face %r does not exist: the part has %d faces, Face1 to Face%d"
           % (face, count, count))
    return (brep, face, *(None if b is None else as_brep(b) for b in (b1, b2)))


def _collect(futures, ready, finished, idle, failed_row):
    """The rows of `futures` ({future: grid index}) as they end: ready(pending) gives the ended ones (waiting
    at most IDLE_S), idle() runs while none ends. False when the study was cancelled."""
    pending = set(futures)
    while pending:
        ended = ready(pending)
        if not ended and idle is not None and idle() is False:
            return False
        for future in ended:
            pending.discard(future)
            try:
                row = future.result()
            except Exception as error:  # the worker died or the task could not run: its row says so
                row = failed_row(futures[future], error)
            if finished(futures[future], row) is False:
                return False
    return True


def _broken_pipes_raise():
    """Writing to a worker that died must raise BrokenPipeError, as in any Python, not kill the process:
    python3 ignores SIGPIPE at start-up, FreeCAD 1.0's embedded interpreter leaves it at the default, so
    the first write to a stopped worker's pipe ended freecadcmd (exit 141) or FreeCAD with the document."""
    if threading.current_thread() is threading.main_thread() and signal.getsignal(signal.SIGPIPE) == signal.SIG_DFL:
        signal.signal(signal.SIGPIPE, signal.SIG_IGN)


def _run_on_processes(workers, grid, inputs, finishing, cache_dir, finished, idle):
    # fork: the workers inherit the imported core (and inside freecadcmd, sys.executable is not a Python)
    context = multiprocessing.get_context("fork")
    _broken_pipes_raise()
    with _plain_streams_in_workers():
        pool = concurrent.futures.ProcessPoolExecutor(max_workers=workers, mp_context=context)
        try:
            futures = {pool.submit(_run_cached, v, inputs, finishing, cache_dir): i for i, v in enumerate(grid)}
        except BaseException:
            pool.shutdown(wait=False, cancel_futures=True)
            raise
    ready = lambda pending: concurrent.futures.wait(pending, IDLE_S, concurrent.futures.FIRST_COMPLETED)[0]  # noqa: E731
    completed = False
    try:
        completed = _collect(futures, ready, finished, idle, lambda i, error: _failed(grid[i], error))
    finally:
        if not completed:  # cancelled: the running variants are stopped, not left to load the cores
            _stop_workers(list((getattr(pool, "_processes", None) or {}).values()))  # (no public way in 3.13)
        # not waited for when cancelled: the pool's threads could wait for ever on the pipes of the processes
        # just stopped
        pool.shutdown(wait=completed, cancel_futures=not completed)


def _stop_workers(processes, grace_s=2.0):
    """Terminates the pool's worker processes and reaps them before the run returns: a forked FreeCAD takes
    a moment to die, and a caller that closed the study (the panel) would otherwise still see them running.
    A worker that has not ended after grace_s is killed."""
    for process in processes:
        process.terminate()
    for process in processes:
        process.join(grace_s)
        if process.is_alive():
            process.kill()
            process.join(grace_s)


def _failed(variant, error):
    text = "a worker process died: this variant or one running beside it crashed" if isinstance(
        error, concurrent.futures.process.BrokenProcessPool) else "%s: %s" % (type(error).__name__, error)
    return dict(variant, error=text)


_forking = {"active": 0, "hooked": False}


def _in_forked_child():
    if not _forking["active"]:
        return  # a fork of someone else's: left as it is
    sys.stdin = None  # what multiprocessing then skips closing
    sys.stdout = sys.__stdout__ or open(os.devnull, "w")
    sys.stderr = sys.__stderr__ or open(os.devnull, "w")


@contextlib.contextmanager
def _plain_streams_in_workers():
    """Worker processes forked while the block runs start with the process's own standard streams. FreeCAD's
    GUI replaces sys.stdin/stdout/stderr by objects that write to the Report view (Qt): a forked worker first
    closes stdin (multiprocessing), FreeCAD's has no close(), the worker died printing its traceback through
    the Report view, that print never returned in the forked copy (Qt's locks belong to threads the fork did
    not copy), and the pool waited forever: FreeCAD froze (found by the Strategy study panel's GUI test)."""
    if not _forking["hooked"]:  # a fork hook cannot be removed: registered once, acting only inside the block
        os.register_at_fork(after_in_child=_in_forked_child)
        _forking["hooked"] = True
    _forking["active"] += 1
    try:
        yield
    finally:
        _forking["active"] -= 1


def _run_on_dask(scheduler, grid, inputs, finishing, cache_dir, finished, idle, timeout_s=SCHEDULER_TIMEOUT_S):
    """The variants as tasks of a Dask cluster: the BREP texts are scattered once to every worker, each task
    is one variant (run_variant in the worker, which imports hsmplanner: start the workers with the
    repository's python/ folder on PYTHONPATH). Finished rows come back as they end; a cancel drops the rest."""
    try:
        import distributed
    except ImportError as error:
        raise ImportError("a Dask scheduler was given but Dask distributed is missing: apt-get install "
                          "python3-distributed (%s)" % error) from None
    client = scheduler if isinstance(scheduler, distributed.Client) else _connect(distributed, scheduler, timeout_s)
    try:
        shared = client.scatter(list(inputs), broadcast=True, hash=False)
        futures = {client.submit(_run_cached, v, shared, finishing, cache_dir, pure=False): i
                   for i, v in enumerate(grid)}
        arrived = distributed.as_completed(list(futures))

        def ready(pending):
            if not arrived.has_ready():
                time.sleep(IDLE_S)
            return arrived.next_batch(block=False) if arrived.has_ready() else []

        if not _collect(futures, ready, finished, idle, lambda i, error: _failed(grid[i], error)):
            client.cancel(list(futures))
    finally:
        if client is not scheduler:
            client.close()


def _connect(distributed, address, timeout_s=SCHEDULER_TIMEOUT_S):
    _check(isinstance(address, str) and "://" in address,
           "scheduler %r must be a Dask scheduler's address such as 'tcp://host:8786' (or a distributed.Client)"
           % (address,))
    try:
        client = distributed.Client(address, timeout=timeout_s)
    except (OSError, TimeoutError) as error:
        raise ValueError("the Dask scheduler at %r did not answer within %d s (%s): start it (dask-scheduler) and "
                         "its workers (dask-worker %s, with HSM Planner's python/ on PYTHONPATH), or check the address"
                         % (address, timeout_s, error, address)) from None
    try:
        client.wait_for_workers(1, timeout=timeout_s)
    except (OSError, TimeoutError) as error:
        client.close()
        raise ValueError("the Dask scheduler at %r has no workers after %d s (%s): start some (dask-worker %s, with "
                         "HSM Planner's python/ on PYTHONPATH)" % (address, timeout_s, error or "none joined",
                                                                  address)) from None
    return client


def local_cluster(workers=2):
    """A Dask cluster of `workers` processes of one thread on this machine (to measure the engine's overhead
    against the process pool, or to try a study before a real cluster): (cluster, its scheduler address).
    Close the cluster after use (cluster.close())."""
    _check(isinstance(workers, int) and 1 <= workers <= 256, "workers %r must be an integer in [1, 256]" % (workers,))
    import dask
    import distributed

    _broken_pipes_raise()
    # the workers start as fresh Python processes: inside freecadcmd, sys.executable is FreeCAD, not a Python
    multiprocessing.set_executable(_python_executable())
    # no statistical profiler in the workers: sampling every thread's stack each 10 ms cost the variants 10 %
    with dask.config.set({"distributed.worker.daemon": False, "distributed.worker.profile.enabled": False}):
        cluster = distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                           dashboard_address=None)
    return cluster, cluster.scheduler_address


def _python_executable():
    name = os.path.basename(sys.executable or "")
    return sys.executable if name.startswith("python") else "/usr/bin/python%d" % sys.version_info[0]


def refine_k(part, face, b1, b2, median=True, p=10.0, feed_mm_min=4000.0, machine=feedsim.DEFAULT_MACHINE,
             by="time", low=0.1, high=0.9, tolerance=0.05, max_evaluations=12, finishing=None, cache_dir=None,
             progress=None, net_mode=None, start=None):
    """The paper's step 4 done by the machine: a golden-section search of K in [low, high] (inside ]0, 1[) for
    the guide net (with the median or not, or of `net_mode` when given; step P) that minimises the simulated time ('time') or the slowdown
    share ('slowdown'), until the bracket is narrower than `tolerance` or `max_evaluations` variants ran.
    Returns (the best row, every row evaluated in order). Time is not unimodal in K in general: the search
    finds a local best within the bracket, which is what "increase or decrease K slightly" asks. `start`
    (a K already tried, e.g. the grid's best) is evaluated first: the best returned is never worse than it."""
    _check(0.0 < low < high < 1.0, "K bounds [%r, %r] must lie inside ]0, 1[ with low < high" % (low, high))
    _check(start is None or 0.0 < start < 1.0, "start K %r must lie inside ]0, 1[" % (start,))
    _check(tolerance > 0.0, "K tolerance %r must be positive (e.g. 0.05)" % (tolerance,))
    _check(isinstance(max_evaluations, int) and 3 <= max_evaluations <= 100,
           "max evaluations %r must be an integer in [3, 100]" % (max_evaluations,))
    key = {"time": "time_s", "slowdown": "slowdown_share"}.get(by)
    _check(key is not None, "refine K by %r: use 'time' or 'slowdown'" % (by,))
    inputs = _inputs(part, face, b1, b2)
    evaluated, cache = [], {}

    def evaluate_k(k):
        k = round(k, 6)
        if k not in cache:
            variant = variants(k=(k,), p=(p,), median=(median,), feeds_mm_min=(feed_mm_min,), machines=(machine,),
                               net_modes=None if net_mode is None else (net_mode,))[0]
            row = _run_cached(variant, inputs, finishing, cache_dir)
            evaluated.append(row)
            cache[k] = row[key] if not row.get("error") else float("inf")
            if progress and progress(len(evaluated) / max_evaluations, row) is False:
                raise StopIteration
        return cache[k]

    ratio = (5 ** 0.5 - 1) / 2
    a, b = low, high
    c, d = b - ratio * (b - a), a + ratio * (b - a)
    try:
        if start is not None:
            evaluate_k(start)
        fc, fd = evaluate_k(c), evaluate_k(d)
        while b - a > tolerance and len(evaluated) < max_evaluations:
            if fc <= fd:
                b, d, fd = d, c, fc
                c = b - ratio * (b - a)
                fc = evaluate_k(c)
            else:
                a, c, fc = c, d, fd
                d = a + ratio * (b - a)
                fd = evaluate_k(d)
    except StopIteration:
        pass
    ran = [r for r in evaluated if not r.get("error")]
    _check(bool(ran), "no K could be evaluated: %s" % "; ".join(r.get("error", "") for r in evaluated))
    return min(ran, key=lambda r: r[key]), evaluated


def rank(rows, by="time"):
    """The rows that ran, best first: by simulated time ('time'), by the share of time below half the feed
    ('slowdown'), or the Pareto front of both ('pareto': the rows no other beats on both, by time)."""
    ran = [r for r in rows if not r.get("error")]
    if by == "time":
        return sorted(ran, key=lambda r: r["time_s"])
    if by == "slowdown":
        return sorted(ran, key=lambda r: (r["slowdown_share"], r["time_s"]))
    if by == "pareto":
        return pareto_front(ran)
    raise ValueError("rank by %r: use 'time', 'slowdown' or 'pareto'" % (by,))


def pareto_front(rows, objectives=("time_s", "slowdown_share")):
    """The rows that ran (no error, every objective a number) and that no other beats on both objectives (lower
    is better: time and slowdown share, or a roughing's time and the stock it leaves), fastest first."""
    ran = [r for r in rows if not r.get("error") and all(isinstance(r.get(k), (int, float)) for k in objectives)]
    return sorted((r for r in ran if not any(_dominates(o, r, objectives) for o in ran)), key=lambda r: r[objectives[0]])


def _dominates(a, b, objectives):
    no_worse = all(a[k] <= b[k] for k in objectives)
    return no_worse and any(a[k] < b[k] for k in objectives)


def write_csv(rows, path):
    columns = []
    for row in rows:
        columns += [k for k in row if k not in columns]
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=columns)
        writer.writeheader()
        # lists (the worst slowdown regions) as JSON text in their cell
        writer.writerows({k: json.dumps(v) if isinstance(v, (list, dict)) else v for k, v in row.items()}
                         for row in rows)
    return path


def write_json(rows, path):
    with open(path, "w") as stream:
        json.dump(rows, stream, indent=1)
    return path


__all__ = ["parse_range", "variants", "paper_grid", "variant_name", "short_name", "variant_moves", "simulate_variant", "run_variant", "score", "worst_slowdowns", "local_cluster", "study", "refine_k", "rank", "pareto_front", "write_csv", "write_json", "_core"]
