#!/bin/sh
# Answers every case with a line that is not JSON.
while read -r line; do echo "hello, I am not JSON"; done
