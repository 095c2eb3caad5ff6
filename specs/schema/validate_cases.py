#!/usr/bin/env python3
"""Validate cyclecert spec cases.

    python3 validate_cases.py SCHEMA CASES_DIR... [--rules RULES_JSON]

Checks every *.json under each CASES_DIR (recursively):
  - it is JSON without duplicate keys;
  - it conforms to SCHEMA (JSON Schema draft 2020-12, Draft202012Validator);
  - every rule ID it cites (top-level "rules" and each move's "rules") exists in RULES_JSON
    (default: rules.json next to the schema's directory, i.e. specs/rules.json);
  - its "id" equals the file's path <profile>/<cycle>/<name> relative to CASES_DIR (without .json),
    and the first component equals its "profile";
  - no two files share an id;
and that the catalogue itself has unique rule IDs and only parents it defines.

Prints one line per error, `file: path-in-document: message`, then a count. Exits 1 on any error,
2 on a usage error (missing schema/rules file, invalid schema), 0 otherwise.
Needs the `jsonschema` module (Debian: python3-jsonschema).
"""
import argparse
import json
import sys
from pathlib import Path

try:
    from jsonschema import Draft202012Validator
except ImportError:  # pragma: no cover
    sys.exit("validate_cases.py: the jsonschema module is missing (Debian: apt-get install python3-jsonschema)")


class DuplicateKey(ValueError):
    pass


def _no_duplicates(pairs):
    obj = {}
    for key, value in pairs:
        if key in obj:
            raise DuplicateKey(f"duplicate key {key!r}")
        obj[key] = value
    return obj


def load_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f, object_pairs_hook=_no_duplicates)


def pointer(path):
    """A JSON-pointer-like rendering of a path into the document ("/" for the root)."""
    return "/" + "/".join(str(p) for p in path)


def leaf_errors(error):
    """The errors worth printing for one schema error.

    For oneOf/anyOf failures, jsonschema only says "is not valid under any of the given schemas".
    We pick the branch the instance most plausibly meant — the one whose errors reach deepest into
    the document (a case with "toolpath" fails the alarm branch at /expect but the toolpath branch
    deeper down), ties going to the branch with fewer errors — and report its errors instead.
    """
    if error.validator in ("oneOf", "anyOf") and error.context:
        branches = {}
        for sub in error.context:
            branches.setdefault(sub.relative_schema_path[0], []).append(sub)
        # A branch the instance satisfied yields no sub-errors; oneOf then failed because several
        # branches matched, and the plain message is the right one.
        if len(branches) == len(error.validator_value):
            def score(errs):
                return (-max(len(e.absolute_path) for e in errs), len(errs))
            best = min(branches.values(), key=score)
            out = []
            for sub in best:
                out.extend(leaf_errors(sub))
            return out
    if error.validator == "not" and error.validator_value == {"required": ["center"]}:
        error.message = "a line move has no center (only arc_cw/arc_ccw moves do)"
    return [error]


def case_errors(doc, rel, validator, rule_ids):
    """All errors of one case document as (path, message), sorted by path."""
    errors = []
    for err in validator.iter_errors(doc):
        for leaf in leaf_errors(err):
            errors.append((pointer(leaf.absolute_path), leaf.message))

    if not isinstance(doc, dict):
        return errors

    # id <-> file path
    expected_id = rel.with_suffix("").as_posix()
    if len(rel.parts) != 3:
        errors.append(("/", f"file must live at <profile>/<cycle>/<name>.json under the cases directory, not {rel.as_posix()}"))
    case_id = doc.get("id")
    if isinstance(case_id, str) and case_id != expected_id:
        errors.append(("/id", f"id {case_id!r} does not match the file path {expected_id!r}"))
    profile = doc.get("profile")
    if isinstance(profile, str) and len(rel.parts) == 3 and rel.parts[0] != profile:
        errors.append(("/profile", f"profile {profile!r} does not match the directory {rel.parts[0]!r}"))

    # rule IDs exist in the catalogue
    if rule_ids is not None:
        def check_ids(ids, base):
            if isinstance(ids, list):
                for i, rid in enumerate(ids):
                    if isinstance(rid, str) and rid not in rule_ids:
                        errors.append((pointer(base + [i]), f"unknown rule ID {rid!r} (not in rules.json)"))
        check_ids(doc.get("rules"), ["rules"])
        expect = doc.get("expect")
        if isinstance(expect, dict) and isinstance(expect.get("toolpath"), list):
            for k, move in enumerate(expect["toolpath"]):
                if isinstance(move, dict):
                    check_ids(move.get("rules"), ["expect", "toolpath", k, "rules"])
    return sorted(errors, key=lambda e: e[0])


