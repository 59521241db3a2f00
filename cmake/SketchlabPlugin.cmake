# sketchlab_add_plugin(NAME KIND <corrector|surfacer|input> SOURCES ... [LIBRARIES ...])
#
# Builds a sketchlab plugin: a loadable module named sketchlab_<kind>_<name>
# placed in <build>/lib/sketchlab/plugins (installed to the same place under
# the prefix), linked to the kernel. The sources are compiled once into the
# object library sketchlab_<kind>_<name>_impl, which tests link to call the
# plugin's free functions directly. Tests are picked up from
# tests/plugins/<kind>s/<name>/ by tests/CMakeLists.txt.
function(sketchlab_add_plugin name)
  cmake_parse_arguments(ARG "" "KIND" "SOURCES;LIBRARIES;INCLUDES" ${ARGN})
  if(NOT ARG_KIND MATCHES "^(corrector|surfacer|input)$")
    message(FATAL_ERROR "sketchlab_add_plugin(${name}): KIND must be corrector, surfacer or input, got '${ARG_KIND}'")
  endif()
  set(target sketchlab_${ARG_KIND}_${name})
  set(impl ${target}_impl)
  add_library(${impl} OBJECT ${ARG_SOURCES})
  target_link_libraries(${impl} PUBLIC sketchlab::kernel ${ARG_LIBRARIES})
  target_include_directories(${impl} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR} ${ARG_INCLUDES})
  set_target_properties(${impl} PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  sketchlab_warnings(${impl})

  add_library(${target} MODULE)
  target_link_libraries(${target} PRIVATE ${impl})
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    OUTPUT_NAME ${target}
    LIBRARY_OUTPUT_DIRECTORY ${SKETCHLAB_BUILD_PLUGIN_DIR}
    INSTALL_RPATH "$ORIGIN/../..")
  install(TARGETS ${target} LIBRARY DESTINATION ${SKETCHLAB_PLUGIN_SUBDIR})
  set_property(GLOBAL APPEND PROPERTY SKETCHLAB_PLUGINS ${target})
endfunction()
