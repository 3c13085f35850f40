#!/usr/bin/env bash
# Runs every fuzz target of a TOONFACE_FUZZ build for SECONDS each (default 60 / the number of
# targets: a smoke run of a minute in all), from its seed corpus, and prints each target's
# executions and new inputs found. Exits non-zero when a target finds a crash, a leak or
# undefined behaviour; the failing input is left in BUILD/fuzz-findings/<target>/ (add it to
# fuzz/regressions/<target>/ with the fix).
#   fuzz/run.sh BUILD [SECONDS] [TARGET...]
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:?usage: fuzz/run.sh BUILD [SECONDS] [TARGET...]}" && pwd)"
shift
targets=(project facejson timeline script textgrid lipsync image audio layer)
seconds="${1:-}"
[ $# -gt 0 ] && shift
[ $# -gt 0 ] && targets=("$@")
[ -n "$seconds" ] || seconds=$(( 60 / ${#targets[@]} ))
[ "$seconds" -ge 1 ] || seconds=1
# Seeds beside the corpus: the tests' own fixtures.
declare -A extra=([project]="$here/../tests/data/io" [layer]="$here/../tests/data/render")
export QT_QPA_PLATFORM=offscreen TOONFACE_CACHE_DIR="$build/fuzz-cache"
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1" UBSAN_OPTIONS="print_stacktrace=1"
failed=0
for t in "${targets[@]}"; do
  work="$build/fuzz-corpus/$t"
  findings="$build/fuzz-findings/$t"
  mkdir -p "$work" "$findings"
  log="$build/fuzz-findings/$t.log"
  "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=4096 -timeout=20 \
    -print_final_stats=1 -artifact_prefix="$findings/" \
    "$work" "$here/corpus/$t" ${extra[$t]:-} $( [ -d "$here/regressions/$t" ] && echo "$here/regressions/$t" ) \
    > "$log" 2>&1
  rc=$?
  execs=$(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
  corpus=$(ls "$work" | wc -l)
  if [ $rc -eq 0 ]; then
    echo "fuzz: $t: ${seconds} s, ${execs:-?} runs, $corpus inputs in its corpus, no failure"
  else
    echo "fuzz: $t FAILED (exit $rc): see $log and $findings"
    grep -m5 -E 'ERROR|SUMMARY|runtime error|fuzz check failed' "$log" | sed 's/^/  /'
    failed=1
  fi
done
exit $failed
