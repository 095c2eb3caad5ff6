file(REMOVE_RECURSE
  "CMakeFiles/cyclecert_gcode.dir/reference/gcode/address_ranges.cpp.o"
  "CMakeFiles/cyclecert_gcode.dir/reference/gcode/address_ranges.cpp.o.d"
  "CMakeFiles/cyclecert_gcode.dir/reference/gcode/lexer.cpp.o"
  "CMakeFiles/cyclecert_gcode.dir/reference/gcode/lexer.cpp.o.d"
  "CMakeFiles/cyclecert_gcode.dir/reference/gcode/parser.cpp.o"
  "CMakeFiles/cyclecert_gcode.dir/reference/gcode/parser.cpp.o.d"
  "libcyclecert_gcode.a"
  "libcyclecert_gcode.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/cyclecert_gcode.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
