#!/usr/bin/env bash
# Runs the test levels (all by default: cpp python gui) and exits non-zero if any fails.
# Python and GUI tests run FreeCAD with a throw-away HOME into which the workbench is linked.
set -uo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build_dir=$(cd "${1:-$repo/build}" && pwd)
shift || true
levels=("$@")
[ ${#levels[@]} -eq 0 ] && levels=(cpp python gui)

fresh_home() {
  local home
  home=$(mktemp -d /tmp/hsm-test-home.XXXXXX)
  HOME=$home freecadcmd "$repo/scripts/link_workbench.py" "$repo" > "$home/link.log" 2>&1 ||
    { cat "$home/link.log" >&2; return 1; }
  echo "$home"
}

run_cpp() {
  /usr/bin/ctest --test-dir "$build_dir" --output-on-failure -j 2
}

# The FreeCAD layer in HSM_PYTHON_PROCESSES freecadcmd processes (default: one per core) sharing the test
# modules (HSM_TEST_CLAIMS, see tests/python/run_tests.py); each one's output is shown after it ends, and a
# process that did not say what it ran fails the level (freecadcmd may exit 0 without running the script).
run_python() {
  local home claims processes status=0 i
  home=$(fresh_home) || return 1
  claims=$(mktemp -d /tmp/hsm-test-claims.XXXXXX)
  processes=${HSM_PYTHON_PROCESSES:-$(nproc)}
  local pids=()
  for i in $(seq 1 "$processes"); do
    HOME=$home HSM_TEST_CLAIMS=$claims "$repo/scripts/run-freecadcmd.sh" "$repo/tests/python/run_tests.py" \
      > "$claims.out$i" 2>&1 &
    pids+=($!)
  done
  for i in $(seq 1 "$processes"); do
    wait "${pids[$((i - 1))]}" || status=1
    echo "--- freecadcmd process $i of $processes"
    cat "$claims.out$i"
    grep -q "^this process: " "$claims.out$i" || { echo "freecadcmd process $i ran no test script"; status=1; }
    rm -f "$claims.out$i"
  done
  rm -rf "$home" "$claims"
  return "$status"
}

run_gui() {
  local home out
  home=$(fresh_home) || return 1
  out="$build_dir/gui-test"
  rm -rf "$out" && mkdir -p "$out"
  HOME=$home HSM_GUI_TEST_OUT=$out "$repo/tests/gui/run_gui_test.sh"
  local status=$?
  rm -rf "$home"
  return "$status"
}

failed=()
declare -A seconds
for level in "${levels[@]}"; do
  echo "=== HSM Planner tests: $level ==="
  start=$(date +%s)
  "run_$level" || failed+=("$level")
  seconds[$level]=$(( $(date +%s) - start ))
done

echo "=== summary ==="
for level in "${levels[@]}"; do
  verdict=passed
  [[ " ${failed[*]} " == *" $level "* ]] && verdict=FAILED
  printf '%-7s %-7s %4ss\n' "$level" "$verdict" "${seconds[$level]}"
done
echo "levels: $(( ${#levels[@]} - ${#failed[@]} )) passed, ${#failed[@]} failed"
[ ${#failed[@]} -eq 0 ]
