# Debian root folders made by debootstrap from Debian's archive (trixie for FreeCAD 1.0, forky for 1.1), and
# commands run inside them; sourced by scripts/freecad-env.sh (the build's roots) and tests/package/run.sh (the
# package test's clean roots).
#
#   debian_root_make ROOT SUITE [PACKAGE,...]    debootstrap (minbase) of SUITE into ROOT unless it is complete
#   debian_root_run ROOT DIR [BIND...] -- CMD... runs CMD as root inside ROOT, in DIR, each BIND folder seen at
#                                                the same path, in a private mount namespace (the binds vanish
#                                                with it); the environment is HSM_*, CI and what a login sets
debian_root_mirror=${HSM_DEBIAN_MIRROR:-http://deb.debian.org/debian}

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else echo "error: a Debian root needs root (debootstrap, chroot): run as root or install sudo" >&2; exit 1
  fi
}

# debootstrap on this machine (apt-get holds a lock: install it before anything else may run apt-get beside it)
debian_root_tools() {
  command -v debootstrap >/dev/null && return 0
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap
}

debian_root_make() {
  local root=$1 suite=$2 include=${3:+,$3}
  [ -f "$root/.hsm-complete" ] && return 0
  echo "Making a Debian $suite root in $root (this machine is Debian $(cat /etc/debian_version))"
  debian_root_tools
  # An older debootstrap has no script for a newer suite (Debian 12's knows no forky): sid's fits every one.
  local script=/usr/share/debootstrap/scripts/$suite
  [ -e "$script" ] || script=/usr/share/debootstrap/scripts/sid
  local partial="$root.partial" log
  log=$(mktemp /tmp/hsm-debootstrap.XXXXXX.log)
  as_root rm -rf "$partial"
  as_root mkdir -p "$(dirname "$root")"
  as_root debootstrap --variant=minbase --include="ca-certificates$include" "$suite" "$partial" \
    "$debian_root_mirror" "$script" > "$log" 2>&1 || { tail -30 "$log" >&2; exit 1; }
  rm -f "$log"
  if [ "$suite" = trixie ]; then
    printf 'deb %s %s main\ndeb %s %s-updates main\n' "$debian_root_mirror" "$suite" "$debian_root_mirror" "$suite"
  else
    printf 'deb %s %s main\n' "$debian_root_mirror" "$suite"
  fi | as_root tee "$partial/etc/apt/sources.list" > /dev/null
  # The archive seen here may be a snapshot whose Release files are past their Valid-Until (a testing suite's
  # is a week): apt would refuse every update of such a root.
  echo 'Acquire::Check-Valid-Until "false";' | as_root tee "$partial/etc/apt/apt.conf.d/99hsm-snapshot" > /dev/null
  # Package scripts must not start services on the host's behalf.
  printf '#!/bin/sh\nexit 101\n' | as_root tee "$partial/usr/sbin/policy-rc.d" > /dev/null
  as_root chmod 755 "$partial/usr/sbin/policy-rc.d"
  as_root touch "$partial/.hsm-complete"
  as_root rm -rf "$root"
  as_root mv "$partial" "$root"
}

# A new mount namespace's mounts are made private, so that nothing mounted in it reaches the host. Inside a
# chroot (a Debian root running this) "/" is no mount point and cannot be changed, and needs not be: the
# namespace that entered the chroot made its mounts private already, and a copy of a private mount is private.
debian_root_propagation() {
  if mountpoint -q /; then echo private; else echo unchanged; fi
}

debian_root_run() {
  local root=$1 dir=$2 binds=() passed=() name
  shift 2
  while [ $# -gt 0 ] && [ "$1" != -- ]; do binds+=("$1"); shift; done
  [ "${1:-}" = -- ] && shift
  for name in $(compgen -e); do  # HSM_* settings (HSM_GUI_TESTS…) and CI reach the commands inside
    case "$name" in HSM_*|CI) passed+=("$name=${!name}") ;; esac
  done
  as_root cp /etc/resolv.conf "$root/etc/resolv.conf"
  as_root unshare --mount --propagation "$(debian_root_propagation)" -- /bin/bash -s -- "$root" "$dir" "${#binds[@]}" "${binds[@]}" \
    "${#passed[@]}" "${passed[@]}" "$@" <<'INSIDE'
set -e
root=$1 dir=$2 count=$3; shift 3
binds=("${@:1:$count}"); shift "$count"
count=$1; shift
passed=("${@:1:$count}"); shift "$count"
mount --rbind /dev "$root/dev"
mount --rbind /proc "$root/proc"
mount --rbind /sys "$root/sys"
for bind in "${binds[@]}"; do
  mkdir -p "$root$bind"
  mount --rbind "$bind" "$root$bind"
done
exec chroot "$root" /usr/bin/env -i "${passed[@]}" HOME=/root LANG=C.UTF-8 \
  TERM="${TERM:-dumb}" DISPLAY="${DISPLAY:-}" PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  /bin/bash -c 'cd "$0" && exec "$@"' "$dir" "$@"
INSIDE
}
