#!/usr/bin/env bash
# HSM Planner is built and tested on Debian 13 (trixie): FreeCAD 1.0, OCCT 7.8, Python 3.13. A machine that
# is not Debian 13 yet (Debian 12 has only FreeCAD 0.20) gets a Debian 13 root folder made by debootstrap
# from Debian's archive, and the Makefile's targets run inside it, the repository and its parent folder
# (../shared) bound at the same paths. On Debian 13 itself nothing of this is used.
#
#   scripts/debian13.sh needed        prints "yes" when this machine needs the Debian 13 root, else "no"
#   scripts/debian13.sh run CMD...    makes the root if it is missing, then runs CMD in it (as root)
#   scripts/debian13.sh shell         a shell in it (e.g. to start `freecad` on this machine's display)
#
# HSM_DEBIAN13_ROOT (default /var/lib/hsmplanner/debian13) is where the root lives; it is kept between runs,
# so only the first run pays for it (about 20 s of debootstrap, then `make` installs the packages it needs).
set -euo pipefail
# shellcheck source=scripts/debian-root.sh
. "$(dirname "$0")/debian-root.sh"
root=${HSM_DEBIAN13_ROOT:-/var/lib/hsmplanner/debian13}

needed() {
  [ -n "${HSM_IN_DEBIAN13:-}" ] && { echo no; return; }
  local major
  major=$(cut -d. -f1 /etc/debian_version 2>/dev/null || echo "")
  case "$major" in
    ''|*[!0-9]*) echo no ;;  # testing/sid ("trixie/sid") or not Debian: build natively
    *) if [ "$major" -lt 13 ]; then echo yes; else echo no; fi ;;
  esac
}

make_root() {
  debian_root_make "$root" make
}

# Runs "$@" inside the root, in the current folder, the repository's parent folder bound at the same path.
run_inside() {
  local here work
  here=$(pwd -P)
  work=$(cd "$(dirname "$0")/../.." && pwd -P)
  export HSM_IN_DEBIAN13=1
  debian_root_run "$root" "$here" "$work" -- "$@"
}

case "${1:-}" in
  needed) needed ;;
  run) shift; [ $# -gt 0 ] || { echo "usage: $0 run COMMAND..." >&2; exit 2; }
       make_root; run_inside "$@" ;;
  shell) make_root; run_inside /bin/bash ;;
  *) echo "usage: $0 needed | run COMMAND... | shell" >&2; exit 2 ;;
esac
