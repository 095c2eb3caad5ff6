file(REMOVE_RECURSE
  "CMakeFiles/cyclecert.dir/harness/cli/main.cpp.o"
  "CMakeFiles/cyclecert.dir/harness/cli/main.cpp.o.d"
  "cyclecert"
  "cyclecert.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/cyclecert.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
