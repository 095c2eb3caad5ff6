
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/reference/cycles/g71.cpp" "CMakeFiles/cyclecert_reference.dir/reference/cycles/g71.cpp.o" "gcc" "CMakeFiles/cyclecert_reference.dir/reference/cycles/g71.cpp.o.d"
  "/work/main/reference/cycles/g72.cpp" "CMakeFiles/cyclecert_reference.dir/reference/cycles/g72.cpp.o" "gcc" "CMakeFiles/cyclecert_reference.dir/reference/cycles/g72.cpp.o.d"
  "/work/main/reference/cycles/monotonic_check.cpp" "CMakeFiles/cyclecert_reference.dir/reference/cycles/monotonic_check.cpp.o" "gcc" "CMakeFiles/cyclecert_reference.dir/reference/cycles/monotonic_check.cpp.o.d"
  "/work/main/reference/cycles/roughing_cycle.cpp" "CMakeFiles/cyclecert_reference.dir/reference/cycles/roughing_cycle.cpp.o" "gcc" "CMakeFiles/cyclecert_reference.dir/reference/cycles/roughing_cycle.cpp.o.d"
  "/work/main/reference/cycles/shape_program.cpp" "CMakeFiles/cyclecert_reference.dir/reference/cycles/shape_program.cpp.o" "gcc" "CMakeFiles/cyclecert_reference.dir/reference/cycles/shape_program.cpp.o.d"
  "/work/main/reference/cycles/type1_roughing.cpp" "CMakeFiles/cyclecert_reference.dir/reference/cycles/type1_roughing.cpp.o" "gcc" "CMakeFiles/cyclecert_reference.dir/reference/cycles/type1_roughing.cpp.o.d"
  "/work/main/reference/interpreter/block_motion.cpp" "CMakeFiles/cyclecert_reference.dir/reference/interpreter/block_motion.cpp.o" "gcc" "CMakeFiles/cyclecert_reference.dir/reference/interpreter/block_motion.cpp.o.d"
  "/work/main/reference/interpreter/program_runner.cpp" "CMakeFiles/cyclecert_reference.dir/reference/interpreter/program_runner.cpp.o" "gcc" "CMakeFiles/cyclecert_reference.dir/reference/interpreter/program_runner.cpp.o.d"
  "/work/main/reference/profiles/profiles.cpp" "CMakeFiles/cyclecert_reference.dir/reference/profiles/profiles.cpp.o" "gcc" "CMakeFiles/cyclecert_reference.dir/reference/profiles/profiles.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build/CMakeFiles/cyclecert_gcode.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/cyclecert_model.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
