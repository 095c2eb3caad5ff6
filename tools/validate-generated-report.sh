#!/usr/bin/env bash
# CTest's ReportSchema.GeneratedReportValidates: a real report — a mutant through `check` (every
# spec case and regression, real failures with their plots) and then a short `fuzz --resume` into
# the same run (generated failures, a second run record) — validated against
# specs/schema/report.schema.json with python3-jsonschema.
set -uo pipefail
cli=$1 out=$2 source=$3
rm -rf "$out"
"$cli" check --engine mutant:retract-angle --out "$out" >/dev/null
[ $? -eq 1 ] || { echo "check --engine mutant:retract-angle did not report failures"; exit 1; }
"$cli" fuzz --engine mutant:retract-angle --seed 3 --cases 30 --shrink-budget 10 --no-save --resume --out "$out" >/dev/null 2>&1
[ $? -eq 1 ] || { echo "fuzz --engine mutant:retract-angle did not report failures"; exit 1; }
exec python3 "$source/specs/schema/validate_report.py" "$source/specs/schema/report.schema.json" "$out/report.json"
