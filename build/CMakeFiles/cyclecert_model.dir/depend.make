# Empty dependencies file for cyclecert_model.
# This may be replaced when dependencies are built.
