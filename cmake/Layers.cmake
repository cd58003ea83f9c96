# The layers in the build (docs/architecture.md): each directory of cmake/layers.cmake is one library
# that links exactly the layers of its row, and every include is checked against the table before
# anything compiles, so a forbidden include fails the build (not only the test architecture.includes).
#
#   vplab_layer_target(<dir> <out>)        the library of a layer: base -> vplab_base,
#                                          app/views -> vplab_views, app/commands -> vplab_commands
#   vplab_add_layer(<dir> [sources...])    the layer's library (an interface library without sources),
#                                          the project's root on its include path, linking PUBLIC the
#                                          libraries of the layers its row names
#   vplab_link_layers(<target> <dir>)      the same links for another target of the layer (an executable)
include(${PROJECT_SOURCE_DIR}/cmake/layers.cmake)

# The check, once per change of any file of a layer or of the table.
set(VPLAB_LAYER_GLOBS "")
foreach(dir IN LISTS layers)
  foreach(ext h hpp cpp inl inc)
    list(APPEND VPLAB_LAYER_GLOBS "${PROJECT_SOURCE_DIR}/${dir}/*.${ext}")
  endforeach()
endforeach()
file(GLOB_RECURSE VPLAB_LAYER_FILES CONFIGURE_DEPENDS ${VPLAB_LAYER_GLOBS})
set(VPLAB_LAYERS_STAMP ${PROJECT_BINARY_DIR}/layers-checked.stamp)
add_custom_command(
  OUTPUT ${VPLAB_LAYERS_STAMP}
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -P ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake
  COMMAND ${CMAKE_COMMAND} -E touch ${VPLAB_LAYERS_STAMP}
  DEPENDS ${VPLAB_LAYER_FILES} ${PROJECT_SOURCE_DIR}/cmake/layers.cmake ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake
  COMMENT "Checking every include against its layer's row (cmake/layers.cmake)")
add_custom_target(vplab_layers_checked DEPENDS ${VPLAB_LAYERS_STAMP})

function(vplab_layer_target dir out)
  string(REGEX REPLACE "^app/" "" name "${dir}")
  set(${out} vplab_${name} PARENT_SCOPE)
endfunction()

function(vplab_link_layers target dir)
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    set(scope INTERFACE)
  elseif(type STREQUAL "EXECUTABLE")
    set(scope PRIVATE)
  else()
    set(scope PUBLIC)
  endif()
  foreach(used IN LISTS uses_${dir})
    string(REGEX REPLACE "/$" "" used "${used}")
    if(NOT used STREQUAL dir)
      vplab_layer_target(${used} library)
      target_link_libraries(${target} ${scope} ${library})
    endif()
  endforeach()
  add_dependencies(${target} vplab_layers_checked)
endfunction()

function(vplab_add_layer dir)
  if(NOT dir IN_LIST layers)
    message(FATAL_ERROR "vplab_add_layer: ${dir} is no layer of cmake/layers.cmake")
  endif()
  vplab_layer_target(${dir} target)
  if(ARGN)
    add_library(${target} STATIC ${ARGN})
    target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR})
    vplab_target_options(${target})
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${PROJECT_SOURCE_DIR})
  endif()
  vplab_link_layers(${target} ${dir})
endfunction()
