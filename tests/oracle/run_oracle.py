#!/usr/bin/python3
"""LinuxCNC 2.9 as an oracle for the feed-rate simulator (docs/oracle.md).

For each G-code program: runs LinuxCNC headless in simulation (a configuration written into a temporary
folder from the program's machine file by oracle_config.py: trivkins and 3 joints, or a table trunnion's
xyzac-trt-kins / xyzbc-trt-kins and 5 joints in TCP mode; 1 ms servo thread, joint commands looped back to
feedback, our DISPLAY program lcnc_display.py driving it through the `linuxcnc` Python module), measures
its motion time by counting servo cycles in HAL (the `sampler` component samples motion.current-vel and the
joint positions on the servo thread; halsampler writes them to a file), runs hsm-feedsim on the same program
with the same machine file, and prints and writes the table program, LinuxCNC s, ours s, error %.

    /usr/bin/python3 tests/oracle/run_oracle.py [PROGRAM ...] [--out build/oracle] [--max-error 2]

Without programs: tests/oracle/programs/*.ngc, tests/golden/linuxcnc_fixed.ngc and three real programs of the
shared corpus (../shared/data/realworld_gcode/linuxcnc: gcmc, a V-carve, OpenVoronoi) on machine.json,
programs_xyzac/*.ngc on machine_xyzac.json, programs_xyzbc/*.ngc on machine_xyzbc.json. Writes OUT/oracle.md,
OUT/oracle.csv and per program OUT/<name>/ (LinuxCNC's sampled trace and per-line speeds, hsm-feedsim's
summary, blocks and trace). Exit code: 0 (the table is a measurement), 2 if LinuxCNC failed on a program
(its log tail is printed), 3 if hsm-feedsim failed on one, 1 with --max-error when an |error| exceeds it.
Standard library only.
"""
import argparse
import collections
import csv
import fcntl
import json
import math
import os
import pwd
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import uuid

from oracle_config import Machine, write_config

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
# the default set: each folder of programs with the machine it runs on (3 axes on trivkins; the table trunnions
# on xyzac-trt-kins and xyzbc-trt-kins in TCP mode), and programs from elsewhere run on the 3-axis machine
SETS = [("programs", "machine.json"), ("programs_xyzac", "machine_xyzac.json"), ("programs_xyzbc", "machine_xyzbc.json")]
EXTRA_PROGRAMS = [os.path.join(REPO, "tests", "golden", "linuxcnc_fixed.ngc")]
# real programs of the shared corpus (other CAMs' output, read from ../shared, never copied here) whose run fits
# the 10-minute budget of one program: the others take 13 to 48 min in real time (docs/oracle.md)
CORPUS = os.path.join(os.path.dirname(REPO), "shared", "data", "realworld_gcode", "linuxcnc")
CORPUS_PROGRAMS = ["trochoidal_gcmc.ngc", "cereal_vcarve.ngc", "vcarve_openvoronoi.ngc"]
RUN_LOCK = "/tmp/hsm-oracle.lock"
MARGIN_S = 90.0  # LinuxCNC's start and shutdown, on top of the program's length bound
LINUXCNC_LOCK = "/tmp/linuxcnc.lock"
LINUXCNC_PROCESSES = ("rtapi_app", "milltask", "linuxcncsvr", "io", "halsampler", "linuxcnc", "lcnc_display.py")


class RunFailed(Exception):
    def __init__(self, message, log_tail=""):
        super().__init__(message)
        self.log_tail = log_tail


# ---------------------------------------------------------------------------------------------------------
# LinuxCNC installed, one run at a time, no other LinuxCNC running

def ensure_linuxcnc():
    status = subprocess.run(["dpkg-query", "-W", "-f=${db:Status-Status}", "linuxcnc-uspace"],
                            capture_output=True, text=True).stdout
    if status == "installed" and shutil.which("linuxcnc") and shutil.which("halsampler"):
        return
    print("Installing linuxcnc-uspace (Debian package) for the LinuxCNC oracle", flush=True)
    if os.geteuid() == 0:
        as_root = []
    elif shutil.which("sudo"):
        as_root = ["sudo"]
    else:
        sys.exit("error: linuxcnc-uspace is missing and this user is not root and has no sudo: install it as root "
                 "(apt-get install linuxcnc-uspace)")
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(as_root + ["apt-get", "update", "-qq"], check=True, env=env)
    subprocess.run(as_root + ["apt-get", "install", "-y", "-qq", "--no-install-recommends", "linuxcnc-uspace"],
                   check=True, env=env)


