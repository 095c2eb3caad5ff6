
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/harness/reference_plan.cpp" "CMakeFiles/cyclecert_harness.dir/harness/reference_plan.cpp.o" "gcc" "CMakeFiles/cyclecert_harness.dir/harness/reference_plan.cpp.o.d"
  "/work/main/harness/rule_catalogue.cpp" "CMakeFiles/cyclecert_harness.dir/harness/rule_catalogue.cpp.o" "gcc" "CMakeFiles/cyclecert_harness.dir/harness/rule_catalogue.cpp.o.d"
  "/work/main/harness/spec_case.cpp" "CMakeFiles/cyclecert_harness.dir/harness/spec_case.cpp.o" "gcc" "CMakeFiles/cyclecert_harness.dir/harness/spec_case.cpp.o.d"
  "/work/main/harness/spec_check.cpp" "CMakeFiles/cyclecert_harness.dir/harness/spec_check.cpp.o" "gcc" "CMakeFiles/cyclecert_harness.dir/harness/spec_check.cpp.o.d"
  "/work/main/harness/toolpath_compare.cpp" "CMakeFiles/cyclecert_harness.dir/harness/toolpath_compare.cpp.o" "gcc" "CMakeFiles/cyclecert_harness.dir/harness/toolpath_compare.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build/CMakeFiles/cyclecert_reference.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/cyclecert_reports.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/cyclecert_gcode.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/cyclecert_model.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
