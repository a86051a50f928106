"""Which tool controller a new operation of ours takes in its Job: FreeCAD's default controller (a Ø5 mm flat
end mill with feeds of 0) would only make it fail, so an operation takes one it can use, or one is added."""
import FreeCAD


def usable_or_added(job, chosen, usable, add, missing):
    """`chosen` (FreeCAD's pick) if usable(controller), else the Job's first usable one, else add(job, number)
    with the next free tool number, said in the Report view ("<Job> had no <missing>: added …")."""
    if chosen is not None and usable(chosen):
        return chosen
    found = [controller for controller in job.Tools.Group if usable(controller)]
    if found:
        return found[0]
    number = 1 + max([getattr(c, "ToolNumber", 0) for c in job.Tools.Group], default=0)
    controller, described = add(job, number)
    FreeCAD.Console.PrintMessage("%s had no %s: added '%s' (%s); change it in the Job's tool controllers\n"
                                 % (job.Label, missing, controller.Label, described))
    return controller
