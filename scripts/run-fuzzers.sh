#!/usr/bin/env bash
# Runs each libFuzzer harness of tests/fuzz for a given time on its corpus (new inputs are added to it)
# and prints the executions and findings. A finding (crash, sanitizer report, timeout, leak) stops that
# harness and leaves its input as tests/fuzz/findings/<harness>-*; make test then replays the corpus.
set -uo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${1:-$repo/build-asan}
seconds=${2:-60}
findings=$repo/tests/fuzz/findings
mkdir -p "$findings"
status=0
for harness in gcode brep_curvenet brep_finishing; do
  corpus=$repo/tests/fuzz/corpus/$harness
  log=$build_dir/fuzz_$harness.log
  echo "=== fuzz_$harness: $seconds s on $(ls "$corpus" | wc -l) corpus inputs"
  ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$repo/tests/cpp/lsan.supp "$build_dir/bin/fuzz_$harness" "$corpus" -max_total_time="$seconds" \
    -timeout=30 -rss_limit_mb=4096 -max_len=262144 -print_final_stats=1 \
    -artifact_prefix="$findings/$harness-" > "$log" 2>&1
  code=$?
  grep -E "^stat::number_of_executed_units|^stat::new_units_added|^stat::peak_rss_mb" "$log" | sed 's/^/  /'
  if [ $code -ne 0 ]; then
    echo "  FINDING (exit $code): see $log and $findings"
    grep -E "ERROR|SUMMARY|finding|Timeout|runtime error" "$log" | head -5 | sed 's/^/  /'
    status=1
  fi
done
exit $status
