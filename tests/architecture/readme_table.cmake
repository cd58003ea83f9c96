# The layer table of docs/architecture.md (the README's "Architecture" until issue 39) is the table of
# layers.cmake as check_includes.cmake prints it: a layer added, or a use allowed, shows there or this
# test fails.
#
#   cmake -DCHECK=<check_includes.cmake> -DREADME=<docs/architecture.md> -P readme_table.cmake
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND ${CMAKE_COMMAND} -DPRINT=ON -P ${CHECK} OUTPUT_VARIABLE table RESULT_VARIABLE result)
if(NOT result EQUAL 0 OR table STREQUAL "")
  message(FATAL_ERROR "check_includes.cmake -DPRINT=ON printed no table")
endif()
file(READ "${README}" readme)
string(FIND "${readme}" "${table}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${README}: its layer table is not cmake/layers.cmake's. Put this in its place "
                      "(cmake -DPRINT=ON -P cmake/check_includes.cmake):\n${table}")
endif()
message(STATUS "${README} shows the layers of cmake/layers.cmake")
