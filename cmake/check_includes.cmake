# The layers (docs/architecture.md, cmake/layers.cmake): every directory of the sources may include
# only the project's directories its row of the table names, and GL, window and context headers or
# Dear ImGui only where the row allows them; base/, pipeline/ and app/views/ allow neither. This script
# fails when
#   - a file includes a GL, GLES, GLFW, GLAD, EGL, KHR, OSMesa or Dear ImGui header (<glad/gl.h>,
#     <GL/osmesa.h>, <GLFW/glfw3.h>, <EGL/egl.h>, <imgui.h>, "imgui_internal.h", …) its layer may not,
#   - a file includes a header of the project outside its layer's row ("app/render/…" from app/views/),
#   - a directory of sources is in no row (a new layer must say what it uses), or a file lies in app/
#     itself,
#   - a row names a layer above it (the table has no circle), or allows a layer or an outside library
#     that none of its files includes (each row is exact).
# Every *.h, *.hpp, *.cpp, *.inl and *.inc under the layers is read when the script runs (a new file is
# checked without configuring again); only #include lines count, not comments or strings. The build
# runs it before compiling (cmake/Layers.cmake), the test architecture.includes after.
#
#   cmake -DSOURCE_DIR=<tree> [-DLAYERS=<table>] [-DEXCEPTIONS=<file,file,…>] [-DPARTIAL=ON] -P check_includes.cmake
#   cmake -DPRINT=ON -P check_includes.cmake      prints the table as docs/architecture.md shows it
#
# LAYERS: another table than cmake/layers.cmake (the self-test's). EXCEPTIONS: files (relative to
# SOURCE_DIR) that still include such headers and are being moved (tests/CMakeLists.txt says which and
# until when); a listed file that no longer violates is an error too, so the list cannot outlive its
# reason. PARTIAL: a tree with only some of the layers (the self-test's fixture): missing directories
# and unused allowances are not errors.
cmake_minimum_required(VERSION 3.25)

if(NOT LAYERS)
  set(LAYERS ${CMAKE_CURRENT_LIST_DIR}/layers.cmake)
endif()
include(${LAYERS})

# Each row names only layers before it, so that no arrow runs back up and the table has no circle.
set(below "")
set(order_errors "")
foreach(dir IN LISTS layers)
  foreach(used IN LISTS uses_${dir})
    string(REGEX REPLACE "/$" "" used "${used}")
    if(NOT used STREQUAL dir AND NOT used IN_LIST below)
      string(APPEND order_errors "  ${dir}/ may use ${used}/, which is not a layer below it\n")
    endif()
  endforeach()
  list(APPEND below "${dir}")
endforeach()
if(order_errors AND NOT PRINT)
  message(FATAL_ERROR "${LAYERS}: a row may name only the layers listed before it:\n${order_errors}")
endif()

if(PRINT)
  # docs/architecture.md's layer table, from the table itself.
  set(table "| layer | may include | GL / ImGui | what it is |\n|---|---|---|---|\n")
  foreach(dir IN LISTS layers)
    set(name "${dir}/")
    list(JOIN uses_${dir} " " uses)
    list(JOIN outside_${dir} ", " outside)
    string(APPEND table "| `${name}` | ${uses} | ${outside} | ${about_${dir}} |\n")
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -E echo_append "${table}")
  return()
endif()

# Commas, not semicolons: a list passes through add_test and execute_process unsplit.
string(REPLACE "," ";" EXCEPTIONS "${EXCEPTIONS}")
if(NOT SOURCE_DIR OR NOT IS_DIRECTORY "${SOURCE_DIR}")
  message(FATAL_ERROR "check_includes.cmake: SOURCE_DIR \"${SOURCE_DIR}\" is not a directory")
endif()

# Every directory of sources has a row: the top level's (but the tests, the build trees and cmake/, whose web/implementations.cpp compiles libraries' code) and app/'s; no
# source lies in app/ itself.
if(NOT PARTIAL)
  file(GLOB top_dirs LIST_DIRECTORIES true RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/*")
  file(GLOB app_dirs LIST_DIRECTORIES true RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/app/*")
  foreach(d IN LISTS top_dirs app_dirs)
    if(NOT IS_DIRECTORY "${SOURCE_DIR}/${d}" OR d IN_LIST layers OR d MATCHES "^(app|tests|cmake|build.*|\\..*)$")
      continue()
    endif()
    file(GLOB_RECURSE sources "${SOURCE_DIR}/${d}/*.h" "${SOURCE_DIR}/${d}/*.cpp")
    if(sources)
      message(FATAL_ERROR "check_includes.cmake: ${d}/ holds sources but is no layer of cmake/layers.cmake: say what it may include")
    endif()
  endforeach()
  file(GLOB loose RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/app/*.h" "${SOURCE_DIR}/app/*.cpp")
  if(loose)
    message(FATAL_ERROR "check_includes.cmake: ${loose} lie in app/ itself, in no layer: put them in the layer they belong to")
  endif()
endif()

# The project's headers by their first directory; a header's layer is the longest layer it lies in.
set(tops "")
foreach(dir IN LISTS layers)
  string(REGEX REPLACE "/.*" "" top "${dir}")
  list(APPEND tops "${top}")
endforeach()
list(REMOVE_DUPLICATES tops)
list(JOIN tops "|" tops)
set(project_header_regex "^(${tops})/")

# Headers of GL and its loaders, windows and contexts; of Dear ImGui and its backends.
set(gl_header_regex "^(glad/|GL/|GLES[0-9]*/|GLFW/|EGL/|KHR/|osmesa)")
set(imgui_header_regex "^(imgui|backends/imgui)")

