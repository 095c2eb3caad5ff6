file(REMOVE_RECURSE
  "libcyclecert_reference.a"
)
