#!/usr/bin/env python3
"""examples/engine.py with one fault on one case: faulty.py FAULT CASE_ID CYCLECERT.
Every other case gets the reference's answer, so a shift of replies onto the wrong case shows.

FAULT (on the case whose "id" is CASE_ID):
  json-before      a JSON line ({"progress": 50}) before the reply
  log-before       a log line before the reply
  json-after       the reply twice, in one write
  log-after        a log line after the reply, in one write
  late-json-after  the reply, then 0.3 s later the reply again (the next request is waiting by then)
  late-log-after   the reply, then 0.3 s later a log line
  close-stdout     closes its stdout and sleeps
  hang             never replies
  crash            exits with status 3
  flood            endless output without a newline
  flood-lines      endless lines
  nan              a reply with the token NaN as a coordinate
  stop-reading     the reply, then never reads its stdin again
"""
import importlib.util, json, os, sys, time

spec = importlib.util.spec_from_file_location(
    "engine", os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../examples/engine.py"))
engine = importlib.util.module_from_spec(spec)
sys.argv = [sys.argv[0], sys.argv[3]] + sys.argv[1:3]
spec.loader.exec_module(engine)
fault, target = sys.argv[2], sys.argv[3]


def send(text):
    sys.stdout.write(text)
    sys.stdout.flush()


for line in sys.stdin:
    case = json.loads(line)
    reply = json.dumps({**engine.plan(case), "request": case["request"]}) + "\n"
    if case["id"] != target:
        send(reply)
    elif fault == "json-before":
        send('{"progress": 50}\n' + reply)
    elif fault == "log-before":
        send("planning the case...\n" + reply)
    elif fault == "json-after":
        send(reply + reply)
    elif fault == "log-after":
        send(reply + "done planning\n")
    elif fault == "late-json-after":
        send(reply)
        time.sleep(0.3)
        send(reply)
    elif fault == "late-log-after":
        send(reply)
        time.sleep(0.3)
        send("done planning\n")
    elif fault == "close-stdout":
        os.close(1)
        time.sleep(600)
    elif fault == "hang":
        time.sleep(600)
    elif fault == "crash":
        os._exit(3)
    elif fault == "flood":
        while True:
            send("x" * 65536)
    elif fault == "flood-lines":
        while True:
            send("flood\n" * 10000)
    elif fault == "stop-reading":
        send(reply)
        time.sleep(600)
    elif fault == "nan":
        send('{"request": %d, "toolpath": {"moves": [{"kind": "feed", "to": {"x": NaN, "z": 1}}]}}\n' % case["request"])
