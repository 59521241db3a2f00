# sketchlab_add_plugin(NAME KIND <corrector|surfacer|input> SOURCES ...
#                      [LIBRARIES ...] [INCLUDES ...]
#                      [BENCH <executable> <source> [<executable> <source> ...]])
#
# Builds a sketchlab plugin: a loadable module named sketchlab_<kind>_<name>
# (the host checks that the file name matches the descriptor), linked to
# sketchlab::kernel, and installs it to <prefix>/lib/sketchlab/plugins, where
# the installed `sketchlab` looks. The sources are compiled once into the
# object library sketchlab_<kind>_<name>_impl, which tests link to call the
# plugin's free functions directly.
#
# BENCH: benchmark programs of the plugin, one executable per (name, source)
# pair (a relative source is relative to the plugin directory), linked to the
# object library and to sketchlab::lab (replays, distributions), with
# SKETCHLAB_SOURCE_DIR set to the top source directory for bundled data;
# skipped when SKETCHLAB_BUILD_BENCH is OFF. Benchmarks print their figures
# (CPU and wall) and are not tests.
#
# The same file serves the sketchlab build (plugins/*/*: output in
# <build>/lib/sketchlab/plugins, project warnings, tests picked up from
# tests/plugins/<kind>s/<name>/ by tests/CMakeLists.txt) and plugins built
# out of tree against an installed sketchlab (find_package(sketchlab CONFIG)
# includes it; output in <build>/lib/sketchlab/plugins of that project, so
# SKETCHLAB_PLUGIN_PATH=<build>/lib/sketchlab/plugins loads it uninstalled).
# The build fingerprint comes from the installed sketchlab/build_config.hpp:
# nothing to set by hand (docs/plugin-authoring.md).
function(sketchlab_add_plugin name)
  cmake_parse_arguments(ARG "" "KIND" "SOURCES;LIBRARIES;INCLUDES;BENCH" ${ARGN})
  if(NOT ARG_KIND MATCHES "^(corrector|surfacer|input)$")
    message(FATAL_ERROR "sketchlab_add_plugin(${name}): KIND must be corrector, surfacer or input, got '${ARG_KIND}'")
  endif()
  if(NOT name MATCHES "^[a-z0-9_]+$")
    message(FATAL_ERROR "sketchlab_add_plugin(${name}): NAME must be lower-case letters, digits and '_' (it is part of the file name the host checks)")
  endif()
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "sketchlab_add_plugin(${name}): SOURCES is empty")
  endif()
  # The sketchlab tree's convention (docs/DESIGN.md): the entry point
  # (SKETCHLAB_PLUGIN) is in <name>_plugin.cpp. Plugins of other projects
  # name their files as they like.
  if(CMAKE_PROJECT_NAME STREQUAL "sketchlab" AND NOT "${name}_plugin.cpp" IN_LIST ARG_SOURCES)
    message(FATAL_ERROR "sketchlab_add_plugin(${name}): the entry point goes in ${name}_plugin.cpp, which SOURCES must list")
  endif()
  set(target sketchlab_${ARG_KIND}_${name})
  set(impl ${target}_impl)
  add_library(${impl} OBJECT ${ARG_SOURCES})
  target_link_libraries(${impl} PUBLIC sketchlab::kernel ${ARG_LIBRARIES})
  target_include_directories(${impl} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR} ${ARG_INCLUDES})
  # PIC: the objects go into a shared module (a project of its own need not
  # set CMAKE_POSITION_INDEPENDENT_CODE as the sketchlab build does).
  set_target_properties(${impl} PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
                                           POSITION_INDEPENDENT_CODE ON)
  if(COMMAND sketchlab_warnings)
    sketchlab_warnings(${impl})
  endif()

  add_library(${target} MODULE)
  target_link_libraries(${target} PRIVATE ${impl})
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    OUTPUT_NAME ${target}
    LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/${SKETCHLAB_PLUGIN_SUBDIR}
    INSTALL_RPATH "$ORIGIN/../..")
  # SKETCHLAB_PLUGIN_NO_INSTALL (a directory variable): build only.
  if(NOT SKETCHLAB_PLUGIN_NO_INSTALL)
    install(TARGETS ${target} LIBRARY DESTINATION ${SKETCHLAB_PLUGIN_SUBDIR})
  endif()
  set_property(GLOBAL APPEND PROPERTY SKETCHLAB_PLUGINS ${target})

  list(LENGTH ARG_BENCH _n)
  math(EXPR _odd "${_n} % 2")
  if(_odd)
    message(FATAL_ERROR "sketchlab_add_plugin(${name}): BENCH takes pairs <executable> <source>, got '${ARG_BENCH}'")
  endif()
  if(_n GREATER 0 AND (NOT DEFINED SKETCHLAB_BUILD_BENCH OR SKETCHLAB_BUILD_BENCH))
    math(EXPR _last "${_n} - 1")
    foreach(_i RANGE 0 ${_last} 2)
      math(EXPR _j "${_i} + 1")
      list(GET ARG_BENCH ${_i} _bench)
      list(GET ARG_BENCH ${_j} _source)
      add_executable(${_bench} ${_source})
      target_link_libraries(${_bench} PRIVATE ${impl} sketchlab::lab)
      target_compile_definitions(${_bench} PRIVATE SKETCHLAB_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
      if(COMMAND sketchlab_warnings)
        sketchlab_warnings(${_bench})
      endif()
    endforeach()
  endif()
endfunction()
