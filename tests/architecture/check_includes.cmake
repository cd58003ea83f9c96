# The layers (docs/architecture.md, tests/architecture/layers.cmake): every directory of the sources
# may include only the project's directories its row of the table names, and GL, window and context
# headers or Dear ImGui only where the row allows them. pipeline/ and app/views/ allow neither: they
# never draw, open a window or a context, or touch the UI. This script fails when a file includes
#   - a GL, GLES, GLFW, GLAD, EGL, KHR, OSMesa or Dear ImGui header (<glad/gl.h>, <GL/osmesa.h>,
#     <GLFW/glfw3.h>, <EGL/egl.h>, <imgui.h>, "imgui_internal.h", …) that its layer may not, or
#   - a header of the project outside its layer's row ("app/render/…" from app/views/, …),
# or when a directory of sources is in no row of the table (a new layer must say what it uses).
# Every *.h, *.hpp, *.cpp and *.inl under the checked directories is read when the test runs (a new
# file is checked without configuring again); only #include lines count, not comments or strings.
#
#   cmake -DSOURCE_DIR=<tree> [-DEXCEPTIONS=<file,file,…>] [-DPARTIAL=ON] -P check_includes.cmake
#   cmake -DPRINT=ON -P check_includes.cmake      prints the table as docs/architecture.md shows it
#
# EXCEPTIONS: files (relative to SOURCE_DIR) that still include such headers and are being moved
# (tests/CMakeLists.txt says which and until when). A listed file that no longer violates is an
# error too, so the list cannot outlive its reason. PARTIAL: a tree with only some of the layers
# (the self-test's fixture).
cmake_minimum_required(VERSION 3.25)

include(${CMAKE_CURRENT_LIST_DIR}/layers.cmake)

if(PRINT)
  # docs/architecture.md's layer table, from the table itself.
  set(table "| layer | may include | GL / ImGui | what it is |\n|---|---|---|---|\n")
  foreach(dir IN LISTS layers)
    if(dir STREQUAL "app")
      set(name "app/*.cpp")
    else()
      set(name "${dir}/")
    endif()
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

# Every directory of sources has a row: app/'s subdirectories, pipeline/ and bench/.
if(NOT PARTIAL)
  file(GLOB app_dirs LIST_DIRECTORIES true RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/app/*")
  foreach(d IN LISTS app_dirs)
    if(IS_DIRECTORY "${SOURCE_DIR}/${d}" AND NOT d IN_LIST layers)
      file(GLOB_RECURSE sources "${SOURCE_DIR}/${d}/*.h" "${SOURCE_DIR}/${d}/*.cpp")
      if(sources)
        message(FATAL_ERROR "check_includes.cmake: ${d}/ holds sources but is no layer of tests/architecture/layers.cmake: say what it may include")
      endif()
    endif()
  endforeach()
endif()

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
    message(FATAL_ERROR "check_includes.cmake: ${SOURCE_DIR}/${dir} does not exist (is tests/architecture/layers.cmake stale?)")
  endif()
  list(APPEND checked "${dir}")
  if(dir STREQUAL "app")  # app/'s own files; its subdirectories are layers of their own
    file(GLOB files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/app/*.h" "${SOURCE_DIR}/app/*.cpp")
  else()
    file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${dir}/*.h" "${SOURCE_DIR}/${dir}/*.hpp"
         "${SOURCE_DIR}/${dir}/*.cpp" "${SOURCE_DIR}/${dir}/*.inl")
  endif()
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
      if(header MATCHES "${gl_header_regex}" AND NOT "gl" IN_LIST outside_${dir})
        set(why "a GL, window, context or UI header")
      elseif(header MATCHES "${imgui_header_regex}" AND NOT "imgui" IN_LIST outside_${dir})
        set(why "a GL, window, context or UI header")
      elseif(header MATCHES "^(app|pipeline|bench)/")
        set(ok FALSE)
        foreach(prefix IN LISTS uses_${dir})
          string(FIND "${header}" "${prefix}" at)
          if(at EQUAL 0)
            set(ok TRUE)
          endif()
        endforeach()
        if(NOT ok)
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
if(reported OR stale)
  set(text "")
  if(reported)
    string(APPEND text "Each layer may include only what its row of tests/architecture/layers.cmake allows (pipeline/ and app/views/: no GL, windows, contexts or UI). These includes break the layers:\n${reported}")
  endif()
  if(stale)
    string(APPEND text "These files are excepted but include nothing forbidden any more: remove them from the exceptions in tests/CMakeLists.txt:\n${stale}")
  endif()
  message(FATAL_ERROR "${text}")
endif()
list(JOIN checked " and " checked_text)
message(STATUS "${file_count} files in ${checked_text} include only what their layers allow")
