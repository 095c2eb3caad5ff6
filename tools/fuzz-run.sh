#!/usr/bin/env bash
# Runs cyclecert's libFuzzer targets (tests/fuzz/README.md), one after the other:
#   tools/fuzz-run.sh --merge BUILD SECONDS TARGET...   `make fuzz`: each target SECONDS on a copy of
#       tests/fuzz/corpus/TARGET/, then that corpus replaced by the minimised merge of the old corpus
#       and the new inputs (-merge=1: only inputs that add coverage are kept)
#   tools/fuzz-run.sh --smoke BUILD SECONDS TARGET...   `make fuzz-smoke` (CI): the same run, nothing
#       written back
# BUILD/fuzz-TARGET must exist (make fuzz-build, or the sanitizer build). Prints per target the
# executions, the coverage (libFuzzer's cov: and ft:), the corpus and the time; stops at the first
# crash, leak, timeout or out-of-memory with the input saved in BUILD/fuzz-findings/ and the command
# that replays it. Environment: FUZZ_TIMEOUT (seconds per input, default 10), FUZZ_RSS_MB (2048).
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { echo "usage: $0 --merge|--smoke BUILD SECONDS TARGET..." >&2; exit 2; }
[ $# -ge 4 ] || usage
mode=$1 build=$2 seconds=$3
shift 3
case "$mode" in --merge|--smoke) ;; *) usage ;; esac
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "$0: SECONDS must be a whole number, got '$seconds'" >&2; exit 2; }
timeout_s=${FUZZ_TIMEOUT:-10}
rss_mb=${FUZZ_RSS_MB:-2048}
findings="$build/fuzz-findings"
mkdir -p "$findings"
work=$(mktemp -d "${TMPDIR:-/tmp}/cyclecert-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT

dict_for() {
  case "$1" in
    gcode-read|siemens-read|plan) echo "tests/fuzz/gcode.dict" ;;
    spec-case|toolpath-json|process-reply|results) echo "tests/fuzz/json.dict" ;;
    *) echo "" ;;
  esac
}

# Inputs longer than this are cut (libFuzzer's -max_len; default: the corpus's longest). A results
# file of 4 KB holds several result lines with plots, and keeps the corpus small.
max_len_args() {
  case "$1" in
    results) echo "-max_len=4096" ;;
    *) echo "" ;;
  esac
}

# The last "cov: N ft: M corp: K/…" figures and the executions of a libFuzzer log.
figures() {
  local log=$1
  local execs cov ft corp
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$( (grep -o 'cov: [0-9]*' "$log" || true) | tail -1 | cut -d' ' -f2)
  ft=$( (grep -o 'ft: [0-9]*' "$log" || true) | tail -1 | cut -d' ' -f2)
  corp=$( (grep -o 'corp: [0-9]*' "$log" || true) | tail -1 | cut -d' ' -f2)
  printf '%s %s %s %s' "${execs:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}"
}

summary="$work/summary"
printf '%-15s %12s %7s %7s %7s %8s\n' target execs cov ft corpus seconds > "$summary"
for target in "$@"; do
  binary="$build/fuzz-$target"
  corpus="tests/fuzz/corpus/$target"
  [ -x "$binary" ] || { echo "fuzz: $binary is missing (build it: make fuzz-build, or make sanitize)" >&2; exit 1; }
  mkdir -p "$corpus" "$work/$target"
  cp -R "$corpus/." "$work/$target/" 2>/dev/null || true
  log="$findings/$target.log"
  dict=$(dict_for "$target")
  args=(-max_total_time="$seconds" -timeout="$timeout_s" -rss_limit_mb="$rss_mb" -malloc_limit_mb="$rss_mb"
        -print_final_stats=1 -close_fd_mask=1 -artifact_prefix="$findings/$target-")
  [ -n "$dict" ] && args+=(-dict="$dict")
  max_len=$(max_len_args "$target")
  [ -n "$max_len" ] && args+=("$max_len")
  echo "fuzz: $target for $seconds s (corpus $(ls "$corpus" | wc -l) inputs; log $log)"
  start=$(date +%s)
  if ! "$binary" "${args[@]}" "$work/$target" > "$log" 2>&1; then
    saved=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -1)
    kind=$(grep -o -m 1 'ERROR: [A-Za-z]*: [a-z-]*' "$log" || true)
    echo "fuzz: FINDING in $target: ${kind:-the target failed}" >&2
    grep -m 20 -E 'ERROR|SUMMARY|#[0-9]+ 0x' "$log" >&2 || tail -20 "$log" >&2
    if [ -n "$saved" ]; then
      echo "fuzz: the input is saved in $saved; replay it with: $binary $saved" >&2
    fi
    echo "fuzz: the whole log is $log" >&2
    exit 1
  fi
  elapsed=$(( $(date +%s) - start ))
  read -r execs cov ft corp <<< "$(figures "$log")"
  if [ "$mode" = --merge ]; then
    merged="$work/$target.merged"
    mkdir -p "$merged"
    "$binary" -merge=1 $max_len -timeout="$timeout_s" -rss_limit_mb="$rss_mb" -close_fd_mask=1 "$merged" "$corpus" "$work/$target" \
      > "$findings/$target.merge.log" 2>&1 || { echo "fuzz: merging $target's corpus failed: $findings/$target.merge.log" >&2; exit 1; }
    rm -rf "$corpus"
    mv "$merged" "$corpus"
    corp=$(ls "$corpus" | wc -l)
  fi
  printf '%-15s %12s %7s %7s %7s %8s\n' "$target" "$execs" "$cov" "$ft" "$corp" "$elapsed" | tee -a "$summary"
done
echo "fuzz: no finding (mode ${mode#--}, $seconds s per target):"
cat "$summary"
