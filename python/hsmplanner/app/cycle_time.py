"""The cycle time of a CAM Job, CAM's own operations included: per operation, three figures side by side.

- CAM's estimate: the operation's CycleTime property, FreeCAD's `Path.getCycleTime` (length / feed, every move
  with a Z component timed at the tool controller's vertical feed, rapids at the controller's rapid rates when
  they are set, else not at all);
- length / feed: every move at its programmed feed, rapids at the machine's rapid traverse;
- simulated: what the machine does, by the feed-rate simulator on a machine model (jerk, acceleration,
  look-ahead, the rotary axes), with what held the speed.

The Job's total is the whole program simulated in order (the tool changes, the moves between operations),
so it is not the sum of the rows. Pure functions; the document object is cycle_time_object.py.
"""
from hsmplanner import feedsim

from .feedrate import is_job, operations, simulate_object


def cam_estimate_s(obj):
    """Seconds of CAM's CycleTime property ("HH:MM:SS"), or None where CAM gave none or an error text ("Tool
    Feedrate Error")."""
    text = str(getattr(obj, "CycleTime", "") or "").strip()
    parts = text.split(":")
    if not text or len(parts) > 3 or not all(p.strip().isdigit() for p in parts):
        return None
    return float(sum(int(p) * scale for p, scale in zip(reversed(parts), (1, 60, 3600))))


def held_by_text(summary, count=2):
    """What held the speed, the largest shares first: 'F 79 %, X 15 %' (a share under 0.5 % left out)."""
    shares = [(name, share) for name, share in feedsim.speed_limit_shares(summary).items() if share >= 0.005]
    return ", ".join("%s %.0f %%" % (name, 100.0 * share) for name, share in shares[:count])


def operation_row(op, machine):
    """One operation's figures: dict(label, cam_s, naive_s, simulated_s, held_by, error). An operation that
    cannot be simulated (no path, failed or stale, cutting at F0) has error set and no simulated time."""
    row = dict(name=op.Name, label=op.Label, cam_s=cam_estimate_s(op), naive_s=None, simulated_s=None,
               held_by="", error="")
    try:
        summary = simulate_object(op, machine, blocks=False).summary
    except (ValueError, RuntimeError) as error:
        row["error"] = str(error)
        return row
    row.update(naive_s=summary.naive_time, simulated_s=summary.total_time, held_by=held_by_text(summary))
    return row


def job_rows(job, machine=feedsim.DEFAULT_MACHINE):
    """(rows, total) of a Job on `machine` (a preset name or machine file): a row per active operation in order,
    and the total: the whole program simulated as it runs (dict as a row, label 'Job', cam_s CAM's Job
    CycleTime). The total has an error when any operation has one: a program with a hole has no time."""
    if not is_job(job):
        raise ValueError("%s is not a CAM Job: pick a Job" % getattr(job, "Label", job))
    ops = operations(job)
    if not ops:
        raise ValueError("%s has no active operation: add one, or make one active" % job.Label)
    feedsim.load_machine(machine)  # an unknown machine is named once, not in every row
    rows = [operation_row(op, machine) for op in ops]
    total = dict(name=job.Name, label=job.Label, cam_s=cam_estimate_s(job), naive_s=None, simulated_s=None,
                 held_by="", error="")
    failed = [row["label"] for row in rows if row["error"]]
    if failed:
        total["error"] = "not simulated: %s cannot be (see %s)" % (", ".join(failed), "its row" if len(failed) == 1
                                                                   else "their rows")
        return rows, total
    try:
        summary = simulate_object(job, machine, blocks=False).summary
    except (ValueError, RuntimeError) as error:
        total["error"] = str(error)
        return rows, total
    total.update(naive_s=summary.naive_time, simulated_s=summary.total_time, held_by=held_by_text(summary))
    return rows, total


def clock(seconds):
    """'1:02:03' or '2:03' (minutes:seconds) for seconds, '' for None: how CAM shows cycle times."""
    if seconds is None:
        return ""
    whole = int(round(seconds))
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    return "%d:%02d:%02d" % (hours, minutes, secs) if hours else "%d:%02d" % (minutes, secs)
