# Empty dependencies file for cyclecert_reference.
# This may be replaced when dependencies are built.
