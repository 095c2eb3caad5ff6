#!/bin/sh
# Reads a case and never answers.
read -r line
exec sleep 600
