#!/usr/bin/env python3
"""Writes each program of the field corpus (manifest.json) as a spec case whose expectation is
{"oracles": "pass"} (the form of corpus/regressions), so that `cyclecert check` runs and reports
them: python3 corpus/field/field_cases.py OUTDIR. Programs marked "pending" are left out and listed."""
import json
import os
import shutil
import sys

here = os.path.dirname(os.path.abspath(__file__))
out = sys.argv[1]
manifest = json.load(open(os.path.join(here, "manifest.json"), encoding="utf-8"))
shutil.rmtree(out, ignore_errors=True)  # no case of a program since removed
os.makedirs(os.path.join(out, "field"))
written = 0
for entry in manifest["programs"]:
    name = entry["file"].rsplit(".", 1)[0]
    if "pending" in entry or not entry["rules"]:
        print(f"  field/{name:<40} pending: {entry.get('pending', 'no rule cited yet')}")
        continue
    case = {
        "id": f"field/{name}",
        "title": f"field corpus: {entry['description']} [{entry['dialect']}]",
        "rules": entry["rules"],
        "profile": entry["profile"],
        "params": entry["params"],
        "program": open(os.path.join(here, entry["file"]), encoding="utf-8").read(),
        "expect": {"oracles": "pass"},
        "derivation": "A shop-style program of corpus/field (README.md there). No toolpath is expected: "
                      "every oracle judges what the engine does.",
    }
    with open(os.path.join(out, "field", name + ".json"), "w", encoding="utf-8") as f:
        json.dump(case, f, indent=2, ensure_ascii=False)
        f.write("\n")
    written += 1
print(f"field corpus: {written} program(s) written as spec cases to {out}/field")
