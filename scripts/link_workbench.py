"""Link the repository into the Mod folder FreeCAD reports, so FreeCAD loads the HSM Planner workbench.

Run with freecadcmd: `freecadcmd scripts/link_workbench.py /path/to/repo`. Replaces an older link of ours;
refuses to touch a real folder of the same name.
"""
import os
import sys

import FreeCAD

LINK_NAME = "HSMPlanner"


def link_workbench(repo):
    repo = os.path.realpath(repo)
    if not os.path.isfile(os.path.join(repo, "InitGui.py")):
        raise SystemExit("error: %s is not the HSM Planner folder (no InitGui.py)" % repo)
    mod_dir = os.path.join(FreeCAD.getUserAppDataDir(), "Mod")
    os.makedirs(mod_dir, exist_ok=True)
    link = os.path.join(mod_dir, LINK_NAME)
    if os.path.islink(link):
        if os.path.realpath(link) == repo:
            return link
        os.remove(link)
    elif os.path.exists(link):
        raise SystemExit("error: %s exists and is not a link: move it away, then run `make build` again" % link)
    os.symlink(repo, link)
    print("HSM Planner workbench linked: %s -> %s" % (link, repo))
    return link


def link_posts(repo):
    """Our posts into FreeCAD's Macro folder, where the Job's processor list looks for *_post.py."""
    macro_dir = os.path.join(FreeCAD.getUserAppDataDir(), "Macro")
    os.makedirs(macro_dir, exist_ok=True)
    for name in ("siemens840d", "linuxcnc5x"):
        source = os.path.join(repo, "python", "hsmplanner", "app", "posts", name + "_post.py")
        link = os.path.join(macro_dir, "hsm_%s_post.py" % name)
        if os.path.islink(link) or not os.path.exists(link):
            if os.path.islink(link):
                os.remove(link)
            os.symlink(source, link)


def repo_argument():
    """REPO_DIR: the argument after this script's path (freecadcmd 1.0 puts itself first in sys.argv)."""
    script = next((i for i, a in enumerate(sys.argv) if a.endswith(".py")), 0)
    args = sys.argv[script + 1:]
    if not args:
        raise SystemExit("usage: freecadcmd scripts/link_workbench.py REPO_DIR")
    return args[0]


try:
    repo = repo_argument()
    link_workbench(repo)
    link_posts(os.path.realpath(repo))
except SystemExit as failure:
    if failure.code not in (None, 0):
        sys.stderr.write("%s\n" % failure.code)
    sys.stdout.flush()
    sys.stderr.flush()  # freecadcmd 1.0 exits without flushing them
    raise SystemExit(0 if failure.code in (None, 0) else 1)
sys.stdout.flush()
raise SystemExit(0)  # or freecadcmd would try to open the remaining arguments as documents
