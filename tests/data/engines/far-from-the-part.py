#!/usr/bin/env python3
"""examples/engine.py with a fault only the metamorphic relations reach: far-from-the-part.py CYCLECERT.
On a program whose first move ends beyond z = 10 mm, every feed of the toolpath is doubled; the
spec cases the tests run start at z <= 3 mm, so the oracles see nothing — translate-z's follow-up
(Z + 12.5) starts beyond it. The in-process twin is tests/metamorphic_run_test.cpp's engine."""
import importlib.util, json, os, sys

spec = importlib.util.spec_from_file_location(
    "engine", os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../examples/engine.py"))
engine = importlib.util.module_from_spec(spec)
spec.loader.exec_module(engine)


def faulty(reply):
    moves = reply.get("toolpath", {}).get("moves", [])
    if moves and moves[0]["to"]["z"] > 10:
        for m in moves:
            if m.get("feed") is not None:
                m["feed"] *= 2
    return reply


for line in sys.stdin:
    case = json.loads(line)
    print(json.dumps({**faulty(engine.plan(case)), "request": case["request"]}), flush=True)
