# The version `vplab --version` reports: the project's (CMakeLists.txt) and the git commit the build
# is made from, read at configure time. CMake configures again when the checkout's HEAD moves (a
# commit, a checkout), so the commit named is the one built. Outside a git checkout it is "unknown".
find_package(Git QUIET)
set(VPLAB_COMMIT "unknown")
set(VPLAB_COMMIT_EPOCH 0)  # the commit's time: SOURCE_DATE_EPOCH of the manual page and the Debian changelog
if(GIT_FOUND AND EXISTS "${PROJECT_SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse --short=12 HEAD
                  WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}" RESULT_VARIABLE status
                  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(status EQUAL 0 AND commit MATCHES "^[0-9a-f]+$")
    set(VPLAB_COMMIT "${commit}")
  endif()
  execute_process(COMMAND "${GIT_EXECUTABLE}" log -1 --format=%ct HEAD WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
                  OUTPUT_VARIABLE epoch OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(epoch MATCHES "^[0-9]+$")
    set(VPLAB_COMMIT_EPOCH "${epoch}")
  endif()
  execute_process(COMMAND "${GIT_EXECUTABLE}" symbolic-ref -q HEAD WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
                  OUTPUT_VARIABLE branch OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  foreach(file "HEAD" "${branch}" "packed-refs")
    if(file AND EXISTS "${PROJECT_SOURCE_DIR}/.git/${file}")
      set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/.git/${file}")
    endif()
  endforeach()
endif()
configure_file("${PROJECT_SOURCE_DIR}/cmake/version.h.in" "${PROJECT_BINARY_DIR}/generated/vplab_version.h" @ONLY)