def processes():
    """(pid, name, environ or None) of every live process we can see (zombies left out: they are dead)."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                stat = f.read()
            name = stat[stat.index("(") + 1:stat.rindex(")")]
            if stat[stat.rindex(")") + 2:].startswith(("Z", "X")):
                continue
        except (OSError, ValueError):
            continue
        try:
            with open(f"/proc/{entry}/environ", "rb") as f:
                environ = f.read()
        except OSError:
            environ = None
        found.append((int(entry), name, environ))
    return found


def foreign_linuxcnc(wait=15.0):
    """Names and pids of LinuxCNC processes still running after up to `wait` seconds (a LinuxCNC that is
    shutting down gets that long to finish)."""
    names = {"rtapi_app", "milltask", "linuxcncsvr"}
    end = time.monotonic() + wait
    while True:
        running = [f"{name} ({pid})" for pid, name, _ in processes() if name in names]
        if not running or time.monotonic() > end:
            return running
        time.sleep(0.5)


def kill_marked(marker):
    """Ends, by pid, the processes whose environment carries this run's marker; returns their names."""
    token = f"HSM_ORACLE_RUN={marker}".encode()
    killed = []
    for sig in (signal.SIGTERM, signal.SIGKILL):
        victims = [(pid, name) for pid, name, env in processes()
                   if env is not None and token in env.split(b"\0") and pid != os.getpid()]
        for pid, name in victims:
            try:
                os.kill(pid, sig)
                if sig == signal.SIGTERM:
                    killed.append(f"{name} ({pid})")
            except OSError:
                pass
        if not victims:
            break
        time.sleep(1.0)
    return killed


def fallback_uid():
    """rtapi_app refuses to run as root unless RTAPI_UID names the user it drops to."""
    if os.geteuid() != 0:
        return None
    sudo_uid = os.environ.get("SUDO_UID", "")
    if sudo_uid.isdigit() and int(sudo_uid) != 0:
        return int(sudo_uid)
    return pwd.getpwnam("nobody").pw_uid


# ---------------------------------------------------------------------------------------------------------
# A bound on the program's length: the timeout

WORD = re.compile(r"([A-Za-z])\s*([-+]?\d*\.?\d+)")


def program_units(path):
    """"inch" when the program's first G20/G21 is a G20 (the interpreter then starts in G20, as on the inch machine
    the program was written for: see oracle_config.ini_lines), "mm" otherwise."""
    with open(path, errors="replace") as f:
        for raw in f:
            text = re.sub(r"\(.*?\)", "", raw.split(";")[0])
            for letter, number in WORD.findall(text):
                if letter.upper() == "G" and float(number) in (20, 21):
                    return "inch" if float(number) == 20 else "mm"
    return "mm"


def naive_time(path, start_units="mm"):
    """Σ length / F + dwells over the program (arcs counted as full circles, rapids at 1000 mm/min): a generous
    upper bound of the motion time of any sane program, for the timeout only. Lengths and F in mm from the
    G20/G21 in effect, starting in start_units; an F is read in the units in force before its line's G20/G21,
    as LinuxCNC does (so `G20 F6` on a control that starts in mm is 6 mm/min)."""
    scale = 25.4 if start_units == "inch" else 1.0
    pos, angles, feed, feed_deg, motion, total = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], 1000.0, 1000.0, 0, 0.0
    with open(path, errors="replace") as f:
        for raw in f:
            text = re.sub(r"\(.*?\)", "", raw.split(";")[0])
            words = WORD.findall(text)
            values, dwell, line_scale = {}, False, scale
            for letter, number in words:
                letter = letter.upper()
                if letter == "G":
                    g = float(number)
                    if g in (0, 1, 2, 3):
                        motion = int(g)
                    dwell = dwell or g == 4
                    if g in (20, 21):
                        line_scale = 25.4 if g == 20 else 1.0
                elif letter in "XYZABCFRIJKP":
                    values[letter] = float(number)
            if "F" in values and values["F"] > 0:
                feed = values["F"] * scale  # mm/min (deg/min on the rotary axes alone: not scaled)
                feed_deg = values["F"]
            scale = line_scale
            for letter in "XYZRIJK":
                if letter in values:
                    values[letter] *= scale
            if dwell:
                total += abs(values.get("P", 0.0))
                continue
            target = [values.get(a, p) for a, p in zip("XYZ", pos)]
            turned = [values.get(a, p) for a, p in zip("ABC", angles)]
            if target == pos and turned != angles:  # the rotary axes alone: F in deg/min
                total += math.dist(turned, angles) / (1000.0 if motion == 0 else feed_deg) * 60.0
            angles = turned
            if target != pos:
                length = math.dist(target, pos)
                if motion in (2, 3):
                    radius = values.get("R", math.hypot(values.get("I", 0.0), values.get("J", 0.0)))
                    length = max(length, 2 * math.pi * abs(radius))
                total += length / (1000.0 if motion == 0 else feed) * 60.0
                pos = target
            elif motion in (2, 3) and ("I" in values or "J" in values):
                total += 2 * math.pi * math.hypot(values.get("I", 0.0), values.get("J", 0.0)) / feed * 60.0
    return total


