file(REMOVE_RECURSE
  "libcyclecert_model.a"
)
