#!/usr/bin/env bash
# `make run`'s job: the spec suite and a fuzz campaign against each built-in engine, joined into one
# report in BUILD/report (index.html, report.json, junit.xml).
#
# Exit 0 when every run completed: findings — a failing case, a fuzz failure — are what the run is
# for, not a failure of it (check and fuzz exit 1 for them). Any other exit (bad usage, an input
# that cannot be read, a crash of cyclecert itself) stops the job with that status.
set -uo pipefail
if [ ! -d specs/cases ]; then
  echo "main-job.sh: run it from the repository's root (make run does)" >&2
  exit 2
fi
build=${1:-build}
fuzz_seconds=${FUZZ_SECONDS:-30}
cli="$build/cyclecert"
report="$build/report"
runs="$report/runs"
rm -rf "$report"
mkdir -p "$runs"

step() {
  echo "== $*"
  "$@"
  local status=$?
  if [ "$status" -gt 1 ]; then
    echo "make run: '$*' stopped with exit $status" >&2
    exit "$status"
  fi
}

engines=(reference linuxcnc)
for engine in "${engines[@]}"; do
  # Paths relative to the repository, so that the report names files as a reader finds them.
  step "$cli" check --engine "$engine" --specs specs --regressions corpus/regressions --out "$runs/check-$engine"
done
# The field corpus (corpus/field/manifest.json): shop-style programs of every dialect, each judged by
# every oracle on the reference's path (the programs still pending are listed, not run).
python3 corpus/field/field_cases.py "$build/field-cases" || exit 2
step "$cli" check --engine reference --specs specs --regressions "$build/field-cases" --out "$runs/check-field-reference"
for engine in "${engines[@]}"; do
  # rs274 answers in milliseconds; a case it has not answered in 2 s hangs (README: LinuxCNC findings).
  step "$cli" fuzz --engine "$engine" --seed 1 --time "$fuzz_seconds" --timeout 2 --out "$runs/fuzz-$engine" \
    --regressions "$report/regressions"
done
# A second, short campaign per engine of G73 cases (pattern repeating: `fuzz --cycles g73`), under
# its own seed so that its cases are named apart from the first campaign's. The two campaigns of an
# engine are joined knowingly (--mix-campaigns): both are this job's, run just now.
g73_seconds=${FUZZ_G73_SECONDS:-$(( (fuzz_seconds + 5) / 6 ))}
for engine in "${engines[@]}"; do
  step "$cli" fuzz --engine "$engine" --cycles g73 --seed 73 --time "$g73_seconds" --timeout 2 \
    --out "$runs/fuzz-g73-$engine" --regressions "$report/regressions"
done
# And a SINUMERIK campaign (LCYC95 and CYCLE95, `fuzz --cycles siemens`) for the reference alone:
# LinuxCNC reads no Siemens dialect.
step "$cli" fuzz --engine reference --cycles siemens --seed 95 --time "$g73_seconds" --timeout 2 \
  --out "$runs/fuzz-siemens-reference" --regressions "$report/regressions"
# And a G74.1 campaign (GSK's axial groove, `fuzz --cycles g74.1`) for the reference alone: LinuxCNC
# has no G74.1.
step "$cli" fuzz --engine reference --cycles g74.1 --seed 741 --time "$g73_seconds" --timeout 2 \
  --out "$runs/fuzz-g74_1-reference" --regressions "$report/regressions"
step "$cli" merge --mix-campaigns --out "$report" "$runs"/*
step "$cli" report "$report"

# The closing lines: where the report is, and per engine the headline numbers.
python3 - "$report" <<'PY'
import json, sys
out = sys.argv[1]
report = json.load(open(f"{out}/report.json"))
nonconforming = {}
for entry in report["certification"]["nonconforming_rules"]:
    for engine in entry["engines"]:
        nonconforming[engine] = nonconforming.get(engine, 0) + 1
print(f"\nmake run: done; the report is {out}/index.html ({out}/report.json and {out}/junit.xml beside it)")
for e in report["engines"]:
    t, f = e["totals"], e["fuzz"]
    spec = f"{t['pass']} of {t['cases']} spec/regression cases pass"
    others = [f"{t[k]} {label}" for k, label in
              (("fail", "fail"), ("not_applicable", "not applicable"), ("engine_failure", "engine failure(s)")) if t[k]]
    if others:
        spec += " (" + ", ".join(others) + ")"
    fuzz = f"fuzz {f['cases']} cases, {f['fail'] + f['engine_failure']} failing"
    rules = f"{nonconforming.get(e['name'], 0)} rule(s) not conformed to"
    print(f"  {e['name']:<10} {spec}; {fuzz}; {rules}")
PY
