"""View providers of HSM Planner document objects."""
from hsmplanner.resources import icon


class ViewProviderMasterBottomFeature:
    def __init__(self, view_object):
        view_object.Proxy = self

    def attach(self, view_object):
        self.Object = view_object.Object

    def getIcon(self):
        return icon("MasterBottomFeature")

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None
