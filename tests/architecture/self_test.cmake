# The architecture test must fail on a violation: check_includes.cmake runs over the small tree in
# fixture/ (files never compiled) whose files break the layers in each way, with one excepted file
# and one stale exception, and over fixture_rows/ with two tables whose rows are wrong (one allows
# what no file includes, one names a layer above it); this script checks that it fails and names each
# case exactly.
#
#   cmake -DCHECK=<check_includes.cmake> -DFIXTURE=<fixture dir> -P self_test.cmake  (fixture_rows/ beside it)
cmake_minimum_required(VERSION 3.25)

execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${FIXTURE} -DPARTIAL=ON
                        -DEXCEPTIONS=app/views/excepted.cpp,pipeline/clean.h -P ${CHECK}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(text "${out}${err}")
set(failures "")
if(result EQUAL 0)
  string(APPEND failures "the check passed on a tree that breaks the layers\n")
endif()
foreach(expected
    "pipeline/uses_gl.cpp: #include <GL/gl.h>: a GL, window, context or UI header"
    "pipeline/uses_views.h: #include \"app/views/display_list.h\": a layer above pipeline/"
    "app/views/uses_imgui.cpp: #include \"imgui_internal.h\": a GL, window, context or UI header"
    "app/views/uses_render.cpp: #include \"app/render/view_renderer.h\": a layer above app/views/"
    "app/views/uses_render.cpp: #include <glad/gl.h>: a GL, window, context or UI header"
    "app/views/excepted.cpp: #include <GLFW/glfw3.h>"  # reported as excepted, not as an error
    "app/fonts/uses_glfw.cpp: #include <GLFW/glfw3.h>: a GL, window, context or UI header"
    "nothing forbidden")  # the stale exception (CMake wraps the message's plain text)
  string(FIND "${text}" "${expected}" at)
  if(at EQUAL -1)
    string(APPEND failures "missing from the output: ${expected}\n")
  endif()
endforeach()
# Allowed includes are not reported: the project's own layers below, system and library headers,
# and an #include in a comment.
foreach(unexpected "#include \"pipeline/math.h\"" "#include <glm/glm.hpp>" "#include \"app/views/views.h\"" "#include <imgui.h>"
                   "#include \"pipeline/clean.h\"")
  string(FIND "${text}" "${unexpected}" at)
  if(NOT at EQUAL -1)
    string(APPEND failures "reported although allowed: ${unexpected}\n")
  endif()
endforeach()
# The excepted file is listed as excepted, before the errors, and not among them.
string(FIND "${text}" "break the layers" errors_at)
string(FIND "${text}" "app/views/excepted.cpp: #include" excepted_at REVERSE)
if(errors_at EQUAL -1 OR NOT excepted_at LESS errors_at)
  string(APPEND failures "the excepted file is reported among the errors\n")
endif()
# The stale exception is named after its heading.
string(FIND "${text}" "nothing forbidden" stale_at)
string(FIND "${text}" "  pipeline/clean.h" clean_at REVERSE)
if(stale_at EQUAL -1 OR NOT clean_at GREATER stale_at)
  string(APPEND failures "the stale exception pipeline/clean.h is not named\n")
endif()
# Without PARTIAL, a directory of sources that no layer names is an error of its own.
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${FIXTURE} -P ${CHECK}
                RESULT_VARIABLE unlisted_result OUTPUT_VARIABLE unlisted_out ERROR_VARIABLE unlisted_err)
string(FIND "${unlisted_out}${unlisted_err}" "app/unlisted/ holds sources but is no layer" unlisted_at)
if(unlisted_result EQUAL 0 OR unlisted_at EQUAL -1)
  string(APPEND failures "a directory that no layer names is not reported: ${unlisted_out}${unlisted_err}\n")
endif()
# Each row is exact: a layer allowed but never included, and an outside library allowed but never
# included, are errors; a row naming a layer above it is an error before any file is read.
get_filename_component(here "${FIXTURE}" DIRECTORY)
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${here}/fixture_rows -DLAYERS=${here}/rows_unused.cmake -P ${CHECK}
                RESULT_VARIABLE unused_result OUTPUT_VARIABLE unused_out ERROR_VARIABLE unused_err)
foreach(expected "high/ allows mid/, which none of its files includes" "high/ allows gl, which none of its files includes")
  string(FIND "${unused_out}${unused_err}" "${expected}" at)
  if(unused_result EQUAL 0 OR at EQUAL -1)
    string(APPEND failures "an allowance no file uses is not reported (${expected}): ${unused_out}${unused_err}\n")
  endif()
endforeach()
string(FIND "${unused_out}${unused_err}" "mid/ allows" mid_at)
if(NOT mid_at EQUAL -1)
  string(APPEND failures "mid/'s row is exact but reported: ${unused_out}${unused_err}\n")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${here}/fixture_rows -DLAYERS=${here}/rows_order.cmake -P ${CHECK}
                RESULT_VARIABLE order_result OUTPUT_VARIABLE order_out ERROR_VARIABLE order_err)
string(FIND "${order_out}${order_err}" "low/ may use high/, which is not a layer below it" order_at)
if(order_result EQUAL 0 OR order_at EQUAL -1)
  string(APPEND failures "a row naming a layer above it is not reported: ${order_out}${order_err}\n")
endif()
if(failures)
  message(FATAL_ERROR "check_includes.cmake does not report the fixture's violations as it should:\n${failures}\nIts output was:\n${text}")
endif()
message(STATUS "check_includes.cmake fails on the fixture and names each violation")
