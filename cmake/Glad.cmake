# GLAD is generated at configure time by the `glad` command of python3-glad, from the specifications
# it ships (--reproducible: nothing is fetched). The generated loader is not committed.
#   glad_gl:  OpenGL 3.3 core + KHR_debug, multi-context (--mx): each context owns a GladGLContext,
#             so there are no global function pointers.
#   glad_egl: EGL 1.5 with its own loader (dlopen of libEGL), for the surfaceless headless backend.
find_program(GLAD_EXECUTABLE glad REQUIRED)
set(GLAD_OUT "${CMAKE_BINARY_DIR}/glad")
set(GLAD_GL_EXTENSIONS GL_KHR_debug)
set(GLAD_EGL_EXTENSIONS
    EGL_EXT_platform_base EGL_MESA_platform_surfaceless EGL_KHR_surfaceless_context
    EGL_KHR_create_context EGL_KHR_no_config_context)
list(JOIN GLAD_GL_EXTENSIONS "," _gl_ext)
list(JOIN GLAD_EGL_EXTENSIONS "," _egl_ext)
set(_stamp "${GLAD_OUT}/stamp-${_gl_ext}-${_egl_ext}")

if(NOT EXISTS "${_stamp}")
  file(REMOVE_RECURSE "${GLAD_OUT}")
  execute_process(
    COMMAND "${GLAD_EXECUTABLE}" --api gl:core=3.3 --extensions ${_gl_ext}
            --out-path "${GLAD_OUT}/gl" --reproducible --quiet c --mx
    RESULT_VARIABLE _rc_gl ERROR_VARIABLE _err_gl OUTPUT_QUIET)
  execute_process(
    COMMAND "${GLAD_EXECUTABLE}" --api egl=1.5 --extensions ${_egl_ext}
            --out-path "${GLAD_OUT}/egl" --reproducible --quiet c --loader
    RESULT_VARIABLE _rc_egl ERROR_VARIABLE _err_egl OUTPUT_QUIET)
  if(NOT _rc_gl EQUAL 0 OR NOT _rc_egl EQUAL 0)
    message(FATAL_ERROR "glad failed:\n${_err_gl}\n${_err_egl}")
  endif()
  file(TOUCH "${_stamp}")
endif()

add_library(glad_gl STATIC "${GLAD_OUT}/gl/src/gl.c")
target_include_directories(glad_gl SYSTEM PUBLIC "${GLAD_OUT}/gl/include")
set_target_properties(glad_gl PROPERTIES POSITION_INDEPENDENT_CODE ON)

if(EMSCRIPTEN)
  return()  # the browser has WebGL2 only: no EGL
endif()
add_library(glad_egl STATIC "${GLAD_OUT}/egl/src/egl.c")
target_include_directories(glad_egl SYSTEM PUBLIC "${GLAD_OUT}/egl/include")
target_link_libraries(glad_egl PUBLIC ${CMAKE_DL_LIBS})
set_target_properties(glad_egl PROPERTIES POSITION_INDEPENDENT_CODE ON)
