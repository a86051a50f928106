#!/usr/bin/env bash
# `make test`: every test level on each FreeCAD named (`make FREECAD=VERSION test` for each, all of them run
# whatever the first gives), then one summary. While the first version builds, the next one's root and packages
# are made in the background (downloads, not the compiler), so a fresh machine waits for them once.
#
#   scripts/test-versions.sh VERSION...
set -uo pipefail
cd "$(dirname "$0")/.."
[ $# -gt 0 ] || { echo "usage: $0 VERSION..." >&2; exit 2; }
versions=("$@")
# shellcheck source=scripts/debian-root.sh
. scripts/debian-root.sh
for version in "${versions[@]}"; do
  [ "$(scripts/freecad-env.sh "$version" needed)" = yes ] && debian_root_tools
done
logs=$(mktemp -d /tmp/hsm-test-versions.XXXXXX)

prepare() {  # the root of a version (where one is needed) and its Debian packages
  scripts/freecad-env.sh "$1" run make --no-print-directory FREECAD="$1" deps > "$logs/deps-$1.log" 2>&1
}

declare -A seconds verdict
for i in "${!versions[@]}"; do
  version=${versions[$i]}
  next=${versions[$((i + 1))]:-}
  preparing=""
  if [ -n "$next" ]; then prepare "$next" & preparing=$!; fi
  echo "=== FreeCAD $version: make FREECAD=$version test ==="
  start=$(date +%s)
  # The build beside the next root's downloads; the tests alone (a GUI macro waits on timers, and dpkg
  # unpacking hundreds of packages beside it is no load a user's machine has).
  make --no-print-directory FREECAD="$version" build 2>&1 | tee "$logs/test-$version.log"
  if [ -n "$preparing" ]; then
    wait "$preparing" || { echo "preparing FreeCAD $next failed:"; tail -30 "$logs/deps-$next.log"; }
    tail -3 "$logs/deps-$next.log"
  fi
  make --no-print-directory FREECAD="$version" test 2>&1 | tee -a "$logs/test-$version.log"
  if [ "${PIPESTATUS[0]}" -eq 0 ]; then verdict[$version]=passed; else verdict[$version]=FAILED; fi
  seconds[$version]=$(( $(date +%s) - start ))
done

echo "=== summary of make test ==="
failed=0
for version in "${versions[@]}"; do
  printf 'FreeCAD %-4s %-7s %5ss (build included)\n' "$version" "${verdict[$version]}" "${seconds[$version]}"
  [ "${verdict[$version]}" = passed ] && continue
  failed=1
  # what failed, again here at the end where a long log's tail shows it
  grep -E '^(FAIL|ERROR): |^[0-9]+% tests passed|^ *[0-9]+/[0-9]+ Test .*(Failed|Timeout)|^gui_[a-z_]+: FAILED|^GUI test ' \
    "$logs/test-$version.log" | cut -c1-2000 | sed 's/^/    /'
done
rm -rf "$logs"
exit $failed
