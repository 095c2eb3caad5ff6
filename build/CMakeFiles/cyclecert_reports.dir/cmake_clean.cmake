file(REMOVE_RECURSE
  "CMakeFiles/cyclecert_reports.dir/reports/svg/toolpath_svg.cpp.o"
  "CMakeFiles/cyclecert_reports.dir/reports/svg/toolpath_svg.cpp.o.d"
  "libcyclecert_reports.a"
  "libcyclecert_reports.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/cyclecert_reports.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