# ---------------------------------------------------------------------------------------------------------
# Running LinuxCNC

def tail(path, lines=40):
    try:
        with open(path, errors="replace") as f:
            return "".join(f.readlines()[-lines:])
    except OSError:
        return ""


def run_linuxcnc(program, machine):
    """Runs the program in LinuxCNC; returns (samples path, status dict, folder, log text). Raises RunFailed
    (with the log's tail) when LinuxCNC fails, after ending whatever of it is left."""
    units = program_units(program)
    limit = 30.0 + 10.0 * naive_time(program, units)
    folder = tempfile.mkdtemp(prefix="hsm-oracle-")
    uid = fallback_uid()
    ini = write_config(machine, folder, program, limit, uid, units)
    marker = uuid.uuid4().hex
    env = {
        "PATH": "/usr/bin:/bin:/usr/sbin:/sbin", "HOME": folder, "LANG": "C.UTF-8",
        "RTAPI_FIFO_PATH": os.path.join(folder, "rtapi", "fifo"), "HSM_ORACLE_RUN": marker,
    }
    if uid is not None:
        env["RTAPI_UID"] = str(uid)
    log_path = os.path.join(folder, "linuxcnc.log")
    failure = None
    with open(log_path, "w") as log:
        process = subprocess.Popen(["linuxcnc", "-r", ini], cwd=folder, env=env, stdin=subprocess.DEVNULL,
                                   stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            code = process.wait(timeout=limit + MARGIN_S)
            if code != 0:
                failure = f"linuxcnc exited with code {code}"
        except subprocess.TimeoutExpired:
            failure = (f"timed out after {limit + MARGIN_S:.0f} s (program length bound {limit:.0f} s + "
                       f"{MARGIN_S:.0f} s for start and shutdown)")
            for sig in (signal.SIGTERM, signal.SIGKILL):
                try:
                    os.killpg(process.pid, sig)
                except OSError:
                    pass
                try:
                    process.wait(timeout=10)
                    break
                except subprocess.TimeoutExpired:
                    continue
    status = {}
    status_path = os.path.join(folder, "status.json")
    if os.path.exists(status_path):
        with open(status_path) as f:
            status = json.load(f)
        if not status.get("ok") and failure is None:
            failure = status.get("failure", "the DISPLAY program failed")
        elif not status.get("ok"):
            failure += "; " + status.get("failure", "")
    elif failure is None:
        failure = "the DISPLAY program wrote no status"
    if failure is not None:
        # LinuxCNC's own teardown of the realtime side (rtapi_app), then whatever still carries our marker
        teardown = subprocess.Popen(["halrun", "-U"], env=env, cwd=folder, stdin=subprocess.DEVNULL,
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        try:
            teardown.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(teardown.pid, signal.SIGKILL)
            teardown.wait()
    leftovers = kill_marked(marker)
    with open(log_path, errors="replace") as f:
        log_text = f.read()
    if failure is not None:
        display_log = json.dumps({k: status.get(k) for k in ("steps", "errors", "messages")}) if status else ""
        message = failure + (f"; killed leftover processes: {', '.join(leftovers)}" if leftovers else "")
        message += f"; configuration kept in {folder}"
        raise RunFailed(message, tail(log_path) + ("\nDISPLAY program: " + display_log if display_log else ""))
    if leftovers:
        status.setdefault("messages", []).append("killed leftover processes: " + ", ".join(leftovers))
    status["realtime_delay_reported"] = "Unexpected realtime delay" in log_text
    status["start_units"] = units
    return os.path.join(folder, "samples.txt"), status, folder, log_text


# ---------------------------------------------------------------------------------------------------------
# Reading the samples

# one servo cycle: the planner's path speed (mm/s, or deg/s on a move of the rotary axes alone), the joints'
# position commands (mm, deg), the program line, in-position, the motion type and the cycle's real period
Sample = collections.namedtuple("Sample", "v joints line inpos mtype period")


def read_samples(path):
    rows, overrun_lines, gaps, previous = [], 0, 0, None
    with open(path) as f:
        for line in f:
            fields = line.split()
            if not fields:
                continue
            if fields[0] == "overrun":
                overrun_lines += 1
                continue
            tag = int(fields[0])
            if previous is not None and tag != previous + 1:
                gaps += 1
            previous = tag
            joints = len(fields) - 6
            rows.append(Sample(float(fields[1]), tuple(float(x) for x in fields[2:2 + joints]), int(fields[-4]),
                               int(fields[-3]), int(fields[-2]), int(fields[-1])))
    return rows, overrun_lines, gaps


def analyse(rows, period):
    """Motion time and what the sampled servo cycles show (speeds in mm/s, accelerations in mm/s²)."""
    vel = [r.v for r in rows]
    moving = [i for i, v in enumerate(vel) if v > 0.0]
    if not moving:
        raise RunFailed("LinuxCNC did not move (motion.current-vel stayed 0)")
    first, last = moving[0], moving[-1]
    span = last - first + 1
    result = {
        "cycles": span, "time_s": span * period, "moving_cycles": len(moving), "stop_cycles": span - len(moving),
        "length_mm": sum(vel) * period, "peak_mm_s": max(vel),
    }
    result["mean_mm_s"] = result["length_mm"] / result["time_s"]
    # tangential acceleration from motion.current-vel; the most frequent values show the planner's limits
    histogram = {}
    max_acc = 0.0
    for i in range(first, last + 2):
        a = (vel[i] - vel[i - 1]) / period if i < len(vel) else 0.0
        max_acc = max(max_acc, abs(a))
        if abs(a) > 1e-6:
            key = round(a / 50.0) * 50.0
            histogram[key] = histogram.get(key, 0) + 1
    result["tangential_acc_max_mm_s2"] = max_acc
    result["tangential_acc_modes"] = sorted(histogram.items(), key=lambda kv: -kv[1])[:4]
    # axis speeds and accelerations from the joint position commands (after the cubic interpolator)
    lo, hi = max(first - 5, 1), min(last + 10, len(rows) - 1)
    for axis in range(3):
        p = [r.joints[axis] for r in rows]
        vmax = max(abs(p[i] - p[i - 1]) for i in range(lo, hi + 1)) / period
        amax = max(abs(p[i + 1] - 2 * p[i] + p[i - 1]) for i in range(lo, hi)) / period ** 2
        result["axis_vel_max_mm_s_" + "xyz"[axis]] = vmax
        result["axis_acc_max_mm_s2_" + "xyz"[axis]] = amax
    # the servo thread's real periods (motion.servo.last-period, in CPU clock ticks; the median is taken as
    # the nominal period): late cycles (> 1.5 periods) and the catch-up cycles that follow them (< 0.5)
    periods = sorted(r.period for r in rows[first:last + 1])
    median = periods[len(periods) // 2] if periods else 0
    result["late_cycles"] = sum(1 for q in periods if median and q > 1.5 * median)
    result["catch_up_cycles"] = sum(1 for q in periods if median and q < 0.5 * median)
    result["longest_period_ms"] = periods[-1] / median * period * 1000 if median else None
    # per program line (motion.program-line)
    lines, order = {}, []
    for i in range(first, last + 1):
        line = rows[i].line
        if line not in lines:
            lines[line] = []
            order.append(line)
        lines[line].append(vel[i])
    result["per_line"] = [(line, len(lines[line]), lines[line][0], lines[line][-1], min(lines[line]),
                           sum(lines[line]) / len(lines[line]), max(lines[line])) for line in order]
    return result, first, last


def write_trace(path, rows, first, last, period, axes):
    """Every servo cycle: t, the joints' positions (X Y Z in mm, rotary in deg), feed, line, in-position, type."""
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["t_s"] + [f"{a.lower()}_{'mm' if a in 'XYZ' else 'deg'}" for a in axes]
                     + ["feed_mm_min", "line", "in_position", "motion_type"])
        for i in range(max(first - 1, 0), min(last + 20, len(rows))):
            r = rows[i]
            out.writerow([f"{(i - first + 1) * period:.4f}"] + [f"{q:.6f}" for q in r.joints]
                         + [f"{r.v * 60:.1f}", r.line, r.inpos, r.mtype])


def write_per_line(path, per_line, period):
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["line", "cycles", "time_s", "entry_feed_mm_min", "exit_feed_mm_min", "min_feed_mm_min",
                      "mean_feed_mm_min", "peak_feed_mm_min"])
        for line, cycles, entry, exit_, vmin, vmean, vmax in per_line:
            out.writerow([line, cycles, f"{cycles * period:.4f}", f"{entry * 60:.1f}", f"{exit_ * 60:.1f}",
                          f"{vmin * 60:.1f}", f"{vmean * 60:.1f}", f"{vmax * 60:.1f}"])


# ---------------------------------------------------------------------------------------------------------
# hsm-feedsim

def inch_start_copy(machine_file):
    """The machine file with G20 added to its power-on codes (hsm-feedsim's start in inches), beside it."""
    with open(machine_file) as f:
        data = json.load(f)
    data["power_on_codes"] = (data.get("power_on_codes", "") + " G20").strip()
    copy = os.path.splitext(machine_file)[0] + "_g20.json"
    with open(copy, "w") as f:
        json.dump(data, f, indent=1)
    return copy


def run_feedsim(feedsim, program, machine_file, folder):
    """Our simulated time; waits up to 5 min for the binary if it is being rebuilt."""
    end = time.monotonic() + 300
    while not os.access(feedsim, os.X_OK):
        if time.monotonic() > end:
            raise RunFailed(f"{feedsim} is missing (build it with make build)")
        time.sleep(5)
    summary = os.path.join(folder, "feedsim.json")
    command = [feedsim, program, "--machine", machine_file, "--json", summary, "--csv",
               os.path.join(folder, "feedsim_blocks.csv"), "--trace", os.path.join(folder, "feedsim_trace.csv"),
               "--trace-period", "0.001", "--quiet"]
    for attempt in range(3):
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=600)
        except OSError as error:  # the binary replaced under us by a rebuild: retry
            done = None
            message = str(error)
        if done is not None and done.returncode == 0:
            with open(summary) as f:
                return json.load(f)
        if done is not None:
            message = (done.stderr or done.stdout).strip()
        time.sleep(5)
    raise RunFailed(f"hsm-feedsim failed: {message}")


