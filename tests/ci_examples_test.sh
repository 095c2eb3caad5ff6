#!/usr/bin/env bash
# The CI examples (examples/ci/) run end to end without the CI systems: for each, the `cyclecert`
# command lines it contains are extracted and run as its shards would run them — with the variables
# that system sets for each shard (GitHub: the matrix's CYCLECERT_SHARD; GitLab: CI_NODE_INDEX 1…4
# and CI_NODE_TOTAL; Kubernetes: JOB_COMPLETION_INDEX 0…3 and the manifest's CYCLECERT_SHARD_COUNT;
# Slurm: SLURM_ARRAY_TASK_ID 0…3, _COUNT, _MIN and SLURM_CPUS_PER_TASK) — then its merge and report
# lines. The merged results must be those of the unsharded run: against the reference, line for line
# (sorted, without the timing); against a mutant, case for case with the same verdict (each shard
# shrinks the first failure of each kind it meets, so the shrunk details differ from one run's).
# Usage: ci_examples_test.sh CYCLECERT EXAMPLES_DIR SCRATCH_DIR
set -euo pipefail
cli=$1 examples=$2 work=$3
rm -rf "$work"
mkdir -p "$work/bin"
ln -s "$cli" "$work/bin/cyclecert"
export PATH="$work/bin:$PATH"
export SEED=77 CASES=120  # a small campaign
shard_variables="CYCLECERT_SHARD CYCLECERT_SHARD_COUNT CI_NODE_INDEX CI_NODE_TOTAL JOB_COMPLETION_INDEX
  SLURM_ARRAY_TASK_ID SLURM_ARRAY_TASK_COUNT SLURM_ARRAY_TASK_MIN SLURM_ARRAY_TASK_STEP SLURM_CPUS_PER_TASK"
unset $shard_variables
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The command lines of a file: lines that, after indentation and YAML's "- " or "run: ", start with
# `cyclecert fuzz|merge|report`.
commands() { sed -nE 's/^[[:space:]]*(- )?(run: )?(cyclecert (fuzz|merge|report) .*)$/\3/p' "$1"; }

# results.jsonl's lines without "seconds" (reference), or their case and verdict (a mutant), sorted.
normalized() {
  python3 -c 'import json, sys
for line in sys.stdin:
    r = json.loads(line); r.pop("seconds", None)
    print(json.dumps(r, sort_keys=True) if sys.argv[1] == "reference" else r["case"] + " " + r["verdict"])' "$ENGINE" <"$1" |
    sort
}

# The unsharded run of the campaign, normalized, in $work/whole-$ENGINE.txt.
unsharded_run() {
  whole="$work/whole-${ENGINE/:/-}.txt"
  cyclecert fuzz --engine "$ENGINE" --seed "$SEED" --cases "$CASES" --jobs 1 --no-save --out "$work/whole" >/dev/null 2>&1 ||
    test $? -eq 1
  normalized "$work/whole/results.jsonl" >"$whole"
  rm -rf "$work/whole"
  [ "$(wc -l <"$whole")" -eq "$CASES" ] || fail "the unsharded run has $(wc -l <"$whole") results, not $CASES"
}

