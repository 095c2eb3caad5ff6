# Empty dependencies file for cyclecert.
# This may be replaced when dependencies are built.
