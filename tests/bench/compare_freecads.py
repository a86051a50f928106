"""The core's and the FreeCAD layer's benchmarks on FreeCAD 1.0 and on 1.1, in one run, with the ratios 1.1 / 1.0.

    python3 tests/bench/compare_freecads.py [--repeats 2]

Each benchmark runs where its FreeCAD is (scripts/freecad-env.sh: Debian 13 with OCCT 7.8, Python 3.13 and
pybind11 2.13; Debian forky with OCCT 7.9, Python 3.14 and pybind11 3.1), the two FreeCADs one after the other
for each benchmark, each `--repeats` times (the best kept), so that both see the machine in the same state.
Google Benchmark programs give each of their figures; the others are timed whole (wall time of the program,
which prints its own figures too). Both builds must exist (`make FREECAD=1.0 build`, `make FREECAD=1.1 build`).
Ratios above 1 mean 1.1 takes longer.
"""
import argparse
import json
import os
import subprocess
import sys
import time

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
VERSIONS = ("1.0", "1.1")
# (name, command relative to the build folder or the repository, Google Benchmark?)
BENCHMARKS = [
    ("G-code read and simulate", ["bin/bench_feedsim"], False),
    ("curve nets", ["bin/bench_curvenet"], True),
    ("drop-cutter", ["bin/bench_dropcutter"], False),
    ("machining direction", ["bin/bench_direction"], True),
    ("roughing: volume, partitions, sweeps, clearance, removal", ["bin/bench_roughing", "1"], False),
    ("finishing from Python (freecadcmd)", ["scripts/run-freecadcmd.sh", "tests/bench/bench_finishing.py"], False),
    ("K/P preview from Python (freecadcmd)", ["scripts/run-freecadcmd.sh", "tests/bench/bench_preview.py"], False),
]


def run(version, command, google):
    build = os.path.join(REPO, "build", "freecad-" + version)
    program = os.path.join(build, command[0]) if command[0].startswith("bin/") else command[0]
    argv = [program] + command[1:] + (["--benchmark_format=json"] if google else [])
    begin = time.monotonic()
    done = subprocess.run([os.path.join(REPO, "scripts", "freecad-env.sh"), version, "run",
                           "env", "HSM_BUILD_DIR=" + build] + argv, cwd=REPO, capture_output=True, text=True)
    seconds = time.monotonic() - begin
    if done.returncode != 0:
        raise SystemExit("%s on FreeCAD %s failed (exit %d):\n%s%s" % (" ".join(command), version,
                                                                       done.returncode, done.stdout[-2000:],
                                                                       done.stderr[-2000:]))
    figures = {"whole program, s": seconds}
    if google:
        start = done.stdout.index("{")
        for entry in json.loads(done.stdout[start:])["benchmarks"]:
            figures["%s, %s" % (entry["name"], entry.get("time_unit", "ns"))] = entry["real_time"]
    return figures, done.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=2)
    args = parser.parse_args()
    rows = []
    for name, command, google in BENCHMARKS:
        best = {}
        for _ in range(args.repeats):
            for version in VERSIONS:
                figures, output = run(version, command, google)
                for key, value in figures.items():
                    best.setdefault((key, version), value)
                    best[(key, version)] = min(best[(key, version)], value)
                sys.stderr.write("--- %s on FreeCAD %s\n%s\n" % (name, version, output.strip()[-1500:]))
        for key in sorted({key for key, _ in best}):
            old, new = best[(key, "1.0")], best[(key, "1.1")]
            rows.append((name, key, old, new, new / old if old else float("nan")))
    print("| benchmark | figure | FreeCAD 1.0 | FreeCAD 1.1 | 1.1 / 1.0 |")
    print("|---|---|---:|---:|---:|")
    for name, key, old, new, ratio in rows:
        print("| %s | %s | %.4g | %.4g | %.2f |" % (name, key, old, new, ratio))


main()
