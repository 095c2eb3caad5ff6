file(REMOVE_RECURSE
  "CMakeFiles/cyclecert_model.dir/reference/model/alarms.cpp.o"
  "CMakeFiles/cyclecert_model.dir/reference/model/alarms.cpp.o.d"
  "CMakeFiles/cyclecert_model.dir/reference/model/contour.cpp.o"
  "CMakeFiles/cyclecert_model.dir/reference/model/contour.cpp.o.d"
  "CMakeFiles/cyclecert_model.dir/reference/model/geometry.cpp.o"
  "CMakeFiles/cyclecert_model.dir/reference/model/geometry.cpp.o.d"
  "CMakeFiles/cyclecert_model.dir/reference/model/params.cpp.o"
  "CMakeFiles/cyclecert_model.dir/reference/model/params.cpp.o.d"
  "CMakeFiles/cyclecert_model.dir/reference/model/program.cpp.o"
  "CMakeFiles/cyclecert_model.dir/reference/model/program.cpp.o.d"
  "CMakeFiles/cyclecert_model.dir/reference/model/toolpath.cpp.o"
  "CMakeFiles/cyclecert_model.dir/reference/model/toolpath.cpp.o.d"
  "CMakeFiles/cyclecert_model.dir/reference/model/toolpath_json.cpp.o"
  "CMakeFiles/cyclecert_model.dir/reference/model/toolpath_json.cpp.o.d"
  "libcyclecert_model.a"
  "libcyclecert_model.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/cyclecert_model.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
