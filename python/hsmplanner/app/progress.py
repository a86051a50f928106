"""A progress dialog for the core's long computations (finishing, curve nets): it shows how far the
computation is, and Cancel (or Esc) stops it: the core raises hsmplanner.Cancelled, FreeCAD marks the object
"… cancelled", and the document is kept as it was. Headless (freecadcmd, scripts) nothing is shown: a script
passes its own progress callable to the API.

Why our own dialog and not FreeCAD's progress bar (Base.ProgressIndicator): an operation computes inside the
document's recompute, which runs FreeCAD's sequencer already; a nested indicator never sees Esc (the
recompute's sequencer takes it, after our computation has run to its end).
"""
import contextlib

import FreeCAD

STEPS = 100
SHOW_AFTER_MS = 700  # quick computations flash no dialog


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

    def progress(done):
        dialog.setValue(min(STEPS, int(done * STEPS)))
        QtWidgets.QApplication.processEvents()
        return not dialog.wasCanceled()

    progress.say = lambda label: dialog.setLabelText("%s…" % label)  # what runs now, in a long series
    try:
        yield progress
    finally:
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
