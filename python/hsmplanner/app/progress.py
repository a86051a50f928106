"""A progress dialog for the core's long computations (finishing, curve nets): it shows how far the
computation is, and Cancel (or Esc) stops it: the core raises hsmplanner.Cancelled, FreeCAD marks the object
"… cancelled", and the document is kept as it was. Headless (freecadcmd, scripts) nothing is shown: a script
passes its own progress callable to the API.

Why our own dialog and not FreeCAD's progress bar (Base.ProgressIndicator): an operation computes inside the
document's recompute, which runs FreeCAD's sequencer already; a nested indicator never sees Esc (the
recompute's sequencer takes it, after our computation has run to its end).

While a dialog is open, `in_background` runs a long call of the core in a worker thread (the core releases
Python's lock) and keeps the GUI's event loop turning every PUMP_SECONDS: the 3D view redraws, the dialog
moves and Cancel answers even inside a call that reports no progress for seconds (a stock meshed finely, a
boolean). The worker's progress reports only record the share done; the GUI thread shows it.
"""
import contextlib
import threading
import time

import FreeCAD

STEPS = 100
SHOW_AFTER_MS = 700  # quick computations flash no dialog
PUMP_SECONDS = 0.05

_pumps = []  # the open dialogs' pumps, innermost last


class _Pump:
    """What a progress dialog shows, written from any thread, shown from the GUI thread."""

    def __init__(self, dialog):
        self.dialog, self.done, self.label, self.cancelled = dialog, 0.0, None, False
        self.shown = time.monotonic()

    def report(self, done):
        self.done = done
        if threading.current_thread() is threading.main_thread():
            self.show()
        return not self.cancelled

    def say(self, label):
        self.label = label
        if threading.current_thread() is threading.main_thread():
            self.show()

    def show(self):
        from PySide import QtWidgets

        if self.label is not None:
            self.dialog.setLabelText("%s…" % self.label)
            self.label = None
        self.dialog.setValue(min(STEPS, int(self.done * STEPS)))
        QtWidgets.QApplication.processEvents()
        self.shown = time.monotonic()
        self.cancelled = self.cancelled or self.dialog.wasCanceled()


def breathe():
    """Serves the GUI's events when a progress dialog is open (the display of a long computation's result,
    drawn in the GUI thread, calls it between pieces); nothing otherwise."""
    if _pumps and threading.current_thread() is threading.main_thread() \
            and time.monotonic() - _pumps[-1].shown > PUMP_SECONDS:
        _pumps[-1].show()


def in_background(function, *args, **kwargs):
    """function(*args, **kwargs); while a progress dialog is open, in a worker thread with the GUI's events
    processed meanwhile (what it raises is raised here). Outside the GUI, or with no dialog open, a plain call."""
    if not _pumps or threading.current_thread() is not threading.main_thread():
        return function(*args, **kwargs)
    pump, outcome = _pumps[-1], {}

    def work():
        try:
            outcome["value"] = function(*args, **kwargs)
        except BaseException as error:  # raised again in the GUI thread, whatever it is
            outcome["error"] = error

    worker = threading.Thread(target=work, name="hsmplanner core", daemon=True)
    worker.start()
    while worker.is_alive():
        worker.join(PUMP_SECONDS)
        pump.show()
    if "error" in outcome:
        raise outcome["error"]
    return outcome["value"]


@contextlib.contextmanager
def freecad_progress(text):
    """A progress callable for the core while the block runs (its `say(text)` changes the dialog's words);
    None outside the GUI."""
    if not FreeCAD.GuiUp:
        yield None
        return
    import FreeCADGui
    from PySide import QtCore, QtWidgets

    dialog = QtWidgets.QProgressDialog("%s…" % text, "Cancel", 0, STEPS, FreeCADGui.getMainWindow())
    dialog.setWindowTitle("HSM Planner")
    dialog.setWindowModality(QtCore.Qt.WindowModal)
    dialog.setMinimumDuration(SHOW_AFTER_MS)
    dialog.setAutoClose(False)
    dialog.setValue(0)

    pump = _Pump(dialog)

    def progress(done):
        return pump.report(done)

    progress.say = pump.say  # what runs now, in a long series
    _pumps.append(pump)
    try:
        yield progress
    finally:
        _pumps.remove(pump)
        dialog.reset()
        dialog.close()
        dialog.deleteLater()


def staged(progress, weights):
    """One progress callable per stage of a computation (each reports its own 0..1), reporting to `progress`
    the share of the whole; Nones outside the GUI."""
    if progress is None:
        return [None] * len(weights)
    total = float(sum(weights)) or 1.0
    starts = [sum(weights[:i]) for i in range(len(weights))]
    return [lambda done, start=start, weight=weight: progress((start + weight * done) / total)
            for start, weight in zip(starts, weights)]
