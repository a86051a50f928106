#!/bin/bash
# `make test-package`, inside the clean root of the package's Debian, as the user hsm, with the package installed and no clone
# in sight: the installed study script, the examples from /usr/share/doc, the commands, the GUI under Xvfb, and
# a developer's copy in the user's Mod folder taking precedence. Prints each step; exit status 1 if one failed.
#   as_user.sh OUTPUT_DIR VERSION
set -uo pipefail
tests=$(cd "$(dirname "$0")" && pwd)
out=$1 version=$2
doc=/usr/share/doc/freecad-hsmplanner
mod=/usr/share/freecad/Mod/HSMPlanner
# the user's Mod folder, where this FreeCAD keeps it (1.1: ~/.local/share/FreeCAD/v1-1/Mod)
user_mod=$(freecadcmd -c 'import FreeCAD; print("HSM_MOD=" + FreeCAD.getUserAppDataDir() + "Mod")' 2>/dev/null |
           sed -n 's/^HSM_MOD=//p')
failed=()
cd "$out"

# check NAME COMMAND...: runs COMMAND (output in NAME.log), says how long it took; on failure shows the log.
check() {
  local name=$1 begin
  shift
  begin=$(date +%s)
  if "$@" > "$name.log" 2>&1; then
    echo "ok   $name ($(( $(date +%s) - begin )) s)"
  else
    echo "FAIL $name ($(( $(date +%s) - begin )) s):"
    tail -25 "$name.log" | tr '\r' '\n' | grep -av '^\s*$' | tail -15
    failed+=("$name")
  fi
}
has() { grep -aq -- "$1" "$2"; }

check installed_study freecadcmd "$tests/installed_study.py" "$out/study" "$version"
grep -a '^ok\|^FAIL\|^     ' installed_study.log

# The examples as the package ships them, run where they are.
check example_master_feature freecadcmd "$doc/examples/master_bottom_feature.py" "$out/examples"
check example_guidance_study freecadcmd "$doc/examples/guidance_study.py" "$out/examples"
check example_guidance_study_rows test "$(wc -l < examples/study.csv)" -eq 16
check example_feedrate_study freecadcmd "$doc/examples/feedrate_study.py" "$out/examples"
check example_feedrate_study_rows test "$(wc -l < examples/feedrate_comparison.csv)" -eq 7

# The commands and their manual pages.
check feedsim_machines sh -c 'hsm-feedsim --list-machines | grep -x mikron-ucp710-840d'
check feedsim_program hsm-feedsim study/installed_study.mpf --machine mikron-ucp710-840d --json feedsim.json -q
check feedsim_json python3 -c 'import json, sys; s = json.load(open("feedsim.json"))
sys.exit(0 if s["total_time_s"] > s["naive_time_s"] > 10 else 1)'
check feedsim_bad_input sh -c 'hsm-feedsim missing.ngc -m grbl 2>&1; test $? -eq 1' && \
  check feedsim_bad_input_named has "hsm-feedsim: error: cannot read the program 'missing.ngc'" feedsim_bad_input.log
read -r face b1 b2 < <(python3 -c 'import json; j = json.load(open("examples/master_bottom_feature.json"))
print(j["bottom_face"], j["boundary_1"], j["boundary_2"])')
check study_cli hsm-study examples/master_bottom_feature.brep --face "$face" --b1 "$b1" --b2 "$b2" \
  --planes 0,90 --k 0.5 --p 20 --median with --feeds 4000 --workers 2 --csv study.csv
check study_cli_ranked test "$(grep -c '^planes\|^guide' study_cli.log)" -eq 3
check study_bad_input sh -c 'hsm-study examples/master_bottom_feature.brep --face Face999 --b1 x --b2 y --planes 0 2>&1
  test $? -eq 2' && check study_bad_input_named has "hsm-study: face 'Face999'" study_bad_input.log
check manual_pages sh -c 'for page in hsm-feedsim hsm-study; do
  zcat /usr/share/man/man1/$page.1.gz | grep -q "^\.SH OPTIONS" || exit 1; done'

# The GUI under Xvfb: the workbench's smoke test and the package's own.
check gui env HSM_GUI_TEST_OUT="$out/gui" "$tests/run_gui_test.sh"

# A developer's copy in the user's Mod folder (here a copy of the installed one) is the one loaded, under the
# workbench's own name (FreeCAD skips the system folder) or another (Init.py loads the user's, and says so).
where='import hsmplanner; print("LOADED", hsmplanner.__file__)'
mkdir -p "$user_mod"
cp -rL "$mod" "$user_mod/HSMPlanner"
check user_copy_same_name freecadcmd -c "$where"
check user_copy_same_name_loaded has "LOADED $user_mod/HSMPlanner/python/" user_copy_same_name.log
mv "$user_mod/HSMPlanner" "$user_mod/hsm-planner-dev"
check user_copy_other_name freecadcmd -c "$where"
check user_copy_other_name_loaded has "LOADED $user_mod/hsm-planner-dev/python/" user_copy_other_name.log
check user_copy_other_name_said has "HSM Planner in $mod not loaded: the one in $user_mod/hsm-planner-dev is" \
  user_copy_other_name.log
rm -rf "$user_mod/hsm-planner-dev"
check package_again freecadcmd -c "$where"
check package_again_loaded has "LOADED $mod/python/" package_again.log

echo "as the user: ${#failed[@]} failed ${failed[*]}"
[ ${#failed[@]} -eq 0 ]
