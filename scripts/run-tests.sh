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

run_python() {
  local home
  home=$(fresh_home) || return 1
  HOME=$home "$repo/scripts/run-freecadcmd.sh" "$repo/tests/python/run_tests.py"
  local status=$?
  rm -rf "$home"
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
