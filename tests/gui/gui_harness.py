"""Harness for macros that drive the real FreeCAD GUI under Xvfb.

A macro registers checks; the harness runs them once the main window is up, captures what reaches
sys.stderr (FreeCAD prints Python errors there), closes stray modal dialogs, takes screenshots, writes
result.json into $HSM_GUI_TEST_OUT and ends FreeCAD with os._exit so nothing can hang the test.

After an action, a macro waits for its effect with wait_until(condition, timeout, what) (an object
recomputed, a panel open, a dialog shown, a map drawn), never for a fixed time: a slow machine only waits
longer, and an effect that never comes is a failure that names it.
"""
import io
import json
import os
import sys
import time
import traceback

import FreeCADGui as Gui
from PySide import QtCore, QtWidgets

OUT = os.environ.get("HSM_GUI_TEST_OUT", os.path.join(os.getcwd(), "gui-test"))


def show_only(*objects):
    """Only `objects` visible in the active document's 3D view."""
    import FreeCAD

    for obj in FreeCAD.ActiveDocument.Objects:
        if obj.ViewObject is not None:
            obj.ViewObject.Visibility = obj in objects


def image_pixels(path):
    """The picture at `path` as a numpy array (height, width, 4) of bytes in Qt's RGB32 order (B, G, R, 255),
    on Qt 5 (byteCount) and Qt 6 (sizeInBytes)."""
    import numpy as np
    from PySide import QtGui

    image = QtGui.QImage(path).convertToFormat(QtGui.QImage.Format_RGB32)
    size = image.sizeInBytes() if hasattr(image, "sizeInBytes") else image.byteCount()
    rows = np.frombuffer(image.constBits(), dtype=np.uint8, count=size).reshape(image.height(), image.bytesPerLine())
    return rows[:, : 4 * image.width()].reshape(image.height(), image.width(), 4).copy()


