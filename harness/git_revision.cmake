# Writes OUTPUT with the git revision of SOURCE_DIR: the commit, "+dirty" when the tree has changes
# (untracked files too: they are built when they are sources), "unknown" outside git. Run by every
# build (CMakeLists.txt: cyclecert_git_revision); the header is rewritten only when the revision
# changes, so that nothing recompiles otherwise.
set(revision unknown)
if(GIT_EXECUTABLE)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse HEAD
                  OUTPUT_VARIABLE head RESULT_VARIABLE failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT failed AND head)
    set(revision ${head})
    # --no-optional-locks: a build must never hold git's index lock against someone committing.
    execute_process(COMMAND ${GIT_EXECUTABLE} --no-optional-locks -C ${SOURCE_DIR} status --porcelain
                    OUTPUT_VARIABLE changes RESULT_VARIABLE failed ERROR_QUIET)
    if(failed OR NOT changes STREQUAL "")
      string(APPEND revision "+dirty")
    endif()
  endif()
endif()
file(WRITE ${OUTPUT}.new "#pragma once\n#define CYCLECERT_GIT_REVISION \"${revision}\"\n")
configure_file(${OUTPUT}.new ${OUTPUT} COPYONLY)  # copies only when the contents differ
file(REMOVE ${OUTPUT}.new)
