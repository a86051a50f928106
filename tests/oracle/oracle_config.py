"""The LinuxCNC configuration of the oracle (docs/oracle.md), written from a machine JSON file.

A 3-axis machine runs on trivkins; a machine with a table A/C or B/C trunnion on LinuxCNC's xyzac-trt-kins or
xyzbc-trt-kins (switchkins type 0, the kinematics itself; its y/z or x/z offsets and rot-point from the rotary
axes' pivots), in TCP mode: the program gives the tool tip and A/B/C, as our simulator reads it. Standard
library only.
"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
LINEAR = "XYZ"
# the table trunnions LinuxCNC 2.9 ships: (tilting axis and its direction, C's direction), kinematics module
TRUNNIONS = {("A", (1, 0, 0)): "xyzac-trt-kins", ("B", (0, 1, 0)): "xyzbc-trt-kins"}
C_DIRECTION = (0, 0, 1)
# travel of a continuous C: LinuxCNC needs soft limits; these are never reached by the oracle's programs
CONTINUOUS_DEG = 36000.0
LINEAR_LIMIT_MM = 10000.0


class Machine:
    """What the configuration needs from the machine file: per axis (velocity, acceleration, min, max) in mm or
    deg and s; the servo period; the kinematics module and its HAL parameters."""

    def __init__(self, path):
        self.path = path
        with open(path) as f:
            self.data = json.load(f)
        if self.data.get("controller") != "linuxcnc":
            fail(path, "controller must be 'linuxcnc' for the LinuxCNC oracle")
        self.axes = {}
        for name in LINEAR:
            axis = self.data["axes"][name]
            if axis["rapid_velocity_mm_min"] != axis["max_velocity_mm_min"]:
                fail(path, f"axes.{name}: LinuxCNC rapids at MAX_VELOCITY, so rapid_velocity_mm_min must equal "
                     "max_velocity_mm_min")
            self.axes[name] = (axis["max_velocity_mm_min"] / 60.0, axis["max_acceleration_m_s2"] * 1000.0,
                               -LINEAR_LIMIT_MM, LINEAR_LIMIT_MM)
        period_ms = self.data["interpolation_cycle_ms"]
        if not period_ms > 0:
            fail(path, "interpolation_cycle_ms must be > 0 (it is LinuxCNC's servo period)")
        self.period = period_ms / 1000.0
        self.depth = self.data["look_ahead_blocks"]
        self.kinematics, self.kins_pins = "trivkins", {}
        rotary = self.data.get("rotary_axes") or []
        if rotary:
            self._trunnion(rotary)

    def _trunnion(self, rotary):
        names = [axis["name"] for axis in rotary]
        directions = [tuple(axis["direction"]) for axis in rotary]
        if len(rotary) != 2 or names[1] != "C" or directions[1] != C_DIRECTION or \
                (names[0], directions[0]) not in TRUNNIONS or any(a.get("carrier") != "table" for a in rotary):
            fail(self.path, "the oracle runs LinuxCNC's table trunnions only: rotary_axes A about +X (or B about +Y) "
                 "then C about +Z, both on the table (xyzac-trt-kins, xyzbc-trt-kins)")
        self.kinematics = TRUNNIONS[(names[0], directions[0])]
        tilt_pivot, c_pivot = rotary[0]["pivot_mm"], rotary[1]["pivot_mm"]
        # C turns about its rot-point; the tilting axis passes through it shifted by the offsets across its own
        # direction (xyzac: y and z; xyzbc: x and z)
        self.kins_pins = {"x-rot-point": c_pivot[0], "y-rot-point": c_pivot[1], "z-rot-point": c_pivot[2]}
        for letter in ("yz" if names[0] == "A" else "xz"):
            k = "xyz".index(letter)
            self.kins_pins[f"{letter}-offset"] = tilt_pivot[k] - c_pivot[k]
        for axis in rotary:
            low, high = ((-CONTINUOUS_DEG, CONTINUOUS_DEG) if axis.get("continuous")
                         else (axis["min_deg"], axis["max_deg"]))
            if axis["rapid_velocity_deg_min"] != axis["max_velocity_deg_min"]:
                fail(self.path, f"rotary axis {axis['name']}: LinuxCNC rapids at MAX_VELOCITY, so "
                     "rapid_velocity_deg_min must equal max_velocity_deg_min")
            self.axes[axis["name"]] = (axis["max_velocity_deg_min"] / 60.0, axis["max_acceleration_deg_s2"], low, high)

    @property
    def joints(self):
        return len(self.axes)

    @property
    def coordinates(self):
        return "".join(self.axes)


def fail(path, message):
    sys.exit(f"error: {path}: {message}")


def sampler_cfg(joints):
    """sampler columns: motion.current-vel, each joint's motor-pos-cmd, motion.program-line, motion.in-position,
    motion.motion-type, motion.servo.last-period."""
    return "f" + "f" * joints + "sbsu"


def ini_lines(machine, folder, program, run_timeout, start_units="mm"):
    linear = [machine.axes[n] for n in LINEAR]
    vmax = math.sqrt(sum(v * v for v, *_ in linear))
    amax = math.sqrt(sum(a * a for _, a, *_ in linear))
    ini = [
        "# Written by tests/oracle/run_oracle.py: a headless LinuxCNC 2.9 simulation for the oracle (docs/oracle.md)",
        "[EMC]", "VERSION = 1.1", "MACHINE = hsm-oracle", "DEBUG = 0",
        "[DISPLAY]", f"DISPLAY = {folder}/display", "CYCLE_TIME = 0.100",
        "# the planner sizes blend arcs for F x MAX_FEED_OVERRIDE: 1.0, so that it plans for F itself",
        "MAX_FEED_OVERRIDE = 1.0",
        "[ORACLE]", f"PROGRAM = {program}", f"SAMPLES = {folder}/samples.txt", f"STATUS = {folder}/status.json",
        f"RUN_TIMEOUT = {run_timeout:.0f}", f"JOINTS = {machine.joints}",
        "[TASK]", "TASK = milltask", "CYCLE_TIME = 0.001",
        "[RS274NGC]", f"PARAMETER_FILE = {folder}/oracle.var",
    ]
    if start_units == "inch":
        # an inch program starts in G20, as on the inch machine it was written for: LinuxCNC reads the F of the
        # line that holds the G20 before the G20 (order of execution), in the units the interpreter starts in
        ini += ["RS274NGC_STARTUP_CODE = G20"]
    ini += [
        "[EMCMOT]", "EMCMOT = motmod", "COMM_TIMEOUT = 1.0", "BASE_PERIOD = 0",
        f"SERVO_PERIOD = {round(machine.period * 1e9)}",
        "[EMCIO]", "EMCIO = io", "CYCLE_TIME = 0.100", f"TOOL_TABLE = {folder}/tool.tbl",
        "[HAL]", f"HALFILE = {folder}/oracle.hal",
        "[TRAJ]", f"COORDINATES = {' '.join(machine.axes)}", "LINEAR_UNITS = mm", "ANGULAR_UNITS = degree",
        "# the vector limits are the norms of the axis limits: they never bind, the axis limits do",
        f"DEFAULT_LINEAR_VELOCITY = {linear[0][0]:.6g}", f"MAX_LINEAR_VELOCITY = {vmax:.6g}",
        f"DEFAULT_LINEAR_ACCELERATION = {amax:.6g}", f"MAX_LINEAR_ACCELERATION = {amax:.6g}",
        "# LinuxCNC 2.9's defaults, written out; the optimization depth is the machine file's look-ahead",
        "ARC_BLEND_ENABLE = 1", "ARC_BLEND_FALLBACK_ENABLE = 0",
        f"ARC_BLEND_OPTIMIZATION_DEPTH = {machine.depth}", "ARC_BLEND_GAP_CYCLES = 4", "ARC_BLEND_RAMP_FREQ = 100",
        "ARC_BLEND_KINK_RATIO = 0.1",
        "[KINS]", f"KINEMATICS = {machine.kinematics}", f"JOINTS = {machine.joints}",
    ]
    for name, (v, a, low, high) in machine.axes.items():
        ini += [f"[AXIS_{name}]", f"MAX_VELOCITY = {v:.6g}", f"MAX_ACCELERATION = {a:.6g}",
                f"MIN_LIMIT = {low:g}", f"MAX_LIMIT = {high:g}"]
    for joint, (name, (v, a, low, high)) in enumerate(machine.axes.items()):
        ini += [f"[JOINT_{joint}]", f"TYPE = {'LINEAR' if name in LINEAR else 'ANGULAR'}", "HOME = 0",
                f"MAX_VELOCITY = {v:.6g}", f"MAX_ACCELERATION = {a:.6g}", f"MIN_LIMIT = {low:g}",
                f"MAX_LIMIT = {high:g}", "FERROR = 1000", "MIN_FERROR = 1000",
                "# homes in place at once: no search, no latch, no index",
                "HOME_OFFSET = 0", "HOME_SEARCH_VEL = 0", "HOME_LATCH_VEL = 0", "HOME_USE_INDEX = NO",
                "HOME_SEQUENCE = 0"]
    return ini


def hal_lines(machine):
    joints = machine.joints
    hal = [
        "# Written by tests/oracle/run_oracle.py (docs/oracle.md)",
        f"loadrt {machine.kinematics}",
        "loadrt [EMCMOT]EMCMOT base_period_nsec=[EMCMOT]BASE_PERIOD servo_period_nsec=[EMCMOT]SERVO_PERIOD "
        "num_joints=[KINS]JOINTS",
        f"loadrt sampler depth=16384 cfg={sampler_cfg(joints)}",
        "addf motion-command-handler servo-thread",
        "addf motion-controller servo-thread",
        "addf sampler.0 servo-thread",
        "# sampling starts when the DISPLAY program runs the G-code and stops after it",
        "setp sampler.0.enable 0",
        "# position commands loop back to feedback, as in the sim configurations",
        "net current-vel motion.current-vel => sampler.0.pin.0",
    ]
    for joint in range(joints):
        hal.append(f"net j{joint}-pos joint.{joint}.motor-pos-cmd => joint.{joint}.motor-pos-fb "
                   f"sampler.0.pin.{joint + 1}")
    hal += [
        f"net program-line motion.program-line => sampler.0.pin.{joints + 1}",
        f"net in-position motion.in-position => sampler.0.pin.{joints + 2}",
        f"net motion-type motion.motion-type => sampler.0.pin.{joints + 3}",
        f"net servo-period motion.servo.last-period => sampler.0.pin.{joints + 4}",
        "net estop-loop iocontrol.0.user-enable-out iocontrol.0.emc-enable-in",
        "net tool-prep-loop iocontrol.0.tool-prepare iocontrol.0.tool-prepared",
        "net tool-change-loop iocontrol.0.tool-change iocontrol.0.tool-changed",
    ]
    if machine.kinematics != "trivkins":
        hal.append("# switchkins type 0 (motion.switchkins-type left at 0) is the trunnion kinematics: TCP")
        hal += [f"setp {machine.kinematics}.{pin} {value:.9g}" for pin, value in machine.kins_pins.items()]
        hal.append(f"setp {machine.kinematics}.tool-offset 0")
    return hal


ORACLE_TOOLS = 99  # T1..T99: what real programs call (LinuxCNC stops at a T word its table lacks)


def tool_table():
    """LinuxCNC's tool table of ORACLE_TOOLS tools in pockets of their number, of zero length and diameter:
    the oracle times motion, and a program's G43 then changes nothing."""
    return "".join("T%d P%d D0 Z0 ;oracle tool %d\n" % (n, n, n) for n in range(1, ORACLE_TOOLS + 1))


