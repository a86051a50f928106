"""What FreeCAD's GUI runs for a GUI test: the macro named by HSM_GUI_MACRO, guarded.

FreeCAD shows an error raised by a macro it was started with in its Report view and then waits: a macro that
fails before its harness has started (an import that no longer exists, a name error at module level) would
leave FreeCAD open until the runner's timeout. Here any exception the macro raises while it loads writes the
verdict with its traceback and ends FreeCAD at once.
"""
import json
import os
import runpy
import sys
import traceback


def _fail(out, text):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "result.json"), "w") as stream:
        json.dump({"ok": False, "failures": ["the macro raised while loading: " + text], "notes": {},
                   "screenshots": []}, stream, indent=2)
    sys.__stderr__.write(text)
    sys.__stderr__.flush()
    os._exit(1)


def _launch():
    macro = os.environ.get("HSM_GUI_MACRO", "")
    out = os.environ.get("HSM_GUI_TEST_OUT", os.getcwd())
    if not os.path.isfile(macro):
        _fail(out, "HSM_GUI_MACRO=%r is not a file: set it to the path of a tests/gui/gui_*.py macro\n" % macro)
    sys.path.insert(0, os.path.dirname(os.path.abspath(macro)))
    try:
        runpy.run_path(macro, run_name="__main__")
    except BaseException:  # SystemExit too: a macro must end through its harness
        _fail(out, traceback.format_exc())


_launch()
