file(REMOVE_RECURSE
  "libcyclecert_reports.a"
)
