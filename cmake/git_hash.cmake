# Writes OUT, a header that defines WIREPACK_GIT: the short hash of the source tree's HEAD, with
# "-dirty" when the sources built into wirepack differ from it (tracked changes or new files under
# the layers' directories), "unknown" outside a git checkout. CMakeLists.txt runs it at every
# build (target wirepack_git); OUT is rewritten only when its text changes, so a build with the
# same hash recompiles nothing.
#   cmake -DSOURCE_DIR=... -DOUT=... -P cmake/git_hash.cmake
set(ENV{GIT_OPTIONAL_LOCKS} 0)  # git status must not take the index lock from a concurrent git
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY "${SOURCE_DIR}"
                OUTPUT_VARIABLE hash OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR "${hash}" STREQUAL "")
  set(hash "unknown")
else()
  execute_process(COMMAND git status --porcelain -- CMakeLists.txt cmake app engine analysis sweep
                          report
                  WORKING_DIRECTORY "${SOURCE_DIR}" OUTPUT_VARIABLE changes ERROR_QUIET)
  if(NOT "${changes}" STREQUAL "")
    string(APPEND hash "-dirty")
  endif()
endif()
set(text "// Written by cmake/git_hash.cmake at build time.\n#define WIREPACK_GIT \"${hash}\"\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE "${OUT}" "${text}")
endif()