def write_config(machine, folder, program, run_timeout, fallback_uid, start_units="mm"):
    """INI, HAL, the DISPLAY wrapper and a tool table in folder; returns the INI's path. start_units: the
    length units the interpreter starts in ("mm" or "inch", its RS274NGC_STARTUP_CODE)."""
    with open(os.path.join(folder, "oracle.ini"), "w") as f:
        f.write("\n".join(ini_lines(machine, folder, program, run_timeout, start_units)) + "\n")
    with open(os.path.join(folder, "oracle.hal"), "w") as f:
        f.write("\n".join(hal_lines(machine)) + "\n")
    with open(os.path.join(folder, "tool.tbl"), "w") as f:
        f.write(tool_table())
    wrapper = os.path.join(folder, "display")
    with open(wrapper, "w") as f:
        f.write(f"#!/bin/sh\nexec /usr/bin/python3 {os.path.join(HERE, 'lcnc_display.py')} \"$@\"\n")
    os.chmod(wrapper, 0o755)
    # rtapi_app (running as fallback_uid when we are root) makes its socket RTAPI_FIFO_PATH in here
    rtapi = os.path.join(folder, "rtapi")
    os.mkdir(rtapi)
    if fallback_uid is not None:
        os.chown(rtapi, fallback_uid, -1)
    os.chmod(folder, 0o755)
    return os.path.join(folder, "oracle.ini")
