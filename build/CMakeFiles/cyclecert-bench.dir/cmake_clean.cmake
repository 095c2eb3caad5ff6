file(REMOVE_RECURSE
  "CMakeFiles/cyclecert-bench.dir/bench/g71_type1_bench.cpp.o"
  "CMakeFiles/cyclecert-bench.dir/bench/g71_type1_bench.cpp.o.d"
  "cyclecert-bench"
  "cyclecert-bench.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/cyclecert-bench.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
