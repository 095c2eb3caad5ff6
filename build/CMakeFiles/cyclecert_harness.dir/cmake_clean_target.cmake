file(REMOVE_RECURSE
  "libcyclecert_harness.a"
)
