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
    """An analysis whose detailed result (`self.result`, set by execute) is not saved with the document:
    forgotten when the document is reopened, computed again when first asked for."""

    def forget(self):
        self.result = None

    def has_input(self, obj):
        return True

    def ensure_result(self, obj):
        if getattr(self, "result", None) is None and self.has_input(obj):
            self.execute(obj)
        return self.result

    def onDocumentRestored(self, obj):
        self.forget()
