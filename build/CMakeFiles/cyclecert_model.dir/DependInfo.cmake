
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/reference/model/alarms.cpp" "CMakeFiles/cyclecert_model.dir/reference/model/alarms.cpp.o" "gcc" "CMakeFiles/cyclecert_model.dir/reference/model/alarms.cpp.o.d"
  "/work/main/reference/model/contour.cpp" "CMakeFiles/cyclecert_model.dir/reference/model/contour.cpp.o" "gcc" "CMakeFiles/cyclecert_model.dir/reference/model/contour.cpp.o.d"
  "/work/main/reference/model/geometry.cpp" "CMakeFiles/cyclecert_model.dir/reference/model/geometry.cpp.o" "gcc" "CMakeFiles/cyclecert_model.dir/reference/model/geometry.cpp.o.d"
  "/work/main/reference/model/params.cpp" "CMakeFiles/cyclecert_model.dir/reference/model/params.cpp.o" "gcc" "CMakeFiles/cyclecert_model.dir/reference/model/params.cpp.o.d"
  "/work/main/reference/model/program.cpp" "CMakeFiles/cyclecert_model.dir/reference/model/program.cpp.o" "gcc" "CMakeFiles/cyclecert_model.dir/reference/model/program.cpp.o.d"
  "/work/main/reference/model/toolpath.cpp" "CMakeFiles/cyclecert_model.dir/reference/model/toolpath.cpp.o" "gcc" "CMakeFiles/cyclecert_model.dir/reference/model/toolpath.cpp.o.d"
  "/work/main/reference/model/toolpath_json.cpp" "CMakeFiles/cyclecert_model.dir/reference/model/toolpath_json.cpp.o" "gcc" "CMakeFiles/cyclecert_model.dir/reference/model/toolpath_json.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
