#!/usr/bin/env python3
"""A cyclecert engine in 25 lines: reads one request per line (a spec case as JSON, with "request": N)
on stdin and answers one line per request on stdout, echoing "request": N. This one hands each case
to `cyclecert plan` — replace `plan()` with yours. Anything else you print goes to stderr."""
import json, subprocess, sys, tempfile

CYCLECERT = sys.argv[1] if len(sys.argv) > 1 else "build/cyclecert"

def plan(case):
    with tempfile.NamedTemporaryFile("w", suffix=".json") as file:
        json.dump(case, file)
        file.flush()
        run = subprocess.run([CYCLECERT, "plan", "--case", file.name, "--json", "-"], capture_output=True, text=True)
    if run.returncode == 3:
        return {"not_applicable": run.stderr.strip()}
    if run.returncode not in (0, 1):
        return {"error": run.stderr.strip()}
    path = json.loads(run.stdout)
    return {"alarm": path["alarm"]} if path["alarm"] else {"toolpath": path}

if __name__ == "__main__":
    for line in sys.stdin:
        case = json.loads(line)
        print(json.dumps({**plan(case), "request": case["request"]}), flush=True)
