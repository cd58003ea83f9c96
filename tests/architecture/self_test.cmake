# The architecture test must fail on a violation: check_includes.cmake runs over the small tree in
# fixture/ (files never compiled) whose files break the layers in each way, with one excepted file
# and one stale exception, and this script checks that it fails and names each case exactly.
#
#   cmake -DCHECK=<check_includes.cmake> -DFIXTURE=<fixture dir> -P self_test.cmake
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
if(failures)
  message(FATAL_ERROR "check_includes.cmake does not report the fixture's violations as it should:\n${failures}\nIts output was:\n${text}")
endif()
message(STATUS "check_includes.cmake fails on the fixture and names each violation")