set(violations "")
set(violating_files "")
set(file_count 0)
set(checked "")
foreach(dir IN LISTS layers)
  if(NOT IS_DIRECTORY "${SOURCE_DIR}/${dir}")
    if(PARTIAL)
      continue()
    endif()
    message(FATAL_ERROR "check_includes.cmake: ${SOURCE_DIR}/${dir} does not exist (is cmake/layers.cmake stale?)")
  endif()
  list(APPEND checked "${dir}")
  file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${dir}/*.h" "${SOURCE_DIR}/${dir}/*.hpp"
       "${SOURCE_DIR}/${dir}/*.cpp" "${SOURCE_DIR}/${dir}/*.inl" "${SOURCE_DIR}/${dir}/*.inc")
  set(used_by_${dir} "")
  list(SORT files)
  foreach(f IN LISTS files)
    math(EXPR file_count "${file_count} + 1")
    file(STRINGS "${SOURCE_DIR}/${f}" lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS lines)
      if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*([<\"])([^>\"]+)[>\"]")
        continue()
      endif()
      set(header "${CMAKE_MATCH_2}")
      if(CMAKE_MATCH_1 STREQUAL "<")
        set(spelled "<${header}>")
      else()
        set(spelled "\"${header}\"")
      endif()
      set(why "")
      if(header MATCHES "${gl_header_regex}")
        list(APPEND used_by_${dir} gl)
        if(NOT "gl" IN_LIST outside_${dir})
          set(why "a GL, window, context or UI header")
        endif()
      elseif(header MATCHES "${imgui_header_regex}")
        list(APPEND used_by_${dir} imgui)
        if(NOT "imgui" IN_LIST outside_${dir})
          set(why "a GL, window, context or UI header")
        endif()
      elseif(header MATCHES "${project_header_regex}")
        set(layer "")
        foreach(candidate IN LISTS layers)
          string(LENGTH "${candidate}" candidate_length)
          string(LENGTH "${layer}" layer_length)
          string(FIND "${header}" "${candidate}/" at)
          if(at EQUAL 0 AND candidate_length GREATER layer_length)
            set(layer "${candidate}")
          endif()
        endforeach()
        list(APPEND used_by_${dir} "${layer}/")
        if(layer STREQUAL "")
          set(why "a header in no layer of the table")
        elseif(NOT "${layer}/" IN_LIST uses_${dir})
          list(JOIN uses_${dir} " and " allowed_text)
          set(why "a layer above ${dir}/ (it may include only ${allowed_text} of the project)")
        endif()
      endif()
      if(why)
        string(APPEND violations "  ${f}: #include ${spelled}: ${why}\n")
        list(APPEND violating_files "${f}")
      endif()
    endforeach()
  endforeach()
endforeach()
list(REMOVE_DUPLICATES violating_files)

# Each row is exact: what it allows, some file of the layer includes.
set(unused "")
if(NOT PARTIAL)
  foreach(dir IN LISTS layers)
    foreach(allowed IN LISTS uses_${dir} outside_${dir})
      if(NOT allowed STREQUAL "${dir}/" AND NOT allowed STREQUAL "none" AND NOT allowed IN_LIST used_by_${dir})
        string(APPEND unused "  ${dir}/ allows ${allowed}, which none of its files includes\n")
      endif()
    endforeach()
  endforeach()
endif()

# Split the violations into the excepted files and the rest; excepted files that are clean are stale.
set(reported "")
set(excepted "")
string(REPLACE "\n" ";" violation_lines "${violations}")
foreach(v IN LISTS violation_lines)
  if(v STREQUAL "")
    continue()
  endif()
  string(REGEX MATCH "^  ([^:]+):" _ "${v}")
  if(CMAKE_MATCH_1 IN_LIST EXCEPTIONS)
    string(APPEND excepted "${v}\n")
  else()
    string(APPEND reported "${v}\n")
  endif()
endforeach()
set(stale "")
foreach(e IN LISTS EXCEPTIONS)
  if(NOT e IN_LIST violating_files)
    string(APPEND stale "  ${e}\n")
  endif()
endforeach()

list(LENGTH EXCEPTIONS exception_count)
if(excepted)
  message(STATUS "Excepted for now (${exception_count} files still being moved; tests/CMakeLists.txt):\n${excepted}")
endif()
if(reported OR stale OR unused)
  set(text "")
  if(reported)
    string(APPEND text "Each layer may include only what its row of cmake/layers.cmake allows (pipeline/ and app/views/: no GL, windows, contexts or UI). These includes break the layers:\n${reported}")
  endif()
  if(stale)
    string(APPEND text "These files are excepted but include nothing forbidden any more: remove them from the exceptions in tests/CMakeLists.txt:\n${stale}")
  endif()
  if(unused)
    string(APPEND text "Each row of cmake/layers.cmake names exactly what its layer includes; remove these from their rows:\n${unused}")
  endif()
  message(FATAL_ERROR "${text}")
endif()
list(JOIN checked " and " checked_text)
message(STATUS "${file_count} files in ${checked_text} include only what their layers allow")