def main(argv=None):
    ap = argparse.ArgumentParser(description="Validate cyclecert spec cases against the schema and the rule catalogue.")
    ap.add_argument("schema", type=Path, help="specs/schema/case.schema.json")
    ap.add_argument("cases", type=Path, nargs="+", help="one or more cases directories (e.g. specs/cases)")
    ap.add_argument("--rules", type=Path, default=None,
                    help="rule catalogue (default: rules.json in the schema directory's parent, i.e. specs/rules.json)")
    args = ap.parse_args(argv)

    try:
        schema = load_json(args.schema)
        Draft202012Validator.check_schema(schema)
    except Exception as e:  # noqa: BLE001 - any failure here is a usage error
        print(f"{args.schema}: invalid schema: {e}", file=sys.stderr)
        return 2
    validator = Draft202012Validator(schema)

    rules_path = args.rules or args.schema.resolve().parent.parent / "rules.json"
    try:
        catalogue = load_json(rules_path)
        rule_ids = {r["id"] for r in catalogue["rules"]}
    except Exception as e:  # noqa: BLE001
        print(f"{rules_path}: cannot read the rule catalogue: {e}", file=sys.stderr)
        return 2

    n_files = n_errors = n_bad = 0
    # The catalogue itself: unique IDs, parents that exist.
    catalogue_errors = []
    seen_rules = set()
    for i, r in enumerate(catalogue["rules"]):
        if r["id"] in seen_rules:
            catalogue_errors.append((f"/rules/{i}/id", f"duplicate rule ID {r['id']!r}"))
        seen_rules.add(r["id"])
        if "parent" in r and r["parent"] not in rule_ids:
            catalogue_errors.append((f"/rules/{i}/parent", f"unknown parent {r['parent']!r}"))
    for where, msg in catalogue_errors:
        print(f"{rules_path}: {where}: {msg}")
    if catalogue_errors:
        n_bad += 1
        n_errors += len(catalogue_errors)
    seen_ids = {}
    for cases_dir in args.cases:
        if not cases_dir.is_dir():
            print(f"{cases_dir}: /: not a directory")
            n_errors += 1
            n_bad += 1
            continue
        for path in sorted(cases_dir.rglob("*.json")):
            n_files += 1
            rel = path.relative_to(cases_dir)
            try:
                doc = load_json(path)
            except (ValueError, OSError) as e:
                errors = [("/", f"not valid JSON: {e}")]
            else:
                errors = case_errors(doc, rel, validator, rule_ids)
                cid = doc.get("id") if isinstance(doc, dict) else None
                if isinstance(cid, str):
                    if cid in seen_ids:
                        errors.append(("/id", f"id {cid!r} is also used by {seen_ids[cid]}"))
                    else:
                        seen_ids[cid] = path
            for where, msg in errors:
                print(f"{path}: {where}: {msg}")
            if errors:
                n_bad += 1
                n_errors += len(errors)

    print(f"validate_cases: {n_files} case file(s), {n_errors} error(s) in {n_bad} file(s)")
    return 1 if n_errors else 0


if __name__ == "__main__":
    sys.exit(main())
