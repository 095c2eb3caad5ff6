file(REMOVE_RECURSE
  "CMakeFiles/cyclecert-tests.dir/tests/gcode_lexer_test.cpp.o"
  "CMakeFiles/cyclecert-tests.dir/tests/gcode_lexer_test.cpp.o.d"
  "CMakeFiles/cyclecert-tests.dir/tests/gcode_parser_test.cpp.o"
  "CMakeFiles/cyclecert-tests.dir/tests/gcode_parser_test.cpp.o.d"
  "CMakeFiles/cyclecert-tests.dir/tests/svg_test.cpp.o"
  "CMakeFiles/cyclecert-tests.dir/tests/svg_test.cpp.o.d"
  "cyclecert-tests"
  "cyclecert-tests.pdb"
  "cyclecert-tests[1]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/cyclecert-tests.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
