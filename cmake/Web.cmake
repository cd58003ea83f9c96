# The browser build (scripts/web.sh, CMakePresets.json "web"): Debian's emscripten 3.1.6 compiles the
# same sources to WebAssembly. Debian's header-only libraries are used from /usr/include, but only
# through links in build-web/sysinclude/ (the whole /usr/include would put glibc's headers before
# emscripten's libc). Libraries Debian ships compiled are built here from their sources:
#   Dear ImGui 1.86  from Debian's source package (scripts/web.sh fetches it: VPLAB_IMGUI_SOURCE),
#                    configured as Debian configures libimgui-dev (stb from libstb-dev)
#   stb, tinyobjloader  their implementations compiled from Debian's headers (cmake/web/implementations.cpp)
#   GLFW             emscripten's own (-sUSE_GLFW=3: the GLFW 3.2 API over the canvas)
# The targets get the names the desktop's find_package and pkg_check_modules give, so pipeline/ and
# app/ build unchanged.

# vplab reports bad input by exceptions (vplab::Error) everywhere: emscripten catches none unless asked.
# WebAssembly's own exceptions (Chrome 95, Firefox 100, Safari 15.2 and later), not emscripten's
# JavaScript ones: those route every call that may throw through a JavaScript wrapper (invoke_*), a
# round trip out of WebAssembly and back per call (the NPC view of a million triangles: 145 -> 115 ms
# in Chromium's profiler).
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)

set(VPLAB_IMGUI_SOURCE "" CACHE PATH "Dear ImGui 1.86's unpacked source (Debian's source package imgui)")
if(NOT EXISTS "${VPLAB_IMGUI_SOURCE}/imgui.cpp")
  message(FATAL_ERROR "VPLAB_IMGUI_SOURCE (\"${VPLAB_IMGUI_SOURCE}\") holds no imgui.cpp: scripts/web.sh fetches it")
endif()
file(STRINGS "${VPLAB_IMGUI_SOURCE}/imgui.h" _imgui_version REGEX "^#define IMGUI_VERSION ")
if(NOT _imgui_version MATCHES "\"1\\.86\"")
  message(FATAL_ERROR "${VPLAB_IMGUI_SOURCE} is not Dear ImGui 1.86 (${_imgui_version}): the desktop links 1.86")
endif()

set(WEB_SYSINCLUDE "${CMAKE_BINARY_DIR}/sysinclude")
file(MAKE_DIRECTORY "${WEB_SYSINCLUDE}")
foreach(_entry glm nlohmann stb tiny_obj_loader.h)
  if(NOT EXISTS "/usr/include/${_entry}")
    message(FATAL_ERROR "/usr/include/${_entry} is missing: scripts/web.sh installs Debian's headers")
  endif()
  file(CREATE_LINK "/usr/include/${_entry}" "${WEB_SYSINCLUDE}/${_entry}" SYMBOLIC)
endforeach()

add_library(glm::glm INTERFACE IMPORTED)
target_include_directories(glm::glm SYSTEM INTERFACE "${WEB_SYSINCLUDE}")
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE "${WEB_SYSINCLUDE}")

# stb and tinyobjloader: one translation unit holds their implementations.
add_library(web_implementations STATIC "${PROJECT_SOURCE_DIR}/cmake/web/implementations.cpp")
target_include_directories(web_implementations SYSTEM PUBLIC "${WEB_SYSINCLUDE}" "${WEB_SYSINCLUDE}/stb")
target_compile_definitions(web_implementations PUBLIC TINYOBJLOADER_USE_DOUBLE)
add_library(tinyobjloader::tinyobjloader_double ALIAS web_implementations)
add_library(PkgConfig::STB ALIAS web_implementations)

# emscripten's GLFW is part of its JavaScript library (its header is in emscripten's sysroot).
add_library(glfw INTERFACE)
target_link_options(glfw INTERFACE -sUSE_GLFW=3)

# Dear ImGui: the core and the GLFW and OpenGL3 backends, as libimgui-dev builds them.
add_library(imgui_web STATIC
  "${VPLAB_IMGUI_SOURCE}/imgui.cpp" "${VPLAB_IMGUI_SOURCE}/imgui_draw.cpp"
  "${VPLAB_IMGUI_SOURCE}/imgui_tables.cpp" "${VPLAB_IMGUI_SOURCE}/imgui_widgets.cpp"
  "${VPLAB_IMGUI_SOURCE}/misc/cpp/imgui_stdlib.cpp"
  "${VPLAB_IMGUI_SOURCE}/backends/imgui_impl_glfw.cpp" "${VPLAB_IMGUI_SOURCE}/backends/imgui_impl_opengl3.cpp")
target_include_directories(imgui_web SYSTEM PUBLIC "${VPLAB_IMGUI_SOURCE}" "${VPLAB_IMGUI_SOURCE}/misc/cpp")
target_compile_definitions(imgui_web
  PUBLIC IMGUI_DISABLE_STB_RECT_PACK_IMPLEMENTATION "IMGUI_STB_RECT_PACK_FILENAME=<stb/stb_rect_pack.h>"
         IMGUI_DISABLE_STB_TRUETYPE_IMPLEMENTATION "IMGUI_STB_TRUETYPE_FILENAME=<stb/stb_truetype.h>"
  # ImGui 1.86 picks OpenGL ES 2 and "#version 100" under Emscripten unless told: WebGL2 is ES 3.0.
  PRIVATE IMGUI_IMPL_OPENGL_ES3)
target_link_libraries(imgui_web PUBLIC web_implementations glfw)
add_library(PkgConfig::IMGUI ALIAS imgui_web)

