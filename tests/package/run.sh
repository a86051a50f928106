#!/usr/bin/env bash
# `make test-package` (docs/packaging.md): the Debian package installed into a clean root of its Debian (trixie or forky) and used
# there as a user would, outside the source tree; then removed, and the root checked for anything left.
#
#   tests/package/run.sh PACKAGE.deb SUITE FOLDER
#
# FOLDER/base is the clean root: debootstrap (minbase) of the Debian SUITE the package is for (trixie, forky)
# with FreeCAD, Xvfb and a user "hsm" from Debian's
# archive, made by the first run and kept (remove it to make it again). Each run installs into a fresh overlay
# of it (FOLDER/run, kept until the next run: its upper/ holds what the run changed, and the test's outputs in
# upper/tmp/hsm-package-test), so every run starts from the same clean root. apt's downloads are kept in
# FOLDER/apt-archives.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=scripts/debian-root.sh
. "$here/../../scripts/debian-root.sh"

make_base() {
  local base=$1 suite=$2
  [ -f "$base/.hsm-test-root" ] && return 0
  debian_root_make "$base" "$suite" passwd
  echo "Installing FreeCAD, Xvfb and the user hsm into $base (log: $base.log)"
  debian_root_run "$base" / -- /bin/bash -c 'export DEBIAN_FRONTEND=noninteractive
    apt-get update && apt-get install -y --no-install-recommends freecad xvfb xauth && apt-get clean &&
    { id hsm || useradd --create-home --shell /bin/bash hsm; }' > "$base.log" 2>&1 ||
    { tail -30 "$base.log" >&2; exit 1; }
  as_root touch "$base/.hsm-test-root"
}

# In a mount namespace of its own: the overlay, the package and the test files in it, then inside.sh in it.
run_in_overlay() {
  local deb=$1 folder=$2 run=$2/run
  rm -rf "$run"
  mkdir -p "$run/upper" "$run/work" "$run/root" "$folder/apt-archives/partial"
  mount -t overlay overlay -o "lowerdir=$folder/base,upperdir=$run/upper,workdir=$run/work" "$run/root"
  mount --bind "$folder/apt-archives" "$run/root/var/cache/apt/archives"
  local test=$run/root/tmp/hsm-package-test
  mkdir -p "$test"
  cp "$deb" "$here"/{inside.sh,as_user.sh,installed_study.py,gui_package.py} \
    "$here"/../gui/{run_gui_test.sh,user.cfg,gui_harness.py,gui_launch.py,gui_workbench.py} "$test/"
  chmod -R a+rX "$test"
  debian_root_run "$run/root" /tmp/hsm-package-test -- ./inside.sh
}

if [ "${1:-}" = --in-namespace ]; then
  run_in_overlay "$2" "$3"
  exit
fi
[ $# -eq 3 ] && [ -f "$1" ] || { echo "usage: $0 PACKAGE.deb SUITE FOLDER" >&2; exit 2; }
deb=$(realpath "$1")
suite=$2
mkdir -p "$3"
folder=$(cd "$3" && pwd -P)
start=$(date +%s)
make_base "$folder/base" "$suite"
echo "Clean root ready ($(( $(date +%s) - start )) s): $folder/base"
status=0
as_root unshare --mount --propagation "$(debian_root_propagation)" -- "$0" --in-namespace "$deb" "$folder" || status=$?
echo "make test-package: $([ $status -eq 0 ] && echo passed || echo FAILED) in $(( $(date +%s) - start )) s" \
  "(outputs in $folder/run/upper/tmp/hsm-package-test)"
exit $status
