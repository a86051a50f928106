#!/usr/bin/env bash
# Where each supported FreeCAD runs. HSM Planner is built and tested against two FreeCADs from Debian's archive:
#   1.1  Debian forky (testing): FreeCAD 1.1.3, Qt 6 / PySide6, Python 3.14, OCCT 7.9   (the default)
#   1.0  Debian 13 (trixie):     FreeCAD 1.0.0, Qt 5 / PySide2, Python 3.13, OCCT 7.8
# On a machine that is that Debian, natively; on any other, in a root folder of that Debian made by debootstrap
# and kept between runs (one per FreeCAD), the repository's parent folder (so ../shared) bound at the same path.
#
#   scripts/freecad-env.sh VERSION needed        prints "yes" when VERSION needs its root here, else "no"
#   scripts/freecad-env.sh VERSION run CMD...    runs CMD where VERSION is, in the current folder (makes the root
#                                                the first time: about 30 s, then `make` installs the packages)
#   scripts/freecad-env.sh VERSION shell         a shell there (e.g. `freecad` on this machine's DISPLAY)
#   scripts/freecad-env.sh VERSION root          prints the root's folder
#   scripts/freecad-env.sh VERSION suite         prints the Debian suite of VERSION
#
# HSM_ROOTS (default /var/lib/hsmplanner) is the folder of the roots: HSM_ROOTS/freecad-VERSION.
set -euo pipefail
# shellcheck source=scripts/debian-root.sh
. "$(dirname "$0")/debian-root.sh"

usage() {
  echo "usage: $0 VERSION needed | run COMMAND... | shell | root | suite   (VERSION: 1.1 or 1.0)" >&2
  exit 2
}

version=${1:-}
case "$version" in
  1.1) suite=forky ;;
  1.0) suite=trixie ;;
  *) [ -n "$version" ] && echo "error: FreeCAD $version is not supported: use 1.1 (Debian forky) or 1.0 (Debian 13)" >&2
     usage ;;
esac
shift
root=${HSM_ROOTS:-/var/lib/hsmplanner}/freecad-$version

# This machine's Debian suite: its codename (trixie, forky; sid reports the testing one it follows).
this_suite() {
  local codename=""
  [ -r /etc/os-release ] && codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  if [ -z "$codename" ] && [ -r /etc/debian_version ]; then
    codename=$(cut -d/ -f1 /etc/debian_version)
  fi
  echo "$codename"
}

needed() {
  # Inside a root this script made, or on that Debian itself: natively.
  if [ "${HSM_FREECAD_ENV:-}" = "$version" ] || [ "$(this_suite)" = "$suite" ]; then echo no; else echo yes; fi
}

# Runs "$@" where the version's FreeCAD is, in the current folder.
run_there() {
  local native here work
  native=$(needed)
  export HSM_FREECAD_ENV=$version
  if [ "$native" = no ]; then "$@"; return; fi
  here=$(pwd -P)
  work=$(cd "$(dirname "$0")/../.." && pwd -P)
  debian_root_make "$root" "$suite" make
  debian_root_run "$root" "$here" "$work" -- "$@"
}

case "${1:-}" in
  needed) needed ;;
  root) echo "$root" ;;
  suite) echo "$suite" ;;
  run) shift; [ $# -gt 0 ] || usage; run_there "$@" ;;
  shell) run_there /bin/bash ;;
  *) usage ;;
esac
