#!/usr/bin/env python3
"""Validate cyclecert reports.

    python3 validate_report.py SCHEMA REPORT_JSON...

Checks each report.json:
  - it is JSON and conforms to SCHEMA (specs/schema/report.schema.json, JSON Schema draft 2020-12);
  - every totals object adds up (cases = pass + fail + not_applicable + engine_failure), and the
    certification's totals are the engines' summed;
  - every engine gives a verdict for each rule of "rules", in the same order;
  - the certification's nonconforming rules are exactly the rules some engine fails.

Prints one line per error, `file: path-in-document: message`, then a count. Exits 1 on any error,
2 on a usage error (unreadable or invalid schema), 0 otherwise.
Needs the `jsonschema` module (Debian: python3-jsonschema).
"""
import argparse
import json
import sys
from pathlib import Path

try:
    from jsonschema import Draft202012Validator
except ImportError:  # pragma: no cover
    sys.exit("validate_report.py: the jsonschema module is missing (Debian: apt-get install python3-jsonschema)")

VERDICT_COUNTS = ("pass", "fail", "not_applicable", "engine_failure")


def pointer(path):
    return "/" + "/".join(str(p) for p in path)


def totals_errors(totals, where):
    if not isinstance(totals, dict) or not all(isinstance(totals.get(k), int) for k in ("cases",) + VERDICT_COUNTS):
        return []  # the schema reports it
    if totals["cases"] != sum(totals[k] for k in VERDICT_COUNTS):
        return [(where, f"cases {totals['cases']} is not pass + fail + not_applicable + engine_failure")]
    return []


def consistency_errors(doc):
    """What the schema cannot say: counts that add up, one verdict per rule, the nonconforming list."""
    errors = []
    try:
        engines = doc["engines"]
        rule_ids = [r["id"] for r in doc["rules"]]
        certification = doc["certification"]
    except (KeyError, TypeError):
        return errors  # the schema reports it
    summed = dict.fromkeys(("cases",) + VERDICT_COUNTS, 0)
    failing = {}
    for i, engine in enumerate(engines):
        try:
            errors += totals_errors(engine["totals"], f"/engines/{i}/totals")
            errors += totals_errors(engine["fuzz"], f"/engines/{i}/fuzz")
            for key in summed:
                summed[key] += engine["totals"][key]
            if [r["id"] for r in engine["rules"]] != rule_ids:
                errors.append((f"/engines/{i}/rules", "not one verdict per rule of /rules, in its order"))
            for r in engine["rules"]:
                if r["verdict"] == "fail":
                    failing.setdefault(r["id"], []).append(engine["name"])
        except (KeyError, TypeError):
            continue
    try:
        errors += totals_errors(certification["totals"], "/certification/totals")
        if certification["totals"] != summed:
            errors.append(("/certification/totals", f"not the engines' totals summed ({summed})"))
        listed = {r["rule"]: r["engines"] for r in certification["nonconforming_rules"]}
        if listed != failing:
            errors.append(("/certification/nonconforming_rules", f"not the rules the engines fail ({failing})"))
    except (KeyError, TypeError):
        pass
    return errors


def main(argv=None):
    ap = argparse.ArgumentParser(description="Validate cyclecert report.json files.")
    ap.add_argument("schema", type=Path, help="specs/schema/report.schema.json")
    ap.add_argument("reports", type=Path, nargs="+", help="report.json files")
    args = ap.parse_args(argv)
    try:
        schema = json.loads(args.schema.read_text(encoding="utf-8"))
        Draft202012Validator.check_schema(schema)
    except Exception as e:  # noqa: BLE001 - any failure here is a usage error
        print(f"{args.schema}: invalid schema: {e}", file=sys.stderr)
        return 2
    validator = Draft202012Validator(schema)
    n_errors = 0
    for path in args.reports:
        try:
            doc = json.loads(path.read_text(encoding="utf-8"))
        except (ValueError, OSError) as e:
            errors = [("/", f"not valid JSON: {e}")]
        else:
            errors = [(pointer(e.absolute_path), e.message) for e in validator.iter_errors(doc)]
            errors = sorted(errors) + consistency_errors(doc)
        for where, msg in errors:
            print(f"{path}: {where}: {msg}")
        n_errors += len(errors)
    print(f"validate_report: {len(args.reports)} report(s), {n_errors} error(s)")
    return 1 if n_errors else 0


if __name__ == "__main__":
    sys.exit(main())
