# Empty dependencies file for cyclecert-bench.
# This may be replaced when dependencies are built.
