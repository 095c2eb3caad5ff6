file(REMOVE_RECURSE
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/g71.cpp.o"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/g71.cpp.o.d"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/g72.cpp.o"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/g72.cpp.o.d"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/monotonic_check.cpp.o"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/monotonic_check.cpp.o.d"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/roughing_cycle.cpp.o"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/roughing_cycle.cpp.o.d"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/shape_program.cpp.o"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/shape_program.cpp.o.d"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/type1_roughing.cpp.o"
  "CMakeFiles/cyclecert_reference.dir/reference/cycles/type1_roughing.cpp.o.d"
  "CMakeFiles/cyclecert_reference.dir/reference/interpreter/block_motion.cpp.o"
  "CMakeFiles/cyclecert_reference.dir/reference/interpreter/block_motion.cpp.o.d"
  "CMakeFiles/cyclecert_reference.dir/reference/interpreter/program_runner.cpp.o"
  "CMakeFiles/cyclecert_reference.dir/reference/interpreter/program_runner.cpp.o.d"
  "CMakeFiles/cyclecert_reference.dir/reference/profiles/profiles.cpp.o"
  "CMakeFiles/cyclecert_reference.dir/reference/profiles/profiles.cpp.o.d"
  "libcyclecert_reference.a"
  "libcyclecert_reference.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/cyclecert_reference.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