# ---------------------------------------------------------------------------------------------------------
# The table

def fmt(value, digits=3):
    return "—" if value is None else f"{value:.{digits}f}"


def by_machine(results):
    """(machine file, its results) in the order the machines first appear."""
    groups = {}
    for r in results:
        groups.setdefault(r["machine"], []).append(r)
    return list(groups.items())


def markdown_table(results):
    lines = ["| program | LinuxCNC s | ours s | error % |", "|---|---:|---:|---:|"]
    for r in results:
        error = "—" if r["error_pct"] is None else f"{r['error_pct']:+.1f}"
        lines.append(f"| {r['program']} | {fmt(r['linuxcnc_s'])} | {fmt(r['ours_s'])} | {error} |")
    return "\n".join(lines)


def markdown_details(results):
    lines = ["| program | programmed mm | path mm | stop cycles | peak mm/min | mean mm/min "
             "| most frequent dv/dt m/s² (cycles) | max axis acc X/Y/Z m/s² | late servo cycles (longest ms) |",
             "|---|---:|---:|---:|---:|---:|---|---|---:|"]
    for r in results:
        d = r.get("detail")
        programmed = fmt(r.get("programmed_mm"), 1)
        if not d:
            lines.append(f"| {r['program']} | {programmed} | | | | | | | |")
            continue
        modes = ", ".join(f"{a / 1000:+.2f} ({n})" for a, n in d["tangential_acc_modes"][:3])
        acc = "/".join(f"{d['axis_acc_max_mm_s2_' + c] / 1000:.2f}" for c in "xyz")
        lines.append(f"| {r['program']} | {programmed} | {d['length_mm']:.1f} | {d['stop_cycles']} | "
                     f"{d['peak_mm_s'] * 60:.0f} | {d['mean_mm_s'] * 60:.0f} | {modes} | {acc} | "
                     f"{d['late_cycles']} ({d['longest_period_ms']:.1f}) |")
    return "\n".join(lines)


