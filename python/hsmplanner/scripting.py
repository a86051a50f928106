"""Helpers for scripts run by freecadcmd or /usr/bin/python3 (examples, tools).

freecadcmd runs a script as a module (its __name__ is the file's stem, not "__main__") and exits 0 after an
uncaught exception; run_script() turns failures into a message and a non-zero exit code. FreeCAD 1.0's
freecadcmd also puts itself first in sys.argv (['freecadcmd', 'script.py', args…], where /usr/bin/python3
gives ['script.py', args…]) and exits on SystemExit without flushing Python's streams, so what a script
printed last is lost unless flushed first.
"""
import os
import shutil
import sys
import traceback


def script_arguments(argv):
    """The arguments after the script's own path in `argv`, under freecadcmd 0.20 or 1.x or python3."""
    for index, arg in enumerate(argv):
        if arg.endswith(".py"):
            return list(argv[index + 1:])
    return list(argv[1:])


def exit_flushed(code):
    """SystemExit(code) once stdout and stderr are flushed (freecadcmd 1.0 drops unflushed output)."""
    sys.stdout.flush()
    sys.stderr.flush()
    raise SystemExit(code)


def output_dir(argv, default="out"):
    """The output folder named as the script's first argument (default: out/), created."""
    args = [a for a in script_arguments(argv) if not a.startswith("-")]
    folder = os.path.abspath(args[0] if args else default)
    os.makedirs(folder, exist_ok=True)
    return folder


def build_program(repo, name):
    """A program of the clone `repo`'s build for the FreeCAD running this (`make` names that build in
    HSM_BUILD_DIR; else build/freecad-MAJOR.MINOR of the running FreeCAD), or the installed one on the PATH (the
    Debian package's), or the build's path if neither exists (for the error that names it)."""
    build = os.environ.get("HSM_BUILD_DIR") or os.path.join(repo, "build", "freecad-%s" % _freecad_release())
    program = os.path.join(build, "bin", name)
    if os.path.exists(program):
        return program
    return shutil.which(name) or program


def _freecad_release():
    try:
        import FreeCAD
    except ImportError:
        return "1.1"
    return "%s.%s" % tuple(FreeCAD.Version()[:2])


def run_script(main):
    """Call main(sys.argv); exit 1 with the error on failure, 0 on success."""
    try:
        main(list(sys.argv))
    except SystemExit as request:
        exit_flushed(request.code)
    except Exception as error:  # report every failure of a user script with its cause
        traceback.print_exc()
        sys.stderr.write("error: %s\n" % error)
        exit_flushed(1)
    exit_flushed(0)
