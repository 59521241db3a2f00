# sketchlab_add_plugin(NAME KIND <corrector|surfacer|input> SOURCES ...
#                      [LIBRARIES ...] [INCLUDES ...])
#
# Builds a sketchlab plugin: a loadable module named sketchlab_<kind>_<name>
# (the host checks that the file name matches the descriptor), linked to
# sketchlab::kernel, and installs it to <prefix>/lib/sketchlab/plugins, where
# the installed `sketchlab` looks. The sources are compiled once into the
# object library sketchlab_<kind>_<name>_impl, which tests link to call the
# plugin's free functions directly.
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
  cmake_parse_arguments(ARG "" "KIND" "SOURCES;LIBRARIES;INCLUDES" ${ARGN})
  if(NOT ARG_KIND MATCHES "^(corrector|surfacer|input)$")
    message(FATAL_ERROR "sketchlab_add_plugin(${name}): KIND must be corrector, surfacer or input, got '${ARG_KIND}'")
  endif()
  if(NOT name MATCHES "^[a-z0-9_]+$")
    message(FATAL_ERROR "sketchlab_add_plugin(${name}): NAME must be lower-case letters, digits and '_' (it is part of the file name the host checks)")
  endif()
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "sketchlab_add_plugin(${name}): SOURCES is empty")
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
endfunction()
