# The layers (README "Architecture", issue 12): pipeline/ is pure math and app/views/ builds display
# lists from it; neither may draw, open a window or a context, or touch the UI. This script fails
# when a file there includes
#   - a GL, GLES, GLFW, GLAD, EGL, KHR, OSMesa or Dear ImGui header, in <> or "" (<glad/gl.h>,
#     <GL/osmesa.h>, <GLFW/glfw3.h>, <EGL/egl.h>, <imgui.h>, "imgui_internal.h", …), or
#   - a header of a layer above it: pipeline/ may include only "pipeline/…" of the project, app/views/
#     only "pipeline/…" and "app/views/…" (so not "app/gl/…", "app/render/…", "app/context/…",
#     "app/ui/…", "app/fonts/…", "app/export/…", "app/headless.h", …).
# Every *.h, *.hpp, *.cpp and *.inl under the checked directories is read when the test runs (a new
# file is checked without configuring again); only #include lines count, not comments or strings.
#
#   cmake -DSOURCE_DIR=<tree> [-DEXCEPTIONS=<file,file,…>] -P check_includes.cmake
#
# EXCEPTIONS: files (relative to SOURCE_DIR) that still include such headers and are being moved
# (tests/CMakeLists.txt says which and until when). A listed file that no longer violates is an
# error too, so the list cannot outlive its reason.
cmake_minimum_required(VERSION 3.25)

# Commas, not semicolons: a list passes through add_test and execute_process unsplit.
string(REPLACE "," ";" EXCEPTIONS "${EXCEPTIONS}")
if(NOT SOURCE_DIR OR NOT IS_DIRECTORY "${SOURCE_DIR}")
  message(FATAL_ERROR "check_includes.cmake: SOURCE_DIR \"${SOURCE_DIR}\" is not a directory")
endif()

# Checked directory → the project directories its files may include from.
set(checked pipeline app/views)
set(allowed_pipeline "pipeline/")
set(allowed_app/views "pipeline/" "app/views/")

# Headers of GL and its loaders, windows, contexts and the UI, wherever they come from.
set(gl_header_regex "^(glad/|GL/|GLES[0-9]*/|GLFW/|EGL/|KHR/|imgui|osmesa)")

set(violations "")
set(violating_files "")
set(file_count 0)
foreach(dir IN LISTS checked)
  if(NOT IS_DIRECTORY "${SOURCE_DIR}/${dir}")
    message(FATAL_ERROR "check_includes.cmake: ${SOURCE_DIR}/${dir} does not exist (is the list of checked directories stale?)")
  endif()
  file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${dir}/*.h" "${SOURCE_DIR}/${dir}/*.hpp"
       "${SOURCE_DIR}/${dir}/*.cpp" "${SOURCE_DIR}/${dir}/*.inl")
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
        set(why "a GL, window, context or UI header")
      elseif(header MATCHES "^app/")
        set(ok FALSE)
        foreach(prefix IN LISTS allowed_${dir})
          string(FIND "${header}" "${prefix}" at)
          if(at EQUAL 0)
            set(ok TRUE)
          endif()
        endforeach()
        if(NOT ok)
          list(JOIN allowed_${dir} " and " allowed_text)
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
    string(APPEND text "pipeline/ and app/views/ must build without GL, windows, contexts or the UI. These includes break the layers:\n${reported}")
  endif()
  if(stale)
    string(APPEND text "These files are excepted but include nothing forbidden any more: remove them from the exceptions in tests/CMakeLists.txt:\n${stale}")
  endif()
  message(FATAL_ERROR "${text}")
endif()
list(JOIN checked " and " checked_text)
message(STATUS "${file_count} files in ${checked_text} include no GL, window, context or UI header and nothing of a layer above")