def default_programs():
    found = []
    for folder, _ in SETS:
        path = os.path.join(HERE, folder)
        if os.path.isdir(path):
            found += sorted(os.path.join(path, name) for name in os.listdir(path) if name.endswith(".ngc"))
        if folder == "programs":
            found += [p for p in EXTRA_PROGRAMS if os.path.exists(p)]
            found += [p for p in (os.path.join(CORPUS, name) for name in CORPUS_PROGRAMS) if os.path.exists(p)]
    return found


def machine_of(program):
    """The machine file of the set whose folder holds the program; the 3-axis machine for any other."""
    folder = os.path.dirname(os.path.abspath(program))
    for name, machine in SETS:
        if folder == os.path.join(HERE, name):
            return os.path.join(HERE, machine)
    return os.path.join(HERE, SETS[0][1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("programs", nargs="*", help="G-code files (default: tests/oracle/programs*/*.ngc and "
                        "tests/golden/linuxcnc_fixed.ngc)")
    parser.add_argument("--out", default=os.path.join(REPO, "build", "oracle"), help="output folder")
    parser.add_argument("--machine", default=None, help="machine JSON (linuxcnc) for every program (default: the "
                        "machine of the program's folder, tests/oracle/machine*.json)")
    parser.add_argument("--feedsim", default=os.path.join(REPO, "build", "bin", "hsm-feedsim"))
    parser.add_argument("--max-error", type=float, default=None,
                        help="exit 1 when a program's |error| exceeds this many percent")
    parser.add_argument("--keep", action="store_true", help="keep the temporary LinuxCNC configurations")
    args = parser.parse_args()

    programs = [os.path.abspath(p) for p in args.programs] or default_programs()
    for program in programs:
        if not os.path.isfile(program):
            sys.exit(f"error: no such program: {program}")
    os.makedirs(args.out, exist_ok=True)
    machines = {}  # machine file -> (Machine, its copy in --out that hsm-feedsim reads)
    for program in programs:
        path = args.machine or machine_of(program)
        if path not in machines:
            copy = os.path.join(os.path.abspath(args.out), os.path.basename(path))
            shutil.copyfile(path, copy)
            machines[path] = (Machine(path), copy)
    ensure_linuxcnc()

    lock = open(RUN_LOCK, "a")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        sys.exit(f"error: another oracle run holds {RUN_LOCK}; runs must not overlap")
    running = foreign_linuxcnc()
    if running:
        sys.exit("error: LinuxCNC is already running (" + ", ".join(running) + "); stop it first")

    started = time.monotonic()
    results, linuxcnc_failed, feedsim_failed = [], [], []
    for program in programs:
        machine, machine_file = machines[args.machine or machine_of(program)]
        period = machine.period
        name = os.path.splitext(os.path.basename(program))[0]
        folder = os.path.join(args.out, name)
        os.makedirs(folder, exist_ok=True)
        print(f"{name}: ", end="", flush=True)
        result = {"program": name, "path": program, "linuxcnc_s": None, "ours_s": None, "error_pct": None,
                  "programmed_mm": None, "machine": os.path.basename(machine.path)}
        results.append(result)
        t0 = time.monotonic()
        try:
            running = foreign_linuxcnc()
            if running:
                raise RunFailed("LinuxCNC processes of the previous run are still running: " + ", ".join(running))
            samples, status, tmp, _ = run_linuxcnc(program, machine)
            rows, overrun_lines, gaps = read_samples(samples)
            if overrun_lines or gaps or status.get("sampler_overruns"):
                raise RunFailed(f"the sampler lost samples ({overrun_lines} overrun marks, {gaps} gaps, "
                                f"{status.get('sampler_overruns')} overruns): the measurement is incomplete; samples kept in {tmp}")
            detail, first, last = analyse(rows, period)
            end = status.get("end_position")
            detail["end_position"] = end
            detail["wall_run_s"] = status.get("wall_run_s")
            detail["realtime_delay_reported"] = status.get("realtime_delay_reported")
            detail["messages"] = status.get("messages", [])
            detail["start_units"] = status.get("start_units")
            write_trace(os.path.join(folder, "linuxcnc_trace.csv"), rows, first, last, period, machine.axes)
            write_per_line(os.path.join(folder, "linuxcnc_lines.csv"), detail["per_line"], period)
            with open(os.path.join(folder, "linuxcnc.json"), "w") as f:
                json.dump({k: v for k, v in detail.items() if k != "per_line"}, f, indent=1)
            result["linuxcnc_s"] = detail["time_s"]
            result["detail"] = detail
            if not args.keep:
                shutil.rmtree(tmp, ignore_errors=True)
        except RunFailed as failure:
            linuxcnc_failed.append(name)
            print(f"LinuxCNC FAILED: {failure}", flush=True)
            if failure.log_tail:
                print("---- LinuxCNC log tail ----\n" + failure.log_tail.rstrip() + "\n---------------------------",
                      flush=True)
        try:
            if program_units(program) == "inch":  # hsm-feedsim starts in G20 too, as LinuxCNC's interpreter does
                machine_file = inch_start_copy(machine_file)
            summary = run_feedsim(args.feedsim, program, machine_file, folder)
            result["ours_s"] = summary["total_time_s"]
            result["programmed_mm"] = summary["cutting_length_mm"] + summary["rapid_length_mm"]
        except RunFailed as failure:
            feedsim_failed.append(name)
            print(f"hsm-feedsim FAILED: {failure}", flush=True)
        if result["linuxcnc_s"] and result["ours_s"] is not None:
            result["error_pct"] = (result["ours_s"] - result["linuxcnc_s"]) / result["linuxcnc_s"] * 100.0
        print(f"LinuxCNC {fmt(result['linuxcnc_s'])} s, ours {fmt(result['ours_s'])} s "
              f"({time.monotonic() - t0:.1f} s wall)", flush=True)

    wall = time.monotonic() - started
    table = "\n\n".join(f"{name}:\n\n{markdown_table(group)}" for name, group in by_machine(results))
    details = "\n\n".join(f"{name}:\n\n{markdown_details(group)}" for name, group in by_machine(results))
    built = (time.strftime("%Y-%m-%d %H:%M", time.localtime(os.path.getmtime(args.feedsim)))
             if os.path.exists(args.feedsim) else "missing")
    version = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "linuxcnc-uspace"], capture_output=True,
                             text=True).stdout.strip()
    header = (f"LinuxCNC oracle: {len(results)} programs on {', '.join(m.kinematics for m, _ in machines.values())} "
              f"(LinuxCNC {version or 'unknown'}), {wall:.0f} s wall time; hsm-feedsim built {built}")
    with open(os.path.join(args.out, "oracle.md"), "w") as f:
        f.write(f"{header}\n\n{table}\n\nWhat LinuxCNC did (from the sampled servo cycles):\n\n{details}\n")
    with open(os.path.join(args.out, "oracle.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["program", "machine", "linuxcnc_s", "ours_s", "error_pct", "linuxcnc_cycles", "stop_cycles",
                      "programmed_mm", "path_mm", "peak_mm_min", "mean_mm_min", "late_servo_cycles",
                      "longest_servo_period_ms"])
        for r in results:
            d = r.get("detail") or {}
            out.writerow([r["program"], r["machine"], fmt(r["linuxcnc_s"]), fmt(r["ours_s"]),
                          "" if r["error_pct"] is None else f"{r['error_pct']:.2f}", d.get("cycles", ""),
                          d.get("stop_cycles", ""), fmt(r.get("programmed_mm")),
                          f"{d['length_mm']:.3f}" if d else "",
                          f"{d['peak_mm_s'] * 60:.1f}" if d else "", f"{d['mean_mm_s'] * 60:.1f}" if d else "",
                          d.get("late_cycles", ""), f"{d['longest_period_ms']:.2f}" if d else ""])
    print(f"\n{header}\n\n{table}\n\n{details}\n")
    print(f"written: {os.path.join(args.out, 'oracle.md')}, {os.path.join(args.out, 'oracle.csv')}")

    if linuxcnc_failed:
        print(f"LinuxCNC failed on: {', '.join(linuxcnc_failed)}", file=sys.stderr)
        return 2
    if feedsim_failed:
        print(f"hsm-feedsim failed on: {', '.join(feedsim_failed)}", file=sys.stderr)
        return 3
    if args.max_error is not None:
        over = [r["program"] for r in results if r["error_pct"] is not None and abs(r["error_pct"]) > args.max_error]
        if over:
            print(f"|error| above {args.max_error:g} % on: {', '.join(over)}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
