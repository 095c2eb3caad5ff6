# Empty dependencies file for cyclecert_reports.
# This may be replaced when dependencies are built.
