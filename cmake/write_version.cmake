# Writes ${OUT} (mrsim/version.hpp) from ${IN} with the source tree's git revision: run at
# configure time and again at every build (the mrsim_version target), so that the revision in
# log.h5, summary.json and checkpoints is that of the code built, not of the last CMake run (a
# resume refuses a checkpoint of another revision). "-dirty" marks uncommitted changes.
# configure_file() leaves ${OUT} untouched when its text is the same: nothing recompiles then.
execute_process(COMMAND git describe --always --dirty --abbrev=7
  WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE MRSIM_GIT_REVISION OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT MRSIM_GIT_REVISION)
  set(MRSIM_GIT_REVISION "unknown")
endif()
configure_file(${IN} ${OUT} @ONLY)
