# Writes the version header (geometry/version.cpp includes it), run at every
# build by the target hrspace_version_header (geometry/CMakeLists.txt):
#   cmake -DSOURCE_DIR=... -DOUTPUT=... -DVERSION=0.9.0 -P cmake/version.cmake
# The commit is `git rev-parse --short=7 HEAD` of SOURCE_DIR, or "unknown"
# when git is not installed or SOURCE_DIR is not a checkout (a source
# tarball). configure_file leaves the header untouched when nothing changed,
# so a build without a new commit recompiles nothing.
set(HRSPACE_COMMIT "unknown")
find_program(_git git)
if(_git AND EXISTS "${SOURCE_DIR}")
  execute_process(
    COMMAND "${_git}" -C "${SOURCE_DIR}" rev-parse --short=7 HEAD
    OUTPUT_VARIABLE _commit
    RESULT_VARIABLE _status
    ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(_status EQUAL 0 AND _commit MATCHES "^[0-9a-f]+$")
    set(HRSPACE_COMMIT "${_commit}")
  endif()
endif()
set(HRSPACE_VERSION "${VERSION}")
configure_file("${CMAKE_CURRENT_LIST_DIR}/version.h.in" "${OUTPUT}" @ONLY)
