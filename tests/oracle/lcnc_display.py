#!/usr/bin/python3
"""The DISPLAY program of the oracle's LinuxCNC configuration (docs/oracle.md): no GUI, it drives the machine
through the `linuxcnc` Python module and exits, which ends LinuxCNC.

linuxcnc starts it as `DISPLAY -ini INIFILE`. It reads its work from the INI's [ORACLE] section: PROGRAM (the
G-code file), SAMPLES (where halsampler writes the sampled servo cycles), STATUS (a JSON file it writes at the
end: ok, errors, messages, wall times) and RUN_TIMEOUT (seconds the program may run). Steps: start halsampler,
estop reset, machine on, home all joints (they home in place: HOME_SEARCH_VEL 0), auto mode, open the
program, enable the sampler, run, wait until the interpreter is idle, the queue empty and motion in position,
keep sampling 0.2 s more, disable the sampler, let halsampler drain the FIFO, stop it, machine off, exit.
"""
import json
import os
import signal
import subprocess
import sys
import time

import linuxcnc

ERROR_KINDS = {linuxcnc.NML_ERROR, linuxcnc.OPERATOR_ERROR}


class Failure(Exception):
    pass


def ini_value(inifile, section, key, default=None):
    value = linuxcnc.ini(inifile).find(section, key)
    return default if value is None else value


def halcmd(*args):
    done = subprocess.run(["halcmd", *args], capture_output=True, text=True, timeout=20)
    if done.returncode != 0:
        raise Failure(f"halcmd {' '.join(args)} failed: {done.stderr.strip() or done.stdout.strip()}")
    return done.stdout.strip()


def main():
    inifile = sys.argv[sys.argv.index("-ini") + 1] if "-ini" in sys.argv else sys.argv[-1]
    program = ini_value(inifile, "ORACLE", "PROGRAM")
    samples_path = ini_value(inifile, "ORACLE", "SAMPLES")
    status_path = ini_value(inifile, "ORACLE", "STATUS")
    run_timeout = float(ini_value(inifile, "ORACLE", "RUN_TIMEOUT", "600"))
    status = {"ok": False, "program": program, "errors": [], "messages": [], "steps": []}

    stat, command, errors = linuxcnc.stat(), linuxcnc.command(), linuxcnc.error_channel()

    def drain_errors():
        while True:
            message = errors.poll()
            if not message:
                return
            kind, text = message
            (status["errors"] if kind in ERROR_KINDS else status["messages"]).append(text)
            if kind in ERROR_KINDS:
                raise Failure(f"LinuxCNC error: {text}")

    def wait(what, condition, timeout=10.0):
        end = time.monotonic() + timeout
        while True:
            stat.poll()
            drain_errors()
            if condition():
                status["steps"].append(what)
                return
            if time.monotonic() > end:
                raise Failure(f"timed out after {timeout:g} s waiting for: {what}")
            time.sleep(0.005)

    sampler = None
    samples_file = open(samples_path, "w")
    try:
        sampler = subprocess.Popen(["halsampler", "-t"], stdout=samples_file, stderr=subprocess.PIPE, text=True)
        wait("task up", lambda: stat.task_state in (linuxcnc.STATE_ESTOP, linuxcnc.STATE_ESTOP_RESET,
                                                    linuxcnc.STATE_OFF, linuxcnc.STATE_ON), 20)
        command.state(linuxcnc.STATE_ESTOP_RESET)
        wait("estop reset", lambda: stat.task_state == linuxcnc.STATE_ESTOP_RESET)
        command.state(linuxcnc.STATE_ON)
        wait("machine on", lambda: stat.task_state == linuxcnc.STATE_ON)
        command.mode(linuxcnc.MODE_MANUAL)
        wait("manual mode", lambda: stat.task_mode == linuxcnc.MODE_MANUAL)
        command.home(-1)
        wait("homed", lambda: all(stat.homed[j] for j in range(stat.joints)))
        command.mode(linuxcnc.MODE_AUTO)
        wait("auto mode", lambda: stat.task_mode == linuxcnc.MODE_AUTO)
        stat.poll()
        status["start_position"] = list(stat.actual_position[:3])
        command.program_open(program)
        wait("program open", lambda: stat.file == program)
        halcmd("setp", "sampler.0.enable", "1")
        started = time.monotonic()
        command.auto(linuxcnc.AUTO_RUN, 0)
        wait("program running", lambda: stat.interp_state != linuxcnc.INTERP_IDLE or stat.current_vel > 0
             or list(stat.actual_position[:3]) != status["start_position"], 10)
        wait("program done", lambda: stat.interp_state == linuxcnc.INTERP_IDLE and stat.queue == 0
             and stat.inpos and stat.state == linuxcnc.RCS_DONE, run_timeout)
        status["wall_run_s"] = time.monotonic() - started
        status["end_position"] = list(stat.actual_position[:3])
        time.sleep(0.2)
        halcmd("setp", "sampler.0.enable", "0")
        end = time.monotonic() + 20
        while int(halcmd("getp", "sampler.0.curr-depth")) > 0:
            if time.monotonic() > end:
                raise Failure("halsampler did not drain the sampler FIFO within 20 s")
            time.sleep(0.05)
        time.sleep(0.2)
        status["sampler_overruns"] = int(halcmd("getp", "sampler.0.overruns"))
        status["servo_thread_tmax"] = int(halcmd("getp", "servo-thread.tmax"))
        drain_errors()
        status["ok"] = True
    except Failure as failure:
        status["failure"] = str(failure)
    except Exception as failure:  # anything else is a failure of the run too; say what it was
        status["failure"] = f"{type(failure).__name__}: {failure}"
    finally:
        if sampler is not None:
            sampler.send_signal(signal.SIGTERM)
            try:
                _, err = sampler.communicate(timeout=10)
                if err.strip():
                    status["messages"].append("halsampler: " + err.strip())
            except subprocess.TimeoutExpired:
                sampler.kill()
        samples_file.close()
        try:
            command.abort()
            command.state(linuxcnc.STATE_OFF)
            command.state(linuxcnc.STATE_ESTOP)
        except Exception:
            pass
        with open(status_path + ".tmp", "w") as f:
            json.dump(status, f, indent=1)
        os.replace(status_path + ".tmp", status_path)
    return 0 if status["ok"] else 1


if __name__ == "__main__":
    sys.exit(main())
