# Empty dependencies file for cyclecert-tests.
# This may be replaced when dependencies are built.
