
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/tests/gcode_lexer_test.cpp" "CMakeFiles/cyclecert-tests.dir/tests/gcode_lexer_test.cpp.o" "gcc" "CMakeFiles/cyclecert-tests.dir/tests/gcode_lexer_test.cpp.o.d"
  "/work/main/tests/gcode_parser_test.cpp" "CMakeFiles/cyclecert-tests.dir/tests/gcode_parser_test.cpp.o" "gcc" "CMakeFiles/cyclecert-tests.dir/tests/gcode_parser_test.cpp.o.d"
  "/work/main/tests/svg_test.cpp" "CMakeFiles/cyclecert-tests.dir/tests/svg_test.cpp.o" "gcc" "CMakeFiles/cyclecert-tests.dir/tests/svg_test.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build/CMakeFiles/cyclecert_harness.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/cyclecert_reference.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/cyclecert_gcode.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/cyclecert_reports.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/cyclecert_model.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
