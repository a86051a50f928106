#!/bin/bash
# `make test-package`, inside the clean root of its Debian, as root, in the folder tests/package/run.sh filled:
# installs the package with apt as a user would, has the user hsm use it (as_user.sh), removes it with its
# dependencies, and checks that the root then holds no file of it and no path or package it did not hold before.
set -uo pipefail
export DEBIAN_FRONTEND=noninteractive
start=$(date +%s)
failed=()
step() { echo; echo "=== $* (at $(( $(date +%s) - start )) s)"; }
fail() { echo "FAIL $*"; failed+=("$1"); }

# Every path of the root but the users' homes, the temporary folders and apt's and dpkg's own records.
paths() {
  find / -xdev \( -path /proc -o -path /sys -o -path /dev -o -path /tmp -o -path /home -o -path /root \
    -o -path /var/cache -o -path /var/log -o -path /var/lib/apt -o -path /var/lib/dpkg \) -prune -o -print | sort
}
packages() { dpkg-query -W -f='${Package} ${Version}\n' | sort; }

deb=$(echo freecad-hsmplanner_*.deb)
paths > paths.before
packages > packages.before

step "apt-get install ./$deb"
apt-get update -qq > apt.log 2>&1
if ! apt-get install -y --no-install-recommends "./$deb" >> apt.log 2>&1; then
  tail -40 apt.log
  exit 1
fi
version=$(dpkg-query -W -f='${Version}' freecad-hsmplanner)
dpkg -L freecad-hsmplanner | sort > package.files
echo "freecad-hsmplanner $version installed with $(comm -13 packages.before <(packages) | wc -l) packages" \
  "(itself and the dependencies FreeCAD did not bring); $(wc -l < package.files) paths"
compiled=$(find /usr/share/freecad/Mod/HSMPlanner -name '*.pyc' | wc -l)
[ "$compiled" -gt 60 ] || fail "py3compile" "byte-compiled $compiled files"

step "the user hsm uses it (as_user.sh)"
mkdir -p out && chown hsm: out
runuser -u hsm -- env -i HOME=/home/hsm USER=hsm LOGNAME=hsm LANG=C.UTF-8 PATH=/usr/local/bin:/usr/bin:/bin \
  ./as_user.sh "$PWD/out" "$version" || fail "as the user" "(as_user.sh failed)"

step "root's Python caches a post, as CAM does when root posts: the removal takes them too"
post=/usr/share/freecad/Mod/CAM/Path/Post/scripts/hsm_siemens840d_post.py
python3 -m py_compile "$post" || fail "py_compile" "of the linked post"
cache=$(python3 -c 'import importlib.util, sys; print(importlib.util.cache_from_source(sys.argv[1]))' "$post")
[ -f "$cache" ] || fail "cache" "$cache not written"

step "apt-get purge freecad-hsmplanner; apt-get autoremove --purge"
apt-get purge -y freecad-hsmplanner >> apt.log 2>&1 || fail "purge" "(apt.log)"
apt-get autoremove --purge -y >> apt.log 2>&1 || fail "autoremove" "(apt.log)"
paths > paths.after
packages > packages.after
if ! diff paths.before paths.after > paths.diff; then
  fail "paths" "changed by installing and removing the package:"
  head -40 paths.diff
fi
if ! diff packages.before packages.after > packages.diff; then
  fail "packages" "not as before:"
  head -20 packages.diff
fi
left=$(while read -r path; do  # (a package built by dpkg-deb lists its root as "/.")
         [ "$path" != /. ] && { [ -e "$path" ] || [ -L "$path" ]; } && ! grep -qxF "$path" paths.before && echo "$path"
       done < package.files)
[ -z "$left" ] || fail "left" "files of the package: $left"
ls /var/lib/dpkg/info/freecad-hsmplanner.* > /dev/null 2>&1 && fail "dpkg" "still holds the package's scripts"
[ ${#failed[@]} -eq 0 ] && echo "nothing left: $(wc -l < paths.after) paths and $(wc -l < packages.after)" \
  "packages as before"

step "done: ${#failed[@]} failed ${failed[*]}"
[ ${#failed[@]} -eq 0 ]
