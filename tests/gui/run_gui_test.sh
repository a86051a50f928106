#!/usr/bin/env bash
# Starts the real FreeCAD GUI under Xvfb with a macro that drives the workbench, then checks its verdict.
# Needs HOME (throw-away, workbench linked) and HSM_GUI_TEST_OUT (screenshots and result.json) set.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
: "${HSM_GUI_TEST_OUT:?set HSM_GUI_TEST_OUT to the folder for screenshots}"
# The preferences where this FreeCAD reads them (1.1 keeps them per version: ~/.config/FreeCAD/v1-1/).
config=$(freecadcmd -c 'import FreeCAD; print("HSM_CONFIG=" + FreeCAD.ConfigGet("UserConfigPath"))' 2>/dev/null |
         sed -n 's/^HSM_CONFIG=//p')
[ -n "$config" ] || { echo "freecadcmd did not say where FreeCAD keeps its preferences" >&2; exit 1; }
mkdir -p "$config" "$HSM_GUI_TEST_OUT"
cp "$here/user.cfg" "$config/user.cfg"

export QTWEBENGINE_DISABLE_SANDBOX=1 LIBGL_ALWAYS_SOFTWARE=1
failed=0
verdicts=()  # one line per macro, printed again at the end where a log's tail shows them

# run_macro MACRO OUT: FreeCAD's GUI on MACRO through gui_launch.py, its log in OUT/freecad.log.
run_macro() {
  # The macro ends FreeCAD itself (gui_launch.py ends it at once if the macro raises while loading); `timeout` is
  # the last resort if something blocks the event loop.
  HSM_GUI_TEST_OUT=$2 HSM_GUI_MACRO=$1 timeout 600 xvfb-run -a -s "-screen 0 1280x1024x24" \
    freecad "$here/gui_launch.py" > "$2/freecad.log" 2>&1
}

# The launcher itself: a macro that raises while loading ends FreeCAD at once with its traceback in the verdict.
if [ -z "${HSM_GUI_TESTS:-}" ] || [[ " $HSM_GUI_TESTS " == *" launch "* ]]; then
  out="$HSM_GUI_TEST_OUT/gui_launch_check"
  mkdir -p "$out"
  printf 'raise RuntimeError("the launcher check raised this")\n' > "$out/gui_raises.py"
  begin=$(date +%s)
  run_macro "$out/gui_raises.py" "$out"
  took=$(( $(date +%s) - begin ))
  echo "--- gui_launch_check (a macro that raises while loading: FreeCAD ended after $took s)"
  if ! grep -q "the launcher check raised this" "$out/result.json" 2>/dev/null || [ "$took" -gt 120 ]; then
    echo "GUI test launcher: FreeCAD did not end with the macro's traceback (after $took s)" >&2
    failed=1
  fi
fi
# HSM_GUI_TESTS="feedrate direction" runs only those macros (gui_feedrate.py, gui_direction.py).
for macro in "$here"/gui_*.py; do
  name=$(basename "$macro" .py)
  case "$name" in gui_harness|gui_launch) continue ;; esac
  if [ -n "${HSM_GUI_TESTS:-}" ] && [[ " $HSM_GUI_TESTS " != *" ${name#gui_} "* ]]; then continue; fi
  out="$HSM_GUI_TEST_OUT/$name"
  mkdir -p "$out"
  begin=$(date +%s)
  run_macro "$macro" "$out"
  status=$?
  result="$out/result.json"
  took=$(( $(date +%s) - begin ))
  echo "--- $name ($took s)"
  if [ ! -f "$result" ]; then
    echo "GUI test $name: FreeCAD ended (exit $status) without a verdict; log:" >&2
    tail -40 "$out/freecad.log" >&2
    verdicts+=("$name: FAILED after $took s: FreeCAD ended (exit $status) without a verdict; last line of its log: $(tail -1 "$out/freecad.log")")
    failed=1
    continue
  fi
  cat "$result"; echo
  if /usr/bin/python3 -c 'import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))["ok"] else 1)' "$result"; then
    verdicts+=("$name: passed in $took s")
  else
    verdicts+=("$name: FAILED after $took s: $(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["failures"])' "$result" | cut -c1-1500)")
    failed=1
  fi
done
echo "=== GUI macros ==="
printf '%s\n' "${verdicts[@]}"
exit $failed
