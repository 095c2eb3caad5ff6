# Empty dependencies file for cyclecert_harness.
# This may be replaced when dependencies are built.
