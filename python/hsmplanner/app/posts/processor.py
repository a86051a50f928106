"""Our posts as FreeCAD 1.1's class-based post-processors.

FreeCAD 1.1's CAM (its Post Process command, a Job's post-processor list and tooltips) loads a post module by
name (`NAME_post.py` in its post folders or the Macro folder) and takes the class named `NAME.title()` from it
(`hsm_siemens840d` → `Hsm_Siemens840D`), a subclass of `Path.Post.Processor.PostProcessor` whose `export()`
returns the program's sections; a module without one is wrapped as a script. FreeCAD 1.0's base class has
none of 1.1's machinery and its Post Process command wraps our scripts' `export(objects, filename, args)` as
before, so the class is made only on 1.1. Either way the program is the one `export` writes.
"""


def processor_class(class_name, export, tooltip, parser):
    """The class-based post-processor `class_name` that writes with `export(objects, "-", argstring)` (each
    section of the Job: its operations and tool controllers, after the Job itself), or None on a FreeCAD whose
    posts are scripts only (1.0)."""
    try:
        from Path.Post.Processor import PostProcessor
    except ImportError:
        return None
    if not hasattr(PostProcessor, "process_postables"):
        return None

    class Processor(PostProcessor):
        def __init__(self, job):
            super().__init__(job, tooltip=tooltip, tooltipargs=parser.format_help(), units="Metric")

        @property
        def tooltip(self):
            return tooltip

        @property
        def tooltipArgs(self):
            return parser.format_help()

        def export(self):
            """[(section name, program)] of the Job as CAM orders it (by fixture, tool or operation; split or
            not), the Job's PostProcessorArgs as the arguments."""
            arguments = getattr(self._job, "PostProcessorArgs", "") or ""
            return [(section, export([self._job] + list(objects), "-", arguments))
                    for section, objects in self._buildPostList()]

    Processor.__name__ = Processor.__qualname__ = class_name
    return Processor