# run_example NAME FILE [SHARD_FILE] VARIABLES_OF_SHARD_1 … VARIABLES_OF_SHARD_4: the file's fuzz
# line(s) once per shard with that shard's variables, then its merge and report lines.
run_example() {
  local name=$1 file=$2 shard_file=$3
  shift 3
  local fuzz merge report all
  all=$(commands "$examples/$file"; [ -z "$shard_file" ] || commands "$examples/$shard_file")
  fuzz=$(grep '^cyclecert fuzz ' <<<"$all" || true)
  merge=$(grep '^cyclecert merge ' <<<"$all" || true)
  report=$(grep '^cyclecert report ' <<<"$all" || true)
  if [ -z "$fuzz" ] || [ -z "$merge" ] || [ -z "$report" ]; then
    fail "$name: $file lacks a fuzz, merge or report line"
    return
  fi
  grep -q -- '--shard auto' <<<"$fuzz" || fail "$name: the fuzz line does not use --shard auto"
  export RESULTS="$work/$name-${ENGINE/:/-}"
  for variables in "$@"; do
    local status=0
    (unset $shard_variables; export $variables; sh -c "$fuzz" >"$work/$name.log" 2>&1) || status=$?
    if [ "$status" -gt 1 ]; then
      fail "$name: the shard with $variables exited with $status:"
      cat "$work/$name.log"
    fi
  done
  if ! (sh -c "$merge" && sh -c "$report") >"$work/$name.log" 2>&1; then
    fail "$name: merge or report failed:"
    cat "$work/$name.log"
    return
  fi
  [ -f "$RESULTS/merged/report.json" ] || fail "$name: no report.json in $RESULTS/merged"
  if ! diff <(normalized "$RESULTS/merged/results.jsonl") "$whole" >"$work/$name.diff"; then
    fail "$name ($ENGINE): the merged results differ from the unsharded run's:"
    head -c 3000 "$work/$name.diff"
  else
    echo "ok: $name ($ENGINE): $# shards merged into the unsharded run's $CASES results"
  fi
}

# Each example runs 4 shards: the test's variables below stand for what each file declares.
grep -q 'shard: \[1, 2, 3, 4\]' "$examples/github-actions.yml" || fail "github-actions.yml: not a 4-shard matrix"
grep -q 'parallel: 4' "$examples/gitlab-ci.yml" || fail "gitlab-ci.yml: not parallel: 4"
grep -q 'completions: 4' "$examples/kubernetes-indexed-job.yaml" || fail "kubernetes-indexed-job.yaml: not 4 completions"
grep -q 'CYCLECERT_SHARD_COUNT, value: "4"' "$examples/kubernetes-indexed-job.yaml" ||
  fail "kubernetes-indexed-job.yaml: CYCLECERT_SHARD_COUNT is not its 4 completions"
grep -q -- '--array=0-3' "$examples/slurm-fuzz-array.sh" || fail "slurm-fuzz-array.sh: not --array=0-3"

for ENGINE in reference mutant:retract-angle; do  # a clean campaign, and one with failures to shrink
  export ENGINE
  unsharded_run
  run_example github github-actions.yml "" CYCLECERT_SHARD=1/4 CYCLECERT_SHARD=2/4 CYCLECERT_SHARD=3/4 CYCLECERT_SHARD=4/4
  run_example gitlab gitlab-ci.yml "" "CI_NODE_INDEX=1 CI_NODE_TOTAL=4" "CI_NODE_INDEX=2 CI_NODE_TOTAL=4" \
    "CI_NODE_INDEX=3 CI_NODE_TOTAL=4" "CI_NODE_INDEX=4 CI_NODE_TOTAL=4"
  run_example kubernetes kubernetes-indexed-job.yaml "" "JOB_COMPLETION_INDEX=0 CYCLECERT_SHARD_COUNT=4" \
    "JOB_COMPLETION_INDEX=1 CYCLECERT_SHARD_COUNT=4" "JOB_COMPLETION_INDEX=2 CYCLECERT_SHARD_COUNT=4" \
    "JOB_COMPLETION_INDEX=3 CYCLECERT_SHARD_COUNT=4"
  slurm="SLURM_ARRAY_TASK_COUNT=4 SLURM_ARRAY_TASK_MIN=0 SLURM_CPUS_PER_TASK=2"
  run_example slurm slurm-fuzz-array.sh slurm-merge.sh "SLURM_ARRAY_TASK_ID=0 $slurm" "SLURM_ARRAY_TASK_ID=1 $slurm" \
    "SLURM_ARRAY_TASK_ID=2 $slurm" "SLURM_ARRAY_TASK_ID=3 $slurm"
done

if [ "$failures" -ne 0 ]; then
  echo "ci_examples_test: $failures failure(s)"
  exit 1
fi
rm -rf "$work"
echo "ci_examples_test: every example's shards merge into the unsharded run"
