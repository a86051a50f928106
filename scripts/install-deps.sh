#!/usr/bin/env bash
# Installs the Debian packages of scripts/debian-packages.txt (or of the lists named) that are missing.
# Quiet and quick when none is. A name written ?NAME is installed where this Debian's archive has it (a
# package one Debian release has and another not).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lists=("$@")
[ ${#lists[@]} -eq 0 ] && lists=("$here/debian-packages.txt")
mapfile -t wanted < <(cat "${lists[@]}" | grep -v '^\s*#' | grep -v '^\s*$')
missing=()
for package in "${wanted[@]}"; do
  optional=no
  [[ $package == \?* ]] && { package=${package#\?}; optional=yes; }
  status=$(dpkg-query -W -f='${db:Status-Status}' "$package" 2>/dev/null || true)
  [ "$status" = "installed" ] && continue
  if [ $optional = yes ]; then
    # a root just made has no package lists yet: the package would look absent from the archive
    if ! compgen -G "/var/lib/apt/lists/*_Packages" > /dev/null && [ "$(id -u)" -eq 0 ]; then
      DEBIAN_FRONTEND=noninteractive apt-get update -qq
    fi
    apt-cache show "$package" > /dev/null 2>&1 || continue
  fi
  missing+=("$package")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null; then
  as_root=(sudo)
else
  echo "error: packages missing (${missing[*]}) and this user is not root and has no sudo: install them as root" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
