"""Command line of the strategy study, for batch use (`hsm-study --help` where the package is installed,
python3 -m hsmplanner.study_cli --help from a clone).

    hsm-study part.step --face Face4 --b1 Edge12 --b2 Edge20 --planes 0:180:15 \\
        --k 0.25,0.5,0.75 --p 5,10,20 --four-step --feeds 4000 --workers 2 --csv study.csv

Runs with FreeCAD's Python modules (freecadcmd, or /usr/bin/python3 that finds FreeCAD's library): the part is
read with FreeCAD's Part (BREP or STEP), faces and edges by their names. Prints the ranked table; exit status 2
with a message naming the argument for a bad input."""
import argparse
import os
import sys


def _numbers(text, what):
    from hsmplanner.study import parse_range  # (imported by main after FreeCAD, before parse_args calls this)

    try:
        return parse_range(text, what)
    except ValueError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


def parser(prog="python3 -m hsmplanner.study_cli"):
    p = argparse.ArgumentParser(prog=prog, description="Rank finishing strategies of a face "
                                "between two boundaries by simulated machining time and slowdowns.")
    p.add_argument("part", help="the part, a BREP or STEP file")
    p.add_argument("--face", required=True, help="the bottom face, e.g. Face4")
    p.add_argument("--b1", required=True, help="boundary 1, an edge name, e.g. Edge12")
    p.add_argument("--b2", required=True, help="boundary 2, an edge name")
    p.add_argument("--planes", type=lambda t: _numbers(t, "--planes"), default=[], help="plane angles, deg")
    p.add_argument("--k", type=lambda t: _numbers(t, "--k"), default=[], help="K values of the guide nets")
    p.add_argument("--p", type=lambda t: _numbers(t, "--p"), default=[], help="P values (net steps), mm")
    p.add_argument("--median", choices=["with", "without", "both"], default="both", help="guide nets with the median")
    p.add_argument("--net-modes", default=None, help="net modes instead of --median, comma-separated (b1_to_b2, "
                   "median_to_boundaries, boundaries_to_median, b2_to_b1, median)")
    p.add_argument("--four-step", action="store_true", help="add the paper's 4-step method")
    p.add_argument("--feeds", type=lambda t: _numbers(t, "--feeds"), default=[4000.0], help="feeds, mm/min")
    p.add_argument("--machine", action="append", default=None, help="machine model name (repeat for several)")
    p.add_argument("--workers", type=int, default=0, help="worker processes (0: all cores)")
    p.add_argument("--scheduler", default=None, help="a Dask scheduler's address (tcp://host:8786): run there")
    p.add_argument("--scheduler-timeout", type=float, default=20.0,
                   help="seconds to wait for the scheduler and its first worker (default 20)")
    p.add_argument("--cache", default=None, help="folder of cached results (inputs unchanged: not recomputed)")
    p.add_argument("--rank", choices=["time", "slowdown", "pareto"], default="time")
    p.add_argument("--csv", default=None, help="write every row here")
    p.add_argument("--json", default=None, help="write every row here")
    return p


def read_part(path):
    import FreeCAD  # noqa: F401 (first: Part alone crashes outside freecadcmd)
    import Part

    if not os.path.isfile(path):
        raise ValueError("part file %r does not exist" % path)
    shape = Part.Shape()
    try:
        shape.read(path)
    except Exception as error:  # noqa: BLE001 (FreeCAD raises its own types for a file it cannot read)
        raise ValueError("part file %r is not a BREP or STEP file FreeCAD can read (%s): export the part as STEP "
                         "(.step/.stp) or BREP (.brep)" % (path, str(error).strip() or type(error).__name__)) from None
    if shape.isNull() or not shape.Faces:
        raise ValueError("part file %r holds no faces: give a BREP or STEP solid" % path)
    return shape


def element(shape, name, kind):
    try:
        return shape.getElement(name)
    except Exception:
        raise ValueError("%s %r is not an element of the part: name it as FreeCAD does (%s1, %s2, …)"
                         % (kind, name, kind.capitalize(), kind.capitalize())) from None


def console_main(prog):
    """The command line run by /usr/bin/python3 (hsm-study, python3 -m hsmplanner.study_cli): FreeCAD's modules are
    found in Debian's place first."""
    from hsmplanner.geometry import FREECAD_LIB

    if FREECAD_LIB not in sys.path:
        sys.path.append(FREECAD_LIB)
    return main(prog=prog)


def main(argv=None, prog="python3 -m hsmplanner.study"):
    import FreeCAD  # noqa: F401 (before Part and the core, as freecadcmd loads them)

    from hsmplanner import feedsim, study

    args = parser(prog).parse_args(argv)
    try:
        median = {"with": (True,), "without": (False,), "both": (False, True)}[args.median]
        grid = study.variants(planes_deg=args.planes, k=args.k, p=args.p, median=median, four_step=args.four_step,
                              feeds_mm_min=args.feeds, machines=args.machine or [feedsim.DEFAULT_MACHINE],
                              net_modes=args.net_modes.split(",") if args.net_modes else None)
        shape = read_part(args.part)
        element(shape, args.face, "face")
        b1, b2 = element(shape, args.b1, "edge"), element(shape, args.b2, "edge")
    except ValueError as error:
        print("%s: %s" % (prog, error), file=sys.stderr)
        return 2

    def progress(done, row):
        bar = "#" * int(30 * done)
        sys.stderr.write("\r[%-30s] %3.0f %% %s" % (bar, 100 * done, row["name"][:40]))
        sys.stderr.flush()
        return True

    try:
        rows = study.study(shape, args.face, b1, b2, grid, workers=args.workers, cache_dir=args.cache,
                           progress=progress, scheduler=args.scheduler, scheduler_timeout_s=args.scheduler_timeout)
    except (ValueError, ImportError) as error:  # the scheduler (no answer, no workers) or Dask missing
        print("\n%s: %s" % (prog, error), file=sys.stderr)
        return 2
    sys.stderr.write("\n")
    for row in study.rank(rows, args.rank):
        print("%-48s %9.1f s %9.1f s  slowdown %5.1f %%  %5d passes" % (row["name"], row["time_s"],
                                                                       row["length_over_feed_s"],
                                                                       100 * row["slowdown_share"], row["passes"]))
    for row in rows:
        if row.get("error"):
            print("%-48s %s" % (row["name"], row["error"]))
    if args.csv:
        study.write_csv(rows, args.csv)
    if args.json:
        study.write_json(rows, args.json)
    return 0 if any(not r.get("error") for r in rows) else 1


if __name__ == "__main__":  # python3 -m hsmplanner.study_cli …: the command line of hsm-study, from a clone
    sys.exit(console_main("python3 -m hsmplanner.study_cli"))
