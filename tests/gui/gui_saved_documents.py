"""GUI test: the documents saved by HSM Planner with FreeCAD 0.20.2 and 1.0.0 (../shared/data/freecad-0.20 and
freecad-1.0) open in this FreeCAD's GUI with their objects, proxies and view providers, recompute, and give the
paths test_saved_documents expects (the same checks: tests/python/saved_documents.py); a screenshot of each."""
import os
import sys
import tempfile

import FreeCAD
import FreeCADGui as Gui

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "python"))
from gui_harness import GuiRun  # noqa: E402
import saved_documents as documents  # noqa: E402

run = GuiRun()
FOLDER = tempfile.mkdtemp(prefix="hsm-gui-saved-")
state = {}


def view_provider_problems(document):
    """Every Python view provider came back (FreeCAD's under their 0.20 module names too, 1.0's tool bits')."""
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
    scratch = FreeCAD.newDocument("FreshObjects")
    state["fresh"] = documents.fresh_objects(scratch)


def open_and_check(saved_with, name):
    def step(run):
        record = documents.saved_record(saved_with)[name]
        document = documents.open_copy(saved_with, name, FOLDER)
        Gui.ActiveDocument = Gui.getDocument(document.Name)
        saved_paths = documents.paths_of(document)
        check_all(run, "%s: objects and proxies" % name, documents.proxy_problems(document, record["objects"]))
        check_all(run, "%s: Job" % name, documents.job_problems(document))
        check_all(run, "%s: view providers" % name, view_provider_problems(document))
        check_all(run, "%s: paths as opened" % name, documents.saved_path_problems(record, saved_paths))
        check_all(run, "%s: properties" % name, documents.property_problems(document, state["fresh"]))
        check_all(run, "%s: recompute" % name, documents.recompute_all(document))
        check_all(run, "%s: recomputed paths" % name,
                  documents.path_problems(saved_with, name, record, saved_paths, document))
        run.notes["%s %s" % (saved_with, name)] = {obj: len(document.getObject(obj).Path.Commands)
                           for obj in record["path_commands_and_length_as_saved"]}
        Gui.activeDocument().activeView().viewIsometric()
        Gui.SendMsgToActiveView("ViewFit")
        run.screenshot("saved_%s_%s" % (saved_with.replace(".", ""), name.replace(".FCStd", "")))
        FreeCAD.closeDocument(document.Name)

    step.__name__ = "open_%s_%s" % (saved_with.replace(".", ""), name.replace(".FCStd", ""))
    return step


for _saved_with, _names in documents.SAVED_WITH.items():
    for _name in _names:
        run.step(open_and_check(_saved_with, _name))

run.start()
