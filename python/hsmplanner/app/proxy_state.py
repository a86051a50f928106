"""What our document-object proxies save: nothing beyond the object's properties (0.20 spells it
__getstate__/__setstate__, 1.x dumps/loads), and analyses whose result lives in memory only."""


class NoSavedState:
    """A proxy whose whole state is in its object's properties; caches are dropped by `forget`."""

    def forget(self):
        pass

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        self.forget()

    def dumps(self):
        return None

    def loads(self, state):
        self.forget()


class InMemoryResult(NoSavedState):
    """An analysis whose detailed result (`self.result`, set by compute) is not saved with the document:
    forgotten when the document is reopened, computed again when first asked for.

    A computation that fails keeps its message in `self.error`; the view provider and the panel then show the
    message instead of computing again and raising the same error from every redraw.

    A bad input (ValueError) is reported as FreeCAD's own CAM operations report theirs: one line in the report
    view, no traceback, and the object stays valid with empty results (`failed`). An analysis is a leaf of the
    document: nothing downstream needs to see it fail, and a traceback only hides the one line a user must read.
    Any other exception is a bug and propagates with its traceback (FreeCAD marks the object invalid)."""

    def forget(self):
        self.result = None
        self.error = None

    def has_input(self, obj):
        return True

    def compute(self, obj):
        raise NotImplementedError

    def failed(self, obj):
        """Empties the object's result properties after an error (and so redraws its view)."""

    def execute(self, obj):
        try:
            self.run(obj)
        except ValueError:
            import FreeCAD

            FreeCAD.Console.PrintError("%s: %s\n" % (obj.Label, self.error))
            self.failed(obj)

    def run(self, obj):
        """Computes the result, keeping the error in `self.error`; raises it (for panels and scripts)."""
        self.result, self.error = None, None
        try:
            self.compute(obj)
        except Exception as error:
            self.result, self.error = None, str(error) or type(error).__name__
            raise

    def ensure_result(self, obj):
        """The result, computed if needed; None when there is no input or the computation failed (see
        `self.error`)."""
        if getattr(self, "result", None) is None and getattr(self, "error", None) is None and self.has_input(obj):
            try:
                self.run(obj)
            except Exception:
                return None
        return getattr(self, "result", None)

    def onDocumentRestored(self, obj):
        self.forget()
