# Writes OUTPUT (a C++ file) with the git commit of SOURCE_DIR and the build
# settings passed in, at build time: the commit is the one the binary was
# built from, not the one CMake was configured at. configure_file rewrites the
# file only when it changes, so an unchanged commit recompiles nothing.
#   cmake -DSOURCE_DIR=... -DOUTPUT=... -DBUILD_TYPE=... -DCOMPILER=... -DFLAGS=... -P write_build_info.cmake
set(SKETCHLAB_GIT_COMMIT "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse HEAD
                  OUTPUT_VARIABLE _commit RESULT_VARIABLE _rc ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  # Only when SOURCE_DIR is the top of its own checkout (not a tarball
  # unpacked inside some other repository).
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse --show-toplevel
                  OUTPUT_VARIABLE _top RESULT_VARIABLE _rc_top ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(_rc EQUAL 0 AND _rc_top EQUAL 0)
    get_filename_component(_top "${_top}" REALPATH)
    get_filename_component(_src "${SOURCE_DIR}" REALPATH)
    if(_top STREQUAL _src)
      set(SKETCHLAB_GIT_COMMIT "${_commit}")
      # Tracked files changed since that commit.
      execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} status --porcelain --untracked-files=no
                      OUTPUT_VARIABLE _changes ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
      if(NOT _changes STREQUAL "")
        set(SKETCHLAB_GIT_COMMIT "${_commit}-dirty")
      endif()
    endif()
  endif()
endif()
set(SKETCHLAB_BUILD_TYPE_TEXT "${BUILD_TYPE}")
set(SKETCHLAB_COMPILER_TEXT "${COMPILER}")
string(REPLACE "\\" "\\\\" SKETCHLAB_FLAGS_TEXT "${FLAGS}")
string(REPLACE "\"" "\\\"" SKETCHLAB_FLAGS_TEXT "${SKETCHLAB_FLAGS_TEXT}")
string(STRIP "${SKETCHLAB_FLAGS_TEXT}" SKETCHLAB_FLAGS_TEXT)
configure_file(${CMAKE_CURRENT_LIST_DIR}/build_info.cpp.in ${OUTPUT} @ONLY)
