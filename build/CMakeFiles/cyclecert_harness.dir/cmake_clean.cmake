file(REMOVE_RECURSE
  "CMakeFiles/cyclecert_harness.dir/harness/reference_plan.cpp.o"
  "CMakeFiles/cyclecert_harness.dir/harness/reference_plan.cpp.o.d"
  "CMakeFiles/cyclecert_harness.dir/harness/rule_catalogue.cpp.o"
  "CMakeFiles/cyclecert_harness.dir/harness/rule_catalogue.cpp.o.d"
  "CMakeFiles/cyclecert_harness.dir/harness/spec_case.cpp.o"
  "CMakeFiles/cyclecert_harness.dir/harness/spec_case.cpp.o.d"
  "CMakeFiles/cyclecert_harness.dir/harness/spec_check.cpp.o"
  "CMakeFiles/cyclecert_harness.dir/harness/spec_check.cpp.o.d"
  "CMakeFiles/cyclecert_harness.dir/harness/toolpath_compare.cpp.o"
  "CMakeFiles/cyclecert_harness.dir/harness/toolpath_compare.cpp.o.d"
  "libcyclecert_harness.a"
  "libcyclecert_harness.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/cyclecert_harness.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
