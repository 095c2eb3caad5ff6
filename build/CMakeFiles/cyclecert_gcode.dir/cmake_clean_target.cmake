file(REMOVE_RECURSE
  "libcyclecert_gcode.a"
)
