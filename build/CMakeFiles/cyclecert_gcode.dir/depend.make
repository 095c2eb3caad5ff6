# Empty dependencies file for cyclecert_gcode.
# This may be replaced when dependencies are built.
