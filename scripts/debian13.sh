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
root=${HSM_DEBIAN13_ROOT:-/var/lib/hsmplanner/debian13}
mirror=${HSM_DEBIAN_MIRROR:-http://deb.debian.org/debian}
suite=trixie

needed() {
  [ -n "${HSM_IN_DEBIAN13:-}" ] && { echo no; return; }
  local major
  major=$(cut -d. -f1 /etc/debian_version 2>/dev/null || echo "")
  case "$major" in
    ''|*[!0-9]*) echo no ;;  # testing/sid ("trixie/sid") or not Debian: build natively
    *) if [ "$major" -lt 13 ]; then echo yes; else echo no; fi ;;
  esac
}

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else echo "error: the Debian 13 root needs root (debootstrap, chroot): run as root or install sudo" >&2; exit 1
  fi
}

make_root() {
  [ -x "$root/usr/bin/make" ] && [ -f "$root/.hsm-complete" ] && return 0
  echo "Making a Debian 13 ($suite) root in $root for FreeCAD 1.0 (this machine is Debian $(cat /etc/debian_version))"
  if ! command -v debootstrap >/dev/null; then
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap
  fi
  local partial="$root.partial"
  as_root rm -rf "$partial"
  as_root mkdir -p "$(dirname "$root")"
  as_root debootstrap --variant=minbase --include=make,ca-certificates "$suite" "$partial" "$mirror" \
    > "/tmp/hsm-debootstrap.log" 2>&1 || { tail -30 /tmp/hsm-debootstrap.log >&2; exit 1; }
  as_root tee "$partial/etc/apt/sources.list" > /dev/null <<EOF
deb $mirror $suite main
deb $mirror $suite-updates main
EOF
  # Package scripts must not start services on the host's behalf.
  printf '#!/bin/sh\nexit 101\n' | as_root tee "$partial/usr/sbin/policy-rc.d" > /dev/null
  as_root chmod 755 "$partial/usr/sbin/policy-rc.d"
  as_root touch "$partial/.hsm-complete"
  as_root rm -rf "$root"
  as_root mv "$partial" "$root"
}

# Runs "$@" inside the root, in the current folder, in a private mount namespace: the binds vanish with it.
run_inside() {
  local here work
  here=$(pwd -P)
  work=$(cd "$(dirname "$0")/../.." && pwd -P)
  local passed=() name
  for name in $(compgen -e); do  # HSM_* settings (HSM_GUI_TESTS…) and CI reach the commands inside
    case "$name" in HSM_*|CI) passed+=("$name=${!name}") ;; esac
  done
  as_root cp /etc/resolv.conf "$root/etc/resolv.conf"
  as_root unshare --mount --propagation private -- /bin/bash -s -- "$root" "$work" "$here" "${#passed[@]}" \
    "${passed[@]}" "$@" <<'INSIDE'
set -e
root=$1 work=$2 here=$3 count=$4; shift 4
passed=("${@:1:$count}"); shift "$count"
mount --rbind /dev "$root/dev"
mount --rbind /proc "$root/proc"
mount --rbind /sys "$root/sys"
mkdir -p "$root$work"
mount --rbind "$work" "$root$work"
exec chroot "$root" /usr/bin/env -i "${passed[@]}" HSM_IN_DEBIAN13=1 HOME=/root LANG=C.UTF-8 \
  TERM="${TERM:-dumb}" DISPLAY="${DISPLAY:-}" PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  /bin/bash -c 'cd "$0" && exec "$@"' "$here" "$@"
INSIDE
}

case "${1:-}" in
  needed) needed ;;
  run) shift; [ $# -gt 0 ] || { echo "usage: $0 run COMMAND..." >&2; exit 2; }
       make_root; run_inside "$@" ;;
  shell) make_root; run_inside /bin/bash ;;
  *) echo "usage: $0 needed | run COMMAND... | shell" >&2; exit 2 ;;
esac