def scene_nodes(node, type_name):
    """Every Coin node of a type (e.g. "SoText2") under a scene node, in drawing order, cast to that type."""
    from pivy import coin

    search = coin.SoSearchAction()
    search.setType(getattr(coin, type_name).getClassTypeId())
    search.setInterest(coin.SoSearchAction.ALL)
    search.apply(node)
    paths = search.getPaths()
    return [coin.cast(paths[i].getTail(), type_name) for i in range(paths.getLength())]
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
        """Runs the event loop for a fixed time: only to let the 3D view redraw before a screenshot, where
        there is no condition to wait for. After an action, use wait_until."""
        end = time.time() + seconds
        while time.time() < end:
            QtWidgets.QApplication.processEvents()
            time.sleep(0.02)

    def wait_until(self, condition, timeout=10.0, what="the condition"):
        """Processes events until condition() is true, and returns True; after `timeout` seconds records a
        failure naming `what` and returns False. An exception raised by the condition counts as "not yet"
        (a panel not open yet), and is quoted in the failure if the condition never holds."""
        end = time.time() + timeout
        last_error = None
        while True:
            QtWidgets.QApplication.processEvents()
            try:
                if condition():
                    return True
                last_error = None
            except Exception as error:
                last_error = "%s: %s" % (type(error).__name__, error)
            if time.time() >= end:
                self.failures.append("timed out after %g s waiting for %s%s"
                                     % (timeout, what, " (%s)" % last_error if last_error else ""))
                return False
            time.sleep(0.02)

    @staticmethod
    def event_loop_probe(action):
        """Runs action() with a Qt timer ticking every 20 ms, as a user's clicks and the 3D view's redraws would
        be served: {"longest_freeze_s": the longest time between ticks, "ticks", "ticks_in_worker": ticks while
        the core computed in its worker thread, "frozen_in": where the GUI thread was in its longest freeze}."""
        import threading
        import traceback

        ticks, in_worker, frozen, watching = [time.monotonic()], [0], {}, [True]
        main = threading.main_thread().ident

        def tick():
            ticks.append(time.monotonic())
            in_worker[0] += any(t.name == "hsmplanner core" for t in threading.enumerate())

        def watch():  # samples the GUI thread's stack while it serves no event
            while watching[0]:
                time.sleep(0.05)
                since = time.monotonic() - ticks[-1]
                frame = sys._current_frames().get(main)
                if since > 0.2 and frame is not None and since > frozen.get("s", 0.0):
                    stack = [f for f in traceback.extract_stack(frame) if "hsmplanner" in f.filename]
                    frozen.update(s=round(since, 2), where=["%s:%d %s" % (os.path.basename(f.filename), f.lineno,
                                                                          f.name) for f in stack[-4:]])

        watcher = threading.Thread(target=watch, daemon=True)
        timer = QtCore.QTimer()
        timer.setInterval(20)
        timer.timeout.connect(tick)
        timer.start()
        watcher.start()
        try:
            action()
        finally:
            timer.stop()
            watching[0] = False
            watcher.join()
        ticks.append(time.monotonic())
        return {"longest_freeze_s": round(max(b - a for a, b in zip(ticks, ticks[1:])), 2),
                "ticks": len(ticks) - 2, "ticks_in_worker": in_worker[0], "frozen_in": frozen.get("where")}

    @staticmethod
    def valid(obj):
        """The document object exists and its last recompute did not fail. (An object recomputed alone, by
        obj.recompute(), stays "Touched": wait for what its recompute sets as well.)"""
        return obj is not None and obj.isValid()

    @classmethod
    def shape_built(cls, obj):
        """The object is valid and has its shape."""
        return cls.valid(obj) and not obj.Shape.isNull()

    @staticmethod
    def task_dialog_open():
        return bool(Gui.Control.activeDialog())

    def close_modal_dialogs(self):
        widget = QtWidgets.QApplication.activeModalWidget()
        while widget is not None:
            self.failures.append("modal dialog appeared: %s %r" % (type(widget).__name__, widget.windowTitle()))
            widget.close()
            if not self.wait_until(lambda: QtWidgets.QApplication.activeModalWidget() is not widget, 5.0,
                                   "the modal dialog %r to close" % widget.windowTitle()):
                break
            widget = QtWidgets.QApplication.activeModalWidget()

    @staticmethod
    def _ancestors(widget, kind):
        """The widget's ancestors of a kind, nearest first."""
        found = []
        while widget is not None:
            widget = widget.parentWidget()
            if isinstance(widget, kind):
                found.append(widget)
        return found

    def check_fits_combo_view(self, name, form):
        """The panel as the user sees it in FreeCAD's Combo View at its default width (the dock is set to it):
        the task view needs no horizontal scrolling, nothing sticks out of it (a button, a field), no label is
        cut and no combo box's text is cut (a text drawn elided has its full text in the tool tip). Notes the
        Combo View width the task view needs, and the form's own minimum width."""
        from hsmplanner.gui.task_panel import COMBO_VIEW_WIDTH

        # the task view is the outermost scroll area in the dock (a panel's tool box scrolls its pages too)
        docks = self._ancestors(form, QtWidgets.QDockWidget)
        dock = docks[0] if docks else None
        scrolls = [w for w in self._ancestors(form, QtWidgets.QScrollArea) if dock is not None and dock.isAncestorOf(w)]
        scroll = scrolls[-1] if scrolls else None
        if scroll is None:
            self.check("%s is shown in the Combo View's task view" % name, False)
            return
        window = Gui.getMainWindow()
        # FreeCAD 1.0 shows task panels in the Combo View, which takes the width set; 1.1 in its own Tasks dock
        # laid over the 3D view (its default width is more, and the main window cannot resize an overlaid dock:
        # it would say so in a notification): there the panel must need no more than the Combo View would give
        # it, and scroll nowhere as shown.
        overlaid = self._overlaid(window, dock)
        if not overlaid:
            window.resizeDocks([dock], [COMBO_VIEW_WIDTH], QtCore.Qt.Horizontal)
        # the dock takes the width over a few events; it stays wider when the panel's minimum needs more (the
        # check below then fails, saying how much the panel needs)
        self.process_events(0.5)
        frame = dock.width() - scroll.viewport().width()
        needed = scroll.widget().minimumSizeHint().width() + frame
        widths = self.notes.setdefault("panel widths (px)", {})
        widths[name] = {"Combo View needed": needed, "Combo View shown": dock.width(),
                        "form minimum": form.minimumSizeHint().width()}
        widths[name]["task view laid over the 3D view"] = overlaid
        self.check("%s fits the %d px Combo View" % (name, COMBO_VIEW_WIDTH),
                   needed <= COMBO_VIEW_WIDTH and (dock.width() <= COMBO_VIEW_WIDTH or overlaid)
                   and scroll.horizontalScrollBar().maximum() == 0,
                   "needs %d px (hidden right of the view: %d px); widest: %s"
                   % (needed, scroll.horizontalScrollBar().maximum(), self.widest(scroll.widget())))
        cut = self.cut_texts(scroll)
        self.check("%s: no text cut at %d px" % (name, COMBO_VIEW_WIDTH), not cut, str(cut[:6]))

    @staticmethod
    def _overlaid(window, dock):
        """True for a dock FreeCAD 1.1 lays over the 3D view (not in the main window's dock layout)."""
        return dock.parent() is not window

    @staticmethod
    def widest(widget, count=6):
        """The visible widgets under `widget` that need the most width (minimum size hint), to say what to narrow."""
        hints = [(w.minimumSizeHint().width(), type(w).__name__, w.objectName(),
                  (w.text() if hasattr(w, "text") and callable(w.text) else "")[:30])
                 for w in widget.findChildren(QtWidgets.QWidget) if w.isVisible()]
        return sorted(hints, key=lambda h: -h[0])[:count]

    @staticmethod
    def shown_text(combo):
        """A combo box's current text as it is drawn (elided by ours, whole by Qt's)."""
        return combo.shown_text() if hasattr(combo, "shown_text") else combo.currentText()

    def cut_texts(self, scroll):
        """What the visible widgets of a task view show cut: a widget past the view's right edge, a label or a
        button narrower than its text, a combo box whose drawn text does not fit its field, or is elided with
        no tool tip giving it whole."""
        right = scroll.viewport().mapToGlobal(QtCore.QPoint(scroll.viewport().width(), 0)).x()
        cut = []
        for widget in scroll.widget().findChildren(QtWidgets.QWidget):
            if not widget.isVisible() or widget.width() <= 0 or isinstance(widget, QtWidgets.QScrollBar):
                continue
            text = widget.text() if hasattr(widget, "text") and callable(widget.text) else ""
            if widget.mapToGlobal(QtCore.QPoint(widget.width(), 0)).x() > right + 1:
                cut.append("%s %r past the view's edge" % (type(widget).__name__, text or widget.objectName()))
            elif isinstance(widget, QtWidgets.QLabel) and text and not widget.wordWrap():
                if widget.contentsRect().width() + 1 < widget.sizeHint().width() - 2 * widget.margin():
                    cut.append("label %r" % text)
            elif isinstance(widget, (QtWidgets.QPushButton, QtWidgets.QCheckBox, QtWidgets.QRadioButton)) and text:
                if widget.width() < self.button_text_width(widget):
                    cut.append("button %r" % text)
            elif isinstance(widget, QtWidgets.QComboBox):
                cut += self._combo_cut(widget)
        return cut

    @staticmethod
    def button_text_width(button):
        """The width a button needs to show its text whole (a check box: with its box)."""
        from hsmplanner.gui.task_panel import button_text_width

        if not isinstance(button, (QtWidgets.QCheckBox, QtWidgets.QRadioButton)):
            return button_text_width(button)
        style = button.style()
        box = style.pixelMetric(QtWidgets.QStyle.PM_IndicatorWidth) + style.pixelMetric(
            QtWidgets.QStyle.PM_CheckBoxLabelSpacing)
        return button.fontMetrics().horizontalAdvance(button.text().replace("&", "")) + box

    def _combo_cut(self, combo):
        shown, full = self.shown_text(combo), combo.currentText()
        option = QtWidgets.QStyleOptionComboBox()
        combo.initStyleOption(option)
        field = combo.style().subControlRect(QtWidgets.QStyle.CC_ComboBox, option,
                                             QtWidgets.QStyle.SC_ComboBoxEditField, combo)
        if combo.fontMetrics().horizontalAdvance(shown) > field.width():
            return ["combo box %r cut to %d px" % (full, field.width())]
        if shown != full and full not in combo.toolTip():
            return ["combo box %r elided without it in its tool tip" % full]
        return []

    def check_read_apart(self, name, combos):
        """Combo boxes naming different objects read differently as drawn (not cut to one shared prefix)."""
        shown = {self.shown_text(c): c.currentText() for c in combos}
        fulls = {c.currentText() for c in combos}
        self.notes.setdefault("names as drawn", {})[name] = sorted(shown)
        self.check("%s: different names read apart as drawn" % name, len(shown) == len(fulls), str(shown))

    def check_table_reads(self, name, table, key_columns):
        """Every header of the table reads whole (with room for the sort arrow if it sorts), every cell's text fits its
        column, and the first `key_columns` columns are in view without scrolling."""
        header, metrics = table.horizontalHeader(), table.fontMetrics()
        style = header.style()
        arrow = style.pixelMetric(QtWidgets.QStyle.PM_HeaderMarkSize) + 2 * style.pixelMetric(
            QtWidgets.QStyle.PM_HeaderMargin) if table.isSortingEnabled() else 0  # no arrow on an unsorted table
        headers = [table.horizontalHeaderItem(c).text() for c in range(table.columnCount())]
        cut = [text for c, text in enumerate(headers)
               if header.fontMetrics().horizontalAdvance(text) + arrow > header.sectionSize(c)]
        cut += [table.item(r, c).text() for r in range(table.rowCount()) for c in range(table.columnCount())
                if table.item(r, c) is not None
                and metrics.horizontalAdvance(table.item(r, c).text()) + 6 > table.columnWidth(c)]  # cell margins
        self.check("%s: headers and cells read whole" % name, not cut, str(cut[:6]))
        table.horizontalScrollBar().setValue(0)
        shown = [headers[c] for c in range(table.columnCount())
                 if header.sectionViewportPosition(c) + header.sectionSize(c) <= table.viewport().width()]
        self.notes.setdefault("table columns in view", {})[name] = shown
        self.check("%s: the key columns %s in view" % (name, headers[:key_columns]), shown[:key_columns] ==
                   headers[:key_columns], "in view: %s" % shown)

    def panel_plots(self, name, figure):
        """The panel's plots as the user sees them (the panel scrolls them out of the window's screenshot),
        saved and checked for readability."""
        image = os.path.join(OUT, name + ".png")
        figure.savefig(image)
        self.screenshots.append(image)
        self.check_plots_readable(name, figure)

    def check_plots_readable(self, name, figure):
        """Every text of the panel's plots lies inside the figure as the panel sizes it, and the tick labels of
        an axis do not run into each other (what a screenshot shows as "0306090120150180")."""
        figure.canvas.draw()
        renderer = figure.canvas.get_renderer()
        frame = figure.bbox.padded(1.0)
        outside, crowded = [], []
        def drawn_tick_labels(axis):  # matplotlib keeps labels for ticks outside the view: they are not drawn
            low, high = sorted(axis.get_view_interval())
            slack = 1e-9 * max(1.0, abs(high - low))
            return [label for tick in axis.get_major_ticks() if low - slack <= tick.get_loc() <= high + slack
                    for label in (tick.label1, tick.label2) if label.get_visible() and label.get_text()]

        for axes in figure.axes:
            ticks = [drawn_tick_labels(axes.xaxis), drawn_tick_labels(axes.yaxis)]
            texts = [axes.title, axes.xaxis.label, axes.yaxis.label] + ticks[0] + ticks[1]
            legend = axes.get_legend()
            if legend is not None:
                texts += [legend]
            for text in texts:
                if text.get_visible() and (not hasattr(text, "get_text") or text.get_text()):
                    box = text.get_window_extent(renderer)
                    if not (frame.contains(box.x0, box.y0) and frame.contains(box.x1, box.y1)):
                        outside.append(text.get_text() if hasattr(text, "get_text") else "legend")
            for labels in ticks:
                boxes = [t.get_window_extent(renderer) for t in labels]
                crowded += ["%s|%s" % (a, b) for a, b in zip(boxes, boxes[1:]) if a.overlaps(b)]
        size = "%dx%d px" % (figure.bbox.width, figure.bbox.height)
        self.check("%s: every text inside the plots (%s)" % (name, size), not outside, str(outside[:5]))
        self.check("%s: tick labels apart (%s)" % (name, size), not crowded, str(crowded[:3]))

    def press_escape_on_progress(self, seen, image_name):
        """Called from a timer while a computation runs: records the visible progress dialogs in `seen`, saves the
        first as `image_name`.png and presses Esc where the user's key would go (the dialog's focus, Cancel)."""
        from PySide import QtGui
        dialogs = [w for w in QtWidgets.QApplication.topLevelWidgets()
                   if isinstance(w, QtWidgets.QProgressDialog) and w.isVisible()]
        seen["dialogs"] = [(d.labelText(), d.value()) for d in dialogs]
        if not dialogs:
            return
        image = os.path.join(OUT, image_name + ".png")
        dialogs[0].grab().save(image)
        self.screenshots.append(image)
        dialogs[0].activateWindow()
        QtWidgets.QApplication.processEvents()
        target = QtWidgets.QApplication.focusWidget() or dialogs[0]
        for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
            QtWidgets.QApplication.sendEvent(target, QtGui.QKeyEvent(kind, QtCore.Qt.Key_Escape, QtCore.Qt.NoModifier))
        seen["cancelled"] = dialogs[0].wasCanceled()

    @staticmethod
    def report_view_text():
        """What FreeCAD's Report view shows (errors of recomputes land there, not on sys.stderr)."""
        return "\n".join(edit.toPlainText() for edit in Gui.getMainWindow().findChildren(QtWidgets.QTextEdit))

    def widget_screenshot(self, name, widget):
        """A window other than the main one (a plot window: no 3D view in it, so grab() draws it whole)."""
        self.wait_until(widget.isVisible, 5.0, "the window %r shown" % widget.windowTitle())
        self.process_events(0.5)  # settle: a new window lays out and paints its canvas over a few events
        path = os.path.join(OUT, name + ".png")
        widget.grab().save(path)
        self.screenshots.append(path)
        return path

    def screenshot(self, name):
        """Grab the whole main window from the screen (grab() would leave the 3D view blank)."""
        self.process_events(0.5)  # settle: the 3D view redraws (after a ViewFit, a new colour) on later events
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
                # not a wait for an effect: lets a dialog the step left behind (opened by a timer) show itself
                # before close_modal_dialogs looks for one
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
        # The watchdog below needs the event loop; a block outside it (a wait that never ends) is shown by
        # the Python stacks written to the log shortly before the runner's timeout kills FreeCAD.
        import faulthandler

        faulthandler.dump_traceback_later(WATCHDOG_SECONDS + 60, exit=True, file=sys.__stderr__)
        QtCore.QTimer.singleShot(delay_ms, self.run)
        watchdog = QtCore.QTimer(Gui.getMainWindow())
        watchdog.setSingleShot(True)
        watchdog.timeout.connect(self._watchdog)
        watchdog.start(WATCHDOG_SECONDS * 1000)
        self._watchdog_timer = watchdog

    def _watchdog(self):
        """Ends a run that hangs, with what it shows (a screenshot, the active modal widget) and where the Python
        code waits (the stacks, in the log): a modal dialog's loop or a wait that never ends."""
        import faulthandler

        modal = QtWidgets.QApplication.activeModalWidget()
        self.failures.append("watchdog: the GUI run did not finish in %d s%s" % (
            WATCHDOG_SECONDS, "; modal: %s %r" % (type(modal).__name__, modal.windowTitle()) if modal else ""))
        faulthandler.dump_traceback(file=sys.__stderr__)
        self.screenshot("watchdog")
        self.finish()
