#!/usr/bin/env bash
# Builds the fuzz targets' seed corpora, tests/fuzz/corpus/TARGET/, from the spec cases (specs/cases),
# the regressions (corpus/regressions), the example programs (corpus/*.nc, corpus/field), the
# report fixture's results (tests/data/report/source/results.jsonl) and a LinuxCNC canonical output,
# each minimised by its target (-merge=1: only inputs that add coverage are kept).
#   tools/fuzz-seed-corpus.sh [FUZZ_BUILD]     (default build-fuzz; make fuzz-build first)
# It replaces the corpora: run it when the readers change much, then `make fuzz` grows them.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-fuzz}
raw=$(mktemp -d "${TMPDIR:-/tmp}/cyclecert-seeds.XXXXXX")
trap 'rm -rf "$raw"' EXIT

python3 - "$raw" <<'PY'
import glob, hashlib, json, os, sys

raw = sys.argv[1]
# tests/fuzz/fuzz_input.h: the first byte picks the setting (fanucSettings, then allSettings).
FANUC = ["fanuc-0i-f", "fanuc-0i-c", "gsk", "hnc", "haas"]
SIEMENS = ["sinumerik-802s", "sinumerik-802d"]

def put(target, data):
    if isinstance(data, str):
        data = data.encode("utf-8", "surrogateescape")
    os.makedirs(os.path.join(raw, target), exist_ok=True)
    name = hashlib.sha1(data).hexdigest()
    with open(os.path.join(raw, target, name), "wb") as f:
        f.write(data)

def setting_index(profile, params):
    def on(*names):
        return any(float(params.get(n, 0)) == 1 for n in names)
    if profile in SIEMENS:
        return len(FANUC) + 3 + SIEMENS.index(profile)
    if profile == "fanuc-0i-f" and on("FCV", "0001#1"): return 5
    if profile == "fanuc-0i-f" and on("GSC", "3401#7"): return 7
    if profile == "fanuc-0i-f" and on("GSB", "3401#6"): return 6
    return FANUC.index(profile) if profile in FANUC else 0

def program_seeds(profile, params, program, subprograms):
    index = setting_index(profile, params)
    if profile in SIEMENS:
        printed = program + "".join("\n%s.spf\n%s" % (name, text) for name, text in subprograms.items())
        put("siemens-read", bytes([SIEMENS.index(profile)]) + printed.encode())
        put("plan", bytes([index]) + printed.encode())
    else:
        put("gcode-read", bytes([index]) + program.encode())
        put("plan", bytes([index]) + program.encode())

cases = sorted(glob.glob("specs/cases/**/*.json", recursive=True) + glob.glob("corpus/regressions/**/*.json", recursive=True))
for path in cases:
    text = open(path, encoding="utf-8").read()
    put("spec-case", text)
    try:
        case = json.loads(text)
    except ValueError:
        continue
    params = case.get("params", {}) if isinstance(case.get("params"), dict) else {}
    program_seeds(case.get("profile", "fanuc-0i-f"), params, case.get("program", ""), case.get("subprograms", {}) or {})
    expect = case.get("expect", {})
    if isinstance(expect, dict) and isinstance(expect.get("toolpath"), list):
        toolpath = {"profile": case.get("profile"), "units": "mm", "moves": expect["toolpath"]}
        put("toolpath-json", json.dumps(toolpath))
        put("process-reply", json.dumps({"request": 1, "toolpath": toolpath}))
    if isinstance(expect, dict) and isinstance(expect.get("alarm"), dict):
        put("process-reply", json.dumps({"request": 1, "alarm": expect["alarm"]}))
for reply in ({"request": 1, "not_applicable": "no G73"}, {"request": 1, "error": "out of memory"}, {"request": 2, "toolpath": {}}):
    put("process-reply", json.dumps(reply))

# corpus/field/README.md's table gives each field program's profile and parameters.
field = {}
for row in open("corpus/field/README.md", encoding="utf-8"):
    cells = [c.strip() for c in row.split("|")]
    if len(cells) > 5 and cells[1].startswith("[") and ".nc]" in cells[1]:
        name = cells[1][1:cells[1].index("]")]
        params = dict(p.split("=", 1) for p in cells[4].replace("--param", "").split() if "=" in p)
        field[name] = (cells[3].strip("`"), params)
for path in sorted(glob.glob("corpus/*.nc") + glob.glob("corpus/field/**/*.nc", recursive=True)):
    program = open(path, encoding="utf-8", errors="surrogateescape").read()
    profile, params = field.get(os.path.basename(path), ("fanuc-0i-f", {}))
    for line in program.splitlines()[:5]:
        if "(profile:" in line:
            profile = line.split("(profile:")[1].split(")")[0].strip()
    program_seeds(profile, params, program, {})

results = open("tests/data/report/source/results.jsonl", encoding="utf-8").read().splitlines()
put("results", "\n".join(results) + "\n")
for line in results:
    put("results", line + "\n")

put("linuxcnc-canon", """    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    7 N..... SELECT_PLANE(CANON_PLANE_XZ)
   10 N..... STRAIGHT_TRAVERSE(18.0000, 0.0000, 2.0000, 0.0000, 0.0000, 0.0000)
   11 N..... COMMENT("cyclecert: cycle")
   12 N..... SET_FEED_RATE(0.2000)
   14 N..... STRAIGHT_TRAVERSE(18.2000, 0.0000, 2.1000, 0.0000, 0.0000, 0.0000)
(0.1,18.2) (2.1,18.2)
   16 N..... STRAIGHT_FEED(-0.0000, 0.0000, 2.1000, 0.0000, 0.0000, 0.0000)
   18 N..... ARC_FEED(-15.0000, 5.0000, -10.0000, 5.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   19 N..... ARC_FEED(-20.0000, 0.0000, -20.0000, 5.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)
   21 N..... COMMENT("cyclecert: return")
   22 N..... STRAIGHT_TRAVERSE(18.0000, 0.0000, -20.0000, 0.0000, 0.0000, 0.0000)
   23 N..... COMMENT("cyclecert: end")
""")
put("linuxcnc-canon", "G71 cycle: bad pocket\nN20 G01 X10\n")
PY

for dir in "$raw"/*/; do
  target=$(basename "$dir")
  binary="$build/fuzz-$target"
  [ -x "$binary" ] || { echo "fuzz-seed-corpus: $binary is missing (make fuzz-build)" >&2; exit 1; }
  corpus="tests/fuzz/corpus/$target"
  rm -rf "$corpus"
  mkdir -p "$corpus"
  "$binary" -merge=1 -timeout=10 -rss_limit_mb=2048 -close_fd_mask=1 "$corpus" "$dir" > "$raw/$target.log" 2>&1 ||
    { echo "fuzz-seed-corpus: merging $target failed:" >&2; tail -20 "$raw/$target.log" >&2; exit 1; }
  echo "fuzz-seed-corpus: $target: $(ls "$dir" | wc -l) seeds, $(ls "$corpus" | wc -l) kept"
done
