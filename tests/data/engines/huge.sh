#!/bin/sh
# Answers with a line far beyond the size cap.
while read -r line; do head -c 200000 /dev/zero | tr '\0' 'x'; echo; done
