"""GUI test: the documents saved with FreeCAD 0.20.2 (../shared/data/freecad-0.20) open in this FreeCAD's GUI
with their objects, proxies and view providers, recompute, and give the paths test_documents_020 expects (the
same checks: tests/python/documents_020.py); a screenshot of each."""
import os
import sys
import tempfile

import FreeCAD
import FreeCADGui as Gui

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "python"))
from gui_harness import GuiRun  # noqa: E402
import documents_020 as documents  # noqa: E402

run = GuiRun()
FOLDER = tempfile.mkdtemp(prefix="hsm-gui-020-")
state = {}


def view_provider_problems(document):
    """Every Python view provider came back (FreeCAD's under their 0.20 module names too)."""
    problems = []
    for obj in document.Objects:
        view = getattr(obj, "ViewObject", None)
        if view is not None and view.TypeId.endswith("Python") and getattr(view, "Proxy", None) is None:
            problems.append("%s: view provider %s not restored" % (obj.Name, view.TypeId))
    return problems


def check_all(run, what, problems):
    run.check(what, not problems, str(problems[:5]))


@run.step
def fresh_objects_of_today(run):
    scratch = FreeCAD.newDocument("Fresh020")
    state["fresh"] = documents.fresh_objects(scratch)
    state["record"] = documents.saved_record()


def open_and_check(name):
    def step(run):
        record = state["record"][name]
        document = documents.open_copy(name, FOLDER)
        Gui.ActiveDocument = Gui.getDocument(document.Name)
        saved_paths = documents.paths_of(document)
        check_all(run, "%s: objects and proxies" % name, documents.proxy_problems(document, record["objects"]))
        check_all(run, "%s: Job" % name, documents.job_problems(document))
        check_all(run, "%s: view providers" % name, view_provider_problems(document))
        check_all(run, "%s: paths as opened" % name, documents.saved_path_problems(record, saved_paths))
        check_all(run, "%s: properties" % name, documents.property_problems(document, state["fresh"]))
        check_all(run, "%s: recompute" % name, documents.recompute_all(document))
        check_all(run, "%s: recomputed paths" % name,
                  documents.path_problems(name, record, saved_paths, document))
        run.notes[name] = {obj: len(document.getObject(obj).Path.Commands)
                           for obj in record["path_commands_and_length_as_saved"]}
        Gui.activeDocument().activeView().viewIsometric()
        Gui.SendMsgToActiveView("ViewFit")
        run.screenshot("documents_020_" + name.replace(".FCStd", ""))

    step.__name__ = "open_" + name.replace(".FCStd", "")
    return step


for _name in documents.DOCUMENTS:
    run.step(open_and_check(_name))

run.start()
