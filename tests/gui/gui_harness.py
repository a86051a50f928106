"""Harness for macros that drive the real FreeCAD GUI under Xvfb.

A macro registers checks; the harness runs them once the main window is up, captures what reaches
sys.stderr (FreeCAD prints Python errors there), closes stray modal dialogs, takes screenshots, writes
result.json into $HSM_GUI_TEST_OUT and ends FreeCAD with os._exit so nothing can hang the test.
"""
import io
import json
import os
import sys
import time
import traceback

import FreeCADGui as Gui
from PySide2 import QtCore, QtWidgets

OUT = os.environ.get("HSM_GUI_TEST_OUT", os.path.join(os.getcwd(), "gui-test"))
WATCHDOG_SECONDS = 300


class _Tee(io.TextIOBase):
    """Copies everything written to the original stream and keeps it for the verdict."""

    def __init__(self, stream):
        self.stream, self.text = stream, []

    def write(self, text):
        self.text.append(text)
        return self.stream.write(text)

    def flush(self):
        self.stream.flush()


class GuiRun:
    def __init__(self):
        self.checks, self.failures, self.notes, self.screenshots = [], [], {}, []
        self.stderr = _Tee(sys.stderr)
        sys.stderr = self.stderr

    def check(self, name, condition, detail=""):
        if not condition:
            self.failures.append("%s %s" % (name, detail))

    def step(self, function):
        self.checks.append(function)
        return function

    def process_events(self, seconds=0.5):
        end = time.time() + seconds
        while time.time() < end:
            QtWidgets.QApplication.processEvents()
            time.sleep(0.02)

    def close_modal_dialogs(self):
        widget = QtWidgets.QApplication.activeModalWidget()
        while widget is not None:
            self.failures.append("modal dialog appeared: %s %r" % (type(widget).__name__, widget.windowTitle()))
            widget.close()
            self.process_events(0.2)
            if QtWidgets.QApplication.activeModalWidget() is widget:
                break
            widget = QtWidgets.QApplication.activeModalWidget()

    def check_fits_combo_view(self, name, form):
        """The panel fits FreeCAD's default Combo View (its minimum width), and its widgets do not overflow
        the width it is given there."""
        from hsmplanner.gui.task_panel import COMBO_VIEW_WIDTH

        needed = form.minimumSizeHint().width()
        self.notes.setdefault("minimum panel widths (px)", {})[name] = needed
        self.check("%s fits the %d px Combo View" % (name, COMBO_VIEW_WIDTH), needed <= COMBO_VIEW_WIDTH,
                   "needs %d px" % needed)

    def screenshot(self, name):
        """Grab the whole main window from the screen (grab() would leave the 3D view blank)."""
        self.process_events(0.5)
        window = Gui.getMainWindow()
        path = os.path.join(OUT, name + ".png")
        QtWidgets.QApplication.primaryScreen().grabWindow(window.winId()).save(path)
        self.screenshots.append(path)
        return path

    def run(self):
        try:
            for function in self.checks:
                self.close_modal_dialogs()
                function(self)
                self.process_events(0.3)
            self.close_modal_dialogs()
        except Exception:
            self.failures.append("exception: " + traceback.format_exc())
        errors = [line for line in "".join(self.stderr.text).splitlines()
                  if "Traceback" in line or "Error" in line or "Exception" in line]
        if errors:
            self.failures.append("errors printed during the run: %s" % errors[:10])
        self.finish()

    def finish(self):
        os.makedirs(OUT, exist_ok=True)
        verdict = {"ok": not self.failures, "failures": self.failures, "notes": self.notes,
                   "screenshots": self.screenshots}
        with open(os.path.join(OUT, "result.json"), "w") as stream:
            json.dump(verdict, stream, indent=2)
        sys.__stdout__.flush()
        os._exit(0)

    def start(self, delay_ms=1500):
        os.makedirs(OUT, exist_ok=True)
        QtCore.QTimer.singleShot(delay_ms, self.run)
        watchdog = QtCore.QTimer(Gui.getMainWindow())
        watchdog.setSingleShot(True)
        watchdog.timeout.connect(self._watchdog)
        watchdog.start(WATCHDOG_SECONDS * 1000)
        self._watchdog_timer = watchdog

    def _watchdog(self):
        self.failures.append("watchdog: the GUI run did not finish in %d s" % WATCHDOG_SECONDS)
        self.finish()
