#!/bin/sh
# A process engine that takes a quarter second over every case and then says it does not plan it:
# what an engine whose cases are slow (LinuxCNC's rs274 under load) looks like to `fuzz --time`.
while IFS= read -r line; do
  request=$(printf '%s' "$line" | sed -n 's/.*"request":\([0-9]*\).*/\1/p')
  sleep 0.25
  printf '{"not_applicable": "slow test engine", "request": %s}\n' "$request"
done
