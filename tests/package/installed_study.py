"""`make test-package`, in the clean root of its Debian, as a user, no clone in sight: HSM Planner from the package.

    freecadcmd installed_study.py OUTPUT_DIR VERSION

Checks that `import hsmplanner` is the package's copy, of the version packaged, and that CAM lists the package's
posts; plans the master feature's guide-curve study as a Job (the 4-step net, guide-curve finishing), simulates
it on the Mikron UCP 710 / 840D preset, posts it through CAM's own post-processor lookup with hsm_siemens840d,
saves the document and opens it again in a fresh freecadcmd (its proxies restored from FreeCAD's Mod folder).
Prints one line per check; exit status 1 if one failed.
"""
import os
import subprocess
import sys

import FreeCAD

FAILURES = []


def check(name, condition, detail=""):
    print("%-4s %s %s" % ("ok" if condition else "FAIL", name, detail if not condition else ""))
    sys.stdout.flush()
    if not condition:
        FAILURES.append(name)


def arguments():
    args = sys.argv[next(i for i, a in enumerate(sys.argv) if a.endswith(".py")) + 1:]
    if len(args) != 2:
        raise SystemExit("usage: freecadcmd installed_study.py OUTPUT_DIR VERSION")
    os.makedirs(args[0], exist_ok=True)
    return os.path.abspath(args[0]), args[1]


def check_installation(version):
    import hsmplanner
    import Path.Preferences
    from hsmplanner import feedsim, resources

    mod_dir = os.path.join(os.path.realpath(FreeCAD.getResourceDir() + "Mod"), "HSMPlanner")
    check("hsmplanner imported from FreeCAD's Mod folder", hsmplanner.__file__.startswith(mod_dir + os.sep),
          hsmplanner.__file__)
    check("the core found through the package's link", os.path.realpath(hsmplanner._core.__file__).startswith(
        "/usr/lib/freecad-hsmplanner/"), hsmplanner._core.__file__)
    metadata = FreeCAD.Metadata(os.path.join(mod_dir, "package.xml"))
    upstream = version.split("+")[0]  # the package's version names its Debian release: 0.9.0+forky
    check("one version: package, package.xml, hsmplanner.__version__",
          upstream == metadata.Version == hsmplanner.__version__,
          "%s, %s, %s" % (version, metadata.Version, hsmplanner.__version__))
    check("FreeCAD loaded the workbench folder", mod_dir in [os.path.normpath(d) for d in FreeCAD.__ModDirs__])
    check("icons installed", os.path.isfile(resources.icon("HSMPlanner")), resources.icon("HSMPlanner"))
    machines = feedsim.machine_names()
    check("machine presets", "mikron-ucp710-840d" in machines and len(machines) >= 6, str(machines))
    posts = Path.Preferences.allAvailablePostProcessors()
    check("CAM lists the package's posts", {"hsm_siemens840d", "hsm_linuxcnc5x"} <= set(posts), str(posts))


def plan_simulate_post(out):
    """The master feature's guide-curve finishing by the 4-step net: planned, simulated, posted, saved."""
    from hsmplanner import evaluation, feedsim
    from hsmplanner.app import finishing, finishing_ops, guide_curve_net_object, master_feature_object
    from hsmplanner.app.compat import create_job
    from Path.Post.Processor import PostProcessorFactory

    document = FreeCAD.newDocument("InstalledStudy")
    part = master_feature_object.create(document)
    net = guide_curve_net_object.create(document, name="Net", Mode="4-step method", K=0.75,
                                        boundary_1=(part, part.Boundary1), boundary_2=(part, part.Boundary2),
                                        bottom_face=(part, part.BottomFace))
    job = create_job([part])
    op = finishing_ops.CreateGuideCurveFinishing("GuideCurves", parentJob=job)
    op.Net, op.Areas = net, "Elementary areas of the net"
    op.ToolController = finishing.ball_end_controller(job, 4.0, 4000.0)
    document.recompute()
    check("guide-curve finishing planned", op.isValid() and op.Passes > 0, "%s, %s passes" % (op.State, op.Passes))

    job.PostProcessorArgs = "--tolerance=0.01"
    sections = PostProcessorFactory.get_post_processor(job, "hsm_siemens840d").export()
    program = os.path.join(out, "installed_study.mpf")
    with open(program, "w") as stream:
        stream.write("".join(gcode for _, gcode in sections))
    text = open(program).read()
    check("posted by CAM with hsm_siemens840d", "CYCLE832(0.01,1,1)" in text and text.rstrip().endswith("M30"),
          text[:200])

    figures = evaluation.evaluate(feedsim.simulate(program, "mikron-ucp710-840d", blocks=True))
    check("simulated: longer than length / feed", figures["machining_time_s"] > figures["naive_time_s"] > 10,
          str(figures))
    print("     %d passes, %d blocks: %.1f s on the machine, %.1f s by length / feed" % (
        op.Passes, figures["blocks"], figures["machining_time_s"], figures["naive_time_s"]))
    saved = os.path.join(out, "installed_study.FCStd")
    document.saveAs(saved)
    FreeCAD.closeDocument(document.Name)
    return saved


def reopen_in_fresh_process(saved):
    """FreeCAD restores proxies only from modules under its Mod folders: the package's must qualify."""
    code = ("import FreeCAD; d = FreeCAD.openDocument(%r); "
            "print('PROXIES', sorted(type(o.Proxy).__module__ for o in d.Objects "
            "if o.TypeId.endswith('Python') and o.Name in ('MasterBottomFeature', 'Net', 'GuideCurves')))" % saved)
    done = subprocess.run(["freecadcmd", "-c", code], capture_output=True, text=True, timeout=300)
    line = next((l for l in done.stdout.splitlines() if l.startswith("PROXIES")), "")
    check("saved document restored in a fresh freecadcmd", line.count("hsmplanner.app.") == 3
          and "blocked import" not in done.stdout + done.stderr, (line or done.stdout[-500:]) + done.stderr[-500:])


def main():
    out, version = arguments()
    check_installation(version)
    reopen_in_fresh_process(plan_simulate_post(out))
    print("%d failed" % len(FAILURES))
    sys.stdout.flush()
    raise SystemExit(1 if FAILURES else 0)


try:
    main()
except SystemExit:
    raise
except Exception as error:  # a check that cannot run fails the test with its cause
    import traceback

    traceback.print_exc()
    sys.stderr.flush()
    raise SystemExit(1)
