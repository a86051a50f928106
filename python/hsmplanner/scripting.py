"""Helpers for scripts run by freecadcmd or /usr/bin/python3 (examples, tools).

freecadcmd runs a script as a module (its __name__ is the file's stem, not "__main__") and exits 0 after an
uncaught exception; run_script() turns failures into a message and a non-zero exit code.
"""
import os
import sys
import traceback


def output_dir(argv, default="out"):
    """The output folder named as the script's first argument (default: out/), created."""
    args = [a for a in argv[1:] if not a.startswith("-")]
    folder = os.path.abspath(args[0] if args else default)
    os.makedirs(folder, exist_ok=True)
    return folder


def run_script(main):
    """Call main(sys.argv); exit 1 with the error on failure, 0 on success."""
    try:
        main(list(sys.argv))
    except SystemExit:
        raise
    except Exception as error:  # report every failure of a user script with its cause
        traceback.print_exc()
        sys.stderr.write("error: %s\n" % error)
        raise SystemExit(1)
    raise SystemExit(0)
