#!/bin/sh
# Answers the first case properly (through the example engine), then never answers the second: it
# waits for input that will not come, and so ends only when its stdin closes (when the run is killed).
here=$(dirname "$0")
read -r line
printf '%s\n' "$line" | python3 "$here/../../../examples/engine.py" "$1"
read -r line
cat >/dev/null
